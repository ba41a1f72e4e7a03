#include <cdea/material/gent_dielectric.h>

#include <cmath>

namespace cdea
{
  GentDielectric::GentDielectric(const MaterialConstants &constants,
                                 const double             voltage)
    : c(constants)
    , phi(voltage)
    , mu(constants.shear_modulus)
    , jlim(constants.jlim)
    , eps_phi2_h2(constants.permittivity * voltage * voltage /
                  (constants.thickness * constants.thickness))
  {}

  double GentDielectric::electric_field(const double l1, const double l2) const
  {
    return phi * l1 * l2 / c.thickness;
  }

  // With g = 1 - (I - 3)/Jlim and I_i = dI/dl_i:
  //   dW_gent/dl_i = (mu / 2) I_i / g.
  // I_1 = 2 l1 - 2 l1^-3 l2^-2, and the electrostatic part gives
  //   -eps Phi^2/H^2 l1 l2^2.
  NominalStress GentDielectric::stress(const double l1, const double l2) const
  {
    const double g   = gent_margin(l1, l2);
    const double q   = 1. / (l1 * l1 * l2 * l2); // l3^2
    const double I_1 = 2. * (l1 - q / l1);
    const double I_2 = 2. * (l2 - q / l2);
    return {0.5 * mu * I_1 / g - eps_phi2_h2 * l1 * l2 * l2,
            0.5 * mu * I_2 / g - eps_phi2_h2 * l1 * l1 * l2};
  }

  // d2W_gent/dl_i dl_j = (mu / 2) (I_ij / g + I_i I_j / (Jlim g^2)), with
  // I_11 = 2 + 6 q / l1^2, I_22 = 2 + 6 q / l2^2, I_12 = 4 q / (l1 l2), q = l1^-2 l2^-2.
  StressTangent GentDielectric::tangent(const double l1, const double l2) const
  {
    const double g    = gent_margin(l1, l2);
    const double q    = 1. / (l1 * l1 * l2 * l2);
    const double I_1  = 2. * (l1 - q / l1);
    const double I_2  = 2. * (l2 - q / l2);
    const double I_11 = 2. + 6. * q / (l1 * l1);
    const double I_22 = 2. + 6. * q / (l2 * l2);
    const double I_12 = 4. * q / (l1 * l2);
    const double k    = 0.5 * mu / g;
    const double kk   = 0.5 * mu / (jlim * g * g);
    return {k * I_11 + kk * I_1 * I_1 - eps_phi2_h2 * l2 * l2,
            k * I_12 + kk * I_1 * I_2 - 2. * eps_phi2_h2 * l1 * l2,
            k * I_22 + kk * I_2 * I_2 - eps_phi2_h2 * l1 * l1};
  }

  void GentDielectric::stress_and_tangent(const double l1, const double l2, NominalStress &s,
                                          StressTangent &t) const
  {
    const double g    = gent_margin(l1, l2);
    const double q    = 1. / (l1 * l1 * l2 * l2);
    const double I_1  = 2. * (l1 - q / l1);
    const double I_2  = 2. * (l2 - q / l2);
    const double I_11 = 2. + 6. * q / (l1 * l1);
    const double I_22 = 2. + 6. * q / (l2 * l2);
    const double I_12 = 4. * q / (l1 * l2);
    const double k    = 0.5 * mu / g;
    const double kk   = 0.5 * mu / (jlim * g * g);
    s = {0.5 * mu * I_1 / g - eps_phi2_h2 * l1 * l2 * l2,
         0.5 * mu * I_2 / g - eps_phi2_h2 * l1 * l1 * l2};
    t = {k * I_11 + kk * I_1 * I_1 - eps_phi2_h2 * l2 * l2,
         k * I_12 + kk * I_1 * I_2 - 2. * eps_phi2_h2 * l1 * l2,
         k * I_22 + kk * I_2 * I_2 - eps_phi2_h2 * l1 * l1};
  }
} // namespace cdea
