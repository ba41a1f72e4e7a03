#pragma once
// The ideal-dielectric Gent law (GentDielectric) as a MembraneLaw: the
// elastic law of the paper, evaluated at every quadrature point; registered
// as Material/Model = elastic (law_factory.h), the default.

#include <cdea/material/gent_dielectric.h>
#include <cdea/material/membrane_law.h>

#include <memory>

namespace cdea
{
  struct LawSettings;

  /// The ideal-dielectric Gent law of GentDielectric as a MembraneLaw.
  class GentDielectricLaw final : public MembraneLaw
  {
  public:
    explicit GentDielectricLaw(const MaterialConstants &constants);

    /// The Gent law of the film (Shear modulus, Jlim, Permittivity); no
    /// entries of its own.
    static std::shared_ptr<const MembraneLaw> create(const LawSettings &settings);

    bool   evaluate(const LawInput &input, const InternalStep &step, unsigned int request,
                    LawResponse &response) const override;
    bool   parameter_derivative(const LawInput &input, const InternalStep &step,
                                LawParameter parameter, double &d_energy,
                                NominalStress &d_stress) const override;
    double max_hoop_stretch(double l1) const override;

    bool   serves_every_model() const override { return true; }
    double range_margin(double l1, double l2) const override;
    std::pair<double, double> meridian_stretch_range(double l2) const override
    {
      return meridian_stretch_range(c.jlim, l2);
    }
    LawLimit limit() const override { return {"the Gent limit", "g"}; }

    /// The open interval of l1 inside the Gent limit I1 - 3 < @p jlim at
    /// hoop stretch @p l2 (first <= 0 if there is none).
    static std::pair<double, double> meridian_stretch_range(double jlim, double l2);

    const MaterialConstants &constants() const { return c; }

  private:
    MaterialConstants c;
  };
} // namespace cdea
