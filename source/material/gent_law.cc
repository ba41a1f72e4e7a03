#include <cdea/material/gent_law.h>
#include <cdea/material/law_factory.h>

#include <cmath>

namespace cdea
{
  GentDielectricLaw::GentDielectricLaw(const MaterialConstants &constants)
    : c(constants)
  {}

  bool GentDielectricLaw::evaluate(const LawInput &in, const InternalStep &, const unsigned int request,
                                   LawResponse &out) const
  {
    if (!(in.l1 > 0.) || !(in.l2 > 0.))
      return false;
    const GentDielectric             law(c, in.voltage);
    const GentDielectric::Invariants v = law.invariants(in.l1, in.l2);
    if (!(v.g > 0.))
      return false;
    if (request & law_energy)
      out.energy = law.energy(in.l1, in.l2);
    if (request & law_tangent)
      law.stress_and_tangent(in.l1, in.l2, v, out.stress, out.tangent);
    else if (request & law_stress)
      out.stress = law.stress(in.l1, in.l2, v);
    out.tension       = TensionState::taut;
    out.natural_width = in.l2;
    return true;
  }

  // With x = I - 3, g = 1 - x / Jlim, I_i = dI/dl_i and e = Phi^2 / H^2:
  //   dW/dmu   = -(Jlim / 2) log g,                 ds_i/dmu   = I_i / (2 g);
  //   dW/dJlim = -(mu / 2) (log g + x / (Jlim g)),  ds_i/dJlim = -(mu / 2) I_i x / (Jlim g)^2;
  //   dW/deps  = -(e / 2) (l1 l2)^2,                ds_i/deps  = -e l1 l2 (l1 l2) / l_i;
  //   dW/dPhi  = -eps Phi (l1 l2 / H)^2,            ds_i/dPhi  = 2 (ds_i/deps) eps / Phi.
  bool GentDielectricLaw::parameter_derivative(const LawInput &in, const InternalStep &,
                                               const LawParameter parameter, double &d_energy,
                                               NominalStress &d_stress) const
  {
    const double l1 = in.l1, l2 = in.l2;
    const double q  = 1. / (l1 * l1 * l2 * l2);
    const double x  = l1 * l1 + l2 * l2 + q - 3.;
    const double g  = 1. - x / c.jlim;
    if (!(g > 0.))
      return false;
    const double I_1 = 2. * (l1 - q / l1), I_2 = 2. * (l2 - q / l2);
    const double e   = in.voltage * in.voltage / (c.thickness * c.thickness);
    const double J   = l1 * l2;
    switch (parameter)
      {
        case LawParameter::shear_modulus:
          d_energy = -0.5 * c.jlim * std::log(g);
          d_stress = {0.5 * I_1 / g, 0.5 * I_2 / g};
          return true;
        case LawParameter::jlim:
          {
            const double k = -0.5 * c.shear_modulus * x / (c.jlim * c.jlim * g * g);
            d_energy       = -0.5 * c.shear_modulus * (std::log(g) + x / (c.jlim * g));
            d_stress       = {k * I_1, k * I_2};
            return true;
          }
        case LawParameter::permittivity:
          d_energy = -0.5 * e * J * J;
          d_stress = {-e * J * l2, -e * J * l1};
          return true;
        case LawParameter::voltage:
          {
            const double k = -2. * c.permittivity * in.voltage / (c.thickness * c.thickness);
            d_energy       = 0.5 * k * J * J;
            d_stress       = {k * J * l2, k * J * l1};
            return true;
          }
      }
    return false;
  }

  // l1^2 + w^2 + l1^-2 w^-2 - 3 < Jlim, solved for the larger root in w^2.
  double GentDielectricLaw::max_hoop_stretch(const double l1) const
  {
    const double b = c.jlim + 3. - l1 * l1; // w^2 + q / w^2 = b, q = l1^-2
    const double q = 1. / (l1 * l1);
    const double d = b * b - 4. * q;
    return d > 0. ? std::sqrt(0.5 * (b + std::sqrt(d))) : 0.;
  }

  double GentDielectricLaw::range_margin(const double l1, const double l2) const
  {
    return GentDielectric(c, 0.).gent_margin(l1, l2);
  }

  // At fixed l2, g > 0 means I < 3 + Jlim, i.e. with u = l1^2
  //   u^2 - p u + 1/l2^2 < 0,  p = 3 + Jlim - l2^2,
  // so u lies between the roots u- u+ = 1/l2^2, u- + u+ = p.
  std::pair<double, double> GentDielectricLaw::meridian_stretch_range(const double jlim,
                                                                      const double l2)
  {
    const double q    = 1. / (l2 * l2);
    const double p    = 3. + jlim - l2 * l2;
    const double disc = p * p - 4. * q;
    if (!(p > 0.) || !(disc > 0.))
      return {0., 0.};
    const double u_plus  = 0.5 * (p + std::sqrt(disc));
    const double u_minus = q / u_plus;
    return {std::sqrt(u_minus), std::sqrt(u_plus)};
  }

  std::shared_ptr<const MembraneLaw> GentDielectricLaw::create(const LawSettings &settings)
  {
    return std::make_shared<GentDielectricLaw>(settings.material);
  }

  CDEA_REGISTER_PLUGIN(MembraneLaws, GentDielectricLaw, "elastic", 0,
                       "the Gent law of Shear modulus and Jlim.")
} // namespace cdea
