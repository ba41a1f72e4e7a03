#pragma once
// Tension-field (relaxed) membrane law wrapped around any elastic MembraneLaw.
//
// Radial wrinkles let the film take a material hoop stretch larger than the
// kinematic one l2 = r/R: the wrinkles absorb the excess circumference. The
// relaxed energy is therefore (Pipkin 1986; Steigmann 1990; with voltage,
// Greaney, Meere and Zurlo 2019)
//
//   W_rel(l1, l2) = min over w >= l2 of W(l1, w).
//
// Where s2(l1, l2) >= 0 the minimum is at w = l2 (taut: the law itself). Where
// s2 < 0 it is at the natural width w* > l2, the first hoop stretch above l2
// with s2(l1, w*) = 0 (wrinkled). There
//
//   s1_rel = s1(l1, w*),   s2_rel = 0,
//   ds1_rel/dl1 = s11 - s12^2 / s22   (at w*, using dw*/dl1 = -s12/s22),
//
// and the other second derivatives vanish. Two ways the relaxed law can fail,
// both reported rather than crossed: the natural width has no root below the
// base law's hoop limit (TensionState::failed, evaluate() returns false), and
// ds1_rel/dl1 <= 0 (loss of monotonicity in l1, i.e. of strong ellipticity:
// the onset of pull-in), flagged in LawResponse::loses_ellipticity.

#include <cdea/material/membrane_law.h>

#include <memory>

namespace cdea
{
  class TensionField final : public MembraneLaw
  {
  public:
    /// @p base must be elastic (no internal variables).
    explicit TensionField(std::shared_ptr<const MembraneLaw> base);

    const MembraneLaw &base() const { return *law; }

    /// The relaxed response; false where the natural width does not exist
    /// (response.tension is then TensionState::failed) or the base law fails.
    bool evaluate(const LawInput &input, const InternalStep &step, unsigned int request,
                  LawResponse &response) const override;

    /// Wrinkled points: d s1_rel/dp = ds1/dp + s12 dw*/dp, dw*/dp = -(ds2/dp) / s22.
    bool parameter_derivative(const LawInput &input, const InternalStep &step,
                              LawParameter parameter, double &d_energy,
                              NominalStress &d_stress) const override;

    double max_hoop_stretch(double l1) const override { return law->max_hoop_stretch(l1); }

    // The base law's range and constants.
    double range_margin(double l1, double l2) const override { return law->range_margin(l1, l2); }
    std::pair<double, double> meridian_stretch_range(double l2) const override
    {
      return law->meridian_stretch_range(l2);
    }
    LawLimit                 limit() const override { return law->limit(); }
    std::vector<LawConstant> own_constants() const override { return law->own_constants(); }
    bool depends_on(LawParameter p) const override { return law->depends_on(p); }

    /// The relaxed response at (l1, l2) with every quantity (energy, stress,
    /// tangent, state, natural width), whatever the outcome.
    LawResponse relax(const LawInput &input) const;

  private:
    std::shared_ptr<const MembraneLaw> law;
  };
} // namespace cdea
