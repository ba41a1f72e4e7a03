// The Gent-Gent ideal dielectric (Pucci and Saccomandi 2002;
// doc/materials.md): Gent's limiting chain extensibility in I1 and a
// logarithmic I2 term,
//
//   W_e = -(mu Jlim / 2) log(1 - (I1 - 3) / Jlim) + C2 log(I2 / 3),
//
// mu = Material/Shear modulus, Jlim = Material/Jlim, C2 = Material/Gent-Gent
// C2 (kPa) >= 0; small-strain shear modulus mu + 2 C2 / 3; C2 = 0 is the Gent
// law. Registered as Material/Model = gent-gent.

#include <cdea/base/units.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/material/elastic_dielectric.h>
#include <cdea/material/gent_law.h>
#include <cdea/material/law_factory.h>

#include <cmath>

namespace cdea
{
  class GentGentLaw final : public ElasticDielectricLaw
  {
  public:
    /// @p c2 in Pa.
    GentGentLaw(const MaterialConstants &film, const double c2)
      : ElasticDielectricLaw(film)
      , gent(film)
      , c2(c2)
    {}

    static void declare_parameters(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Material");
      prm.add_number("Gent-Gent C2 (kPa)", "0",
                     "Coefficient C2 of log(I2 / 3) in the Gent-Gent law (its I1 part is the "
                     "Gent law of Shear modulus and Jlim); at least 0.");
      prm.leave_subsection();
    }

    static std::shared_ptr<const MembraneLaw> create(const LawSettings &settings)
    {
      const double c2 = settings.constant("Gent-Gent C2 (kPa)");
      if (!(c2 >= 0. && c2 <= 1e9))
        throw InputError("Material/Gent-Gent C2 (kPa) must be between 0 and 1e9, got " +
                         format_number(c2));
      return std::make_shared<GentGentLaw>(settings.material, units::kPa.in_si(c2));
    }

    // The range is the Gent law's: the I2 term is finite at every stretch.
    double max_hoop_stretch(const double l1) const override { return gent.max_hoop_stretch(l1); }
    double range_margin(const double l1, const double l2) const override
    {
      return gent.range_margin(l1, l2);
    }
    std::pair<double, double> meridian_stretch_range(const double l2) const override
    {
      return gent.meridian_stretch_range(l2);
    }
    LawLimit limit() const override { return gent.limit(); }

    std::vector<LawConstant> own_constants() const override
    {
      return {{"Gent-Gent C2 (kPa)", 0., 1e9}};
    }

  private:
    GentDielectricLaw gent; ///< the I1 part's range
    double            c2;   ///< Pa

    // With g = 1 - (I1 - 3) / Jlim:
    //   W1 = mu / (2 g), W11 = mu / (2 Jlim g^2), W2 = C2 / I2, W22 = -C2 / I2^2.
    bool strain_energy(const double l1, const double l2, const unsigned int request,
                       StrainEnergy &e) const override
    {
      const double mu = film().shear_modulus, jlim = film().jlim;
      const auto [I1, I2] = membrane_invariants(l1, l2);
      const double g      = 1. - (I1 - 3.) / jlim;
      if (!(g > 0.))
        return false;
      InvariantDerivatives d;
      d.W   = -0.5 * mu * jlim * std::log(g) + c2 * std::log(I2 / 3.);
      d.W1  = 0.5 * mu / g;
      d.W2  = c2 / I2;
      d.W11 = 0.5 * mu / (jlim * g * g);
      d.W22 = -c2 / (I2 * I2);
      e     = strain_energy_of_invariants(l1, l2, d, request);
      return true;
    }

    // With x = I1 - 3: dW_e/dmu = -(Jlim / 2) log g, dW1/dmu = 1 / (2 g);
    // dW_e/dJlim = -(mu / 2) (log g + x / (Jlim g)), dW1/dJlim = -mu x / (2 Jlim^2 g^2);
    // dW_e/dC2 = log(I2 / 3), dW2/dC2 = 1 / I2 (per Pa; times 1e3 per kPa).
    bool strain_energy_derivative(const double l1, const double l2, const LawParameter p,
                                  double &dW, NominalStress &ds) const override
    {
      const double mu = film().shear_modulus, jlim = film().jlim;
      const auto [I1, I2] = membrane_invariants(l1, l2);
      const double x = I1 - 3., g = 1. - x / jlim;
      if (!(g > 0.))
        return false;
      InvariantDerivatives d;
      if (p == LawParameter::shear_modulus)
        d = {-0.5 * jlim * std::log(g), 0.5 / g, 0.};
      else if (p == LawParameter::jlim)
        d = {-0.5 * mu * (std::log(g) + x / (jlim * g)), -0.5 * mu * x / (jlim * jlim * g * g),
             0.};
      else if (own_constant_index(p) == 0)
        d = {1e3 * std::log(I2 / 3.), 0., 1e3 / I2};
      else
        return false;
      return invariant_parameter_derivative(l1, l2, d, dW, ds);
    }
  };

  CDEA_REGISTER_PLUGIN(MembraneLaws, GentGentLaw, "gent-gent", 0,
                       "the Gent-Gent law: the Gent law of Shear modulus and Jlim plus "
                       "Gent-Gent C2 log(I2 / 3) (Pucci and Saccomandi 2002).")
} // namespace cdea
