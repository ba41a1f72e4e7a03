#pragma once
// Ideal-dielectric Gent membrane under voltage control.
//
// Free energy per reference volume, as a function of the meridian stretch l1,
// the hoop stretch l2 and the voltage Phi across the film (thickness H):
//
//   W(l1, l2) = -(mu Jlim / 2) log(1 - (I - 3) / Jlim)  -  (eps / 2) (Phi l1 l2 / H)^2,
//   I = l1^2 + l2^2 + l1^-2 l2^-2   (incompressible, l3 = 1 / (l1 l2)).
//
// The nominal stresses are s_i = dW/dl_i and the true stresses sigma_i = l_i s_i
// (Guo et al. 2025, eqs. 10-12). The object holds the material constants and one
// voltage; it knows nothing about meshes, so the FE code and the shooting model
// share it. energy() is a template so that automatic differentiation (Sacado)
// can check the hand-derived gradient and Hessian.

#include <cmath>

namespace cdea
{
  /// Material constants in SI units.
  struct MaterialConstants
  {
    double shear_modulus;  ///< mu (Pa)
    double jlim;           ///< Gent limit Jlim (-)
    double permittivity;   ///< eps (F/m)
    double thickness;      ///< undeformed film thickness H (m)
  };

  /// First derivatives of W: nominal stresses (Pa).
  struct NominalStress
  {
    double s1;
    double s2;
  };

  /// Second derivatives of W (Pa).
  struct StressTangent
  {
    double s11;
    double s12;
    double s22;
  };

  class GentDielectric
  {
  public:
    /// @p voltage in volts. (Inline: the laws build one per quadrature point.)
    GentDielectric(const MaterialConstants &constants, const double voltage)
      : c(constants)
      , phi(voltage)
      , mu(constants.shear_modulus)
      , jlim(constants.jlim)
      , eps_phi2_h2(constants.permittivity * voltage * voltage /
                    (constants.thickness * constants.thickness))
    {}

    /// The invariants one point's range check, stress and tangent share:
    /// q = l3^2 = l1^-2 l2^-2 and the margin g = 1 - (I - 3) / Jlim.
    struct Invariants
    {
      double q;
      double g;
    };

    /// W(l1, l2) per reference volume (J/m^3).
    template <typename Number>
    Number energy(const Number &l1, const Number &l2) const
    {
      using std::log;
      const Number I = l1 * l1 + l2 * l2 + 1. / (l1 * l1 * l2 * l2);
      return -0.5 * mu * jlim * log(1. - (I - 3.) / jlim) -
             0.5 * eps_phi2_h2 * l1 * l1 * l2 * l2;
    }

    NominalStress stress(double l1, double l2) const;
    StressTangent tangent(double l1, double l2) const;
    /// stress() and tangent() in one pass (the same expressions, so the
    /// same numbers), for the time laws that need both at every call.
    void stress_and_tangent(double l1, double l2, NominalStress &s, StressTangent &t) const;

    /// q and g of (l1, l2), I = l1^2 + l2^2 + q. (Inline: called at every
    /// quadrature point.)
    Invariants invariants(const double l1, const double l2) const
    {
      const double q = 1. / (l1 * l1 * l2 * l2);
      const double I = l1 * l1 + l2 * l2 + q;
      return {q, 1. - (I - 3.) / jlim};
    }

    /// g = 1 - (I - 3) / Jlim; the law is defined only while g > 0.
    double gent_margin(const double l1, const double l2) const { return invariants(l1, l2).g; }

    /// stress() and stress_and_tangent() from the invariants @p v of the same
    /// (l1, l2), already computed for the range check (the same numbers).
    NominalStress stress(double l1, double l2, const Invariants &v) const;
    void stress_and_tangent(double l1, double l2, const Invariants &v, NominalStress &s,
                            StressTangent &t) const;

    /// True electric field E = Phi l1 l2 / H (V/m).
    double electric_field(double l1, double l2) const;

    double voltage() const { return phi; }
    const MaterialConstants &constants() const { return c; }

  private:
    MaterialConstants c;
    double phi;
    double mu;
    double jlim;
    double eps_phi2_h2; ///< eps Phi^2 / H^2
  };
} // namespace cdea
