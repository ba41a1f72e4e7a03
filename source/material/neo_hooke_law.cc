// The neo-Hookean ideal dielectric (Treloar 1943; doc/materials.md):
//
//   W_e = (mu / 2) (I1 - 3),   mu = Material/Shear modulus,
//
// the Gaussian network without a limiting stretch: the Gent law as Jlim ->
// infinity. Registered as Material/Model = neo-hooke; no entries of its own.

#include <cdea/material/elastic_dielectric.h>
#include <cdea/material/law_factory.h>

#include <limits>

namespace cdea
{
  class NeoHookeLaw final : public ElasticDielectricLaw
  {
  public:
    using ElasticDielectricLaw::ElasticDielectricLaw;

    static std::shared_ptr<const MembraneLaw> create(const LawSettings &settings)
    {
      return std::make_shared<NeoHookeLaw>(settings.material);
    }

    double max_hoop_stretch(double) const override
    {
      return std::numeric_limits<double>::infinity();
    }

    bool depends_on(const LawParameter p) const override { return p != LawParameter::jlim; }

  private:
    bool strain_energy(const double l1, const double l2, const unsigned int request,
                       StrainEnergy &e) const override
    {
      const double mu = film().shear_modulus;
      const double I1 = membrane_invariants(l1, l2).first;
      e = strain_energy_of_invariants(l1, l2, {0.5 * mu * (I1 - 3.), 0.5 * mu}, request);
      return true;
    }

    // dW_e/dmu = (I1 - 3) / 2, the stresses over mu.
    bool strain_energy_derivative(const double l1, const double l2, const LawParameter p,
                                  double &dW, NominalStress &ds) const override
    {
      if (p != LawParameter::shear_modulus)
        return false;
      const double I1 = membrane_invariants(l1, l2).first;
      return invariant_parameter_derivative(l1, l2, {0.5 * (I1 - 3.), 0.5}, dW, ds);
    }
  };

  CDEA_REGISTER_PLUGIN(MembraneLaws, NeoHookeLaw, "neo-hooke", 0,
                       "the neo-Hookean law (mu / 2) (I1 - 3) of Shear modulus (Treloar), "
                       "the Gent law without its limit.")
} // namespace cdea
