// The Mooney-Rivlin ideal dielectric (Mooney 1940; Rivlin 1948;
// doc/materials.md):
//
//   W_e = C1 (I1 - 3) + C2 (I2 - 3),   C1 = mu / 2,
//
// mu = Material/Shear modulus and C2 = Material/Mooney-Rivlin C2 (kPa) >= 0;
// its small-strain shear modulus is mu + 2 C2, and C2 = 0 is the neo-Hookean
// law. Registered as Material/Model = mooney-rivlin.

#include <cdea/base/units.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/material/elastic_dielectric.h>
#include <cdea/material/law_factory.h>

#include <cmath>
#include <limits>

namespace cdea
{
  class MooneyRivlinLaw final : public ElasticDielectricLaw
  {
  public:
    /// @p c2 in Pa.
    MooneyRivlinLaw(const MaterialConstants &film, const double c2)
      : ElasticDielectricLaw(film)
      , c2(c2)
    {}

    static void declare_parameters(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Material");
      prm.add_number("Mooney-Rivlin C2 (kPa)", "0",
                     "Coefficient C2 of I2 - 3 in the Mooney-Rivlin law (C1 = Shear "
                     "modulus / 2); at least 0.");
      prm.leave_subsection();
    }

    static std::shared_ptr<const MembraneLaw> create(const LawSettings &settings)
    {
      const double c2 = settings.constant("Mooney-Rivlin C2 (kPa)");
      if (!(c2 >= 0. && c2 <= 1e9))
        throw InputError("Material/Mooney-Rivlin C2 (kPa) must be between 0 and 1e9, got " +
                         format_number(c2));
      return std::make_shared<MooneyRivlinLaw>(settings.material, units::kPa.in_si(c2));
    }

    double max_hoop_stretch(double) const override
    {
      return std::numeric_limits<double>::infinity();
    }

    bool depends_on(const LawParameter p) const override { return p != LawParameter::jlim; }

    std::vector<LawConstant> own_constants() const override
    {
      return {{"Mooney-Rivlin C2 (kPa)", 0., 1e9}};
    }

  private:
    double c2; ///< Pa

    bool strain_energy(const double l1, const double l2, const unsigned int request,
                       StrainEnergy &e) const override
    {
      const double mu       = film().shear_modulus;
      const auto [I1, I2]   = membrane_invariants(l1, l2);
      const double energy   = 0.5 * mu * (I1 - 3.) + c2 * (I2 - 3.);
      e = strain_energy_of_invariants(l1, l2, {energy, 0.5 * mu, c2}, request);
      return true;
    }

    // dW_e/dmu = (I1 - 3) / 2; dW_e/dC2 = (I2 - 3) per Pa, times 1e3 per kPa.
    bool strain_energy_derivative(const double l1, const double l2, const LawParameter p,
                                  double &dW, NominalStress &ds) const override
    {
      const auto [I1, I2] = membrane_invariants(l1, l2);
      InvariantDerivatives d;
      if (p == LawParameter::shear_modulus)
        d = {0.5 * (I1 - 3.), 0.5, 0.};
      else if (own_constant_index(p) == 0)
        d = {1e3 * (I2 - 3.), 0., 1e3};
      else
        return false;
      return invariant_parameter_derivative(l1, l2, d, dW, ds);
    }
  };

  CDEA_REGISTER_PLUGIN(MembraneLaws, MooneyRivlinLaw, "mooney-rivlin", 0,
                       "the Mooney-Rivlin law (mu / 2) (I1 - 3) + C2 (I2 - 3) of Shear "
                       "modulus and Mooney-Rivlin C2 (Mooney 1940, Rivlin 1948).")
} // namespace cdea
