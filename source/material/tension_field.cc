#include <cdea/material/tension_field.h>
#include <cdea/numerics/bracketed_root.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cdea
{
  namespace
  {
    constexpr unsigned int everything = law_energy | law_stress | law_tangent;
    const InternalStep     no_step{};
  } // namespace

  TensionField::TensionField(std::shared_ptr<const MembraneLaw> base)
    : law(std::move(base))
  {
    if (!law || law->n_internal_variables() != 0)
      throw std::invalid_argument(
        "TensionField: the relaxation wraps an elastic law (no internal variables)");
  }

  LawResponse TensionField::relax(const LawInput &in) const
  {
    LawResponse r;
    if (!law->evaluate(in, no_step, everything, r))
      {
        r.tension = TensionState::failed;
        return r;
      }
    if (r.stress.s2 >= 0.)
      return r;

    // March up in w until s2 changes sign, inside the law's hoop limit, then
    // close the bracket with the project's root finder.
    const auto s2 = [&](const double w) {
      LawResponse p;
      return law->evaluate({in.l1, w, in.voltage}, no_step, law_stress, p) ?
               p.stress.s2 :
               std::numeric_limits<double>::quiet_NaN();
    };
    // A law without a limit (max_hoop_stretch infinite) is searched up to a
    // thousand times the hoop stretch: far beyond any film, and the search
    // ends where s2 stays negative (the voltage term outgrows the law).
    const double w_max = std::min(law->max_hoop_stretch(in.l1), 1e3 * std::max(1., in.l2));
    double       lo = in.l2, f_lo = r.stress.s2, hi = in.l2, f_hi = r.stress.s2;
    double       step = 1e-3 * in.l2;
    while (!(f_hi >= 0.))
      {
        lo   = hi;
        f_lo = f_hi;
        hi   = std::min(hi + step, lo + 0.5 * (w_max - lo));
        if (!(hi > lo) || w_max - hi < 1e-14 * w_max)
          {
            r.tension = TensionState::failed;
            return r;
          }
        f_hi = s2(hi);
        step *= 2.;
      }
    BracketedRootSettings settings;
    settings.x_tolerance     = 1e-15 * hi;
    settings.max_evaluations = 200;
    const double w           = find_bracketed_root(s2, lo, f_lo, hi, f_hi, settings).x;

    LawResponse at_w;
    law->evaluate({in.l1, w, in.voltage}, no_step, everything, at_w);
    const StressTangent &t = at_w.tangent;
    r.tension              = TensionState::wrinkled;
    r.natural_width        = w;
    r.energy               = at_w.energy;
    r.stress               = {at_w.stress.s1, 0.};
    r.tangent              = {t.s11 - t.s12 * t.s12 / t.s22, 0., 0.};
    r.loses_ellipticity    = !(r.tangent.s11 > 0.);
    return r;
  }

  bool TensionField::evaluate(const LawInput &in, const InternalStep &, const unsigned int,
                              LawResponse &response) const
  {
    response = relax(in);
    return response.tension != TensionState::failed;
  }

  bool TensionField::parameter_derivative(const LawInput &in, const InternalStep &step,
                                          const LawParameter parameter, double &d_energy,
                                          NominalStress &d_stress) const
  {
    const LawResponse r = relax(in);
    if (r.tension == TensionState::failed)
      return false;
    if (r.tension == TensionState::taut)
      return law->parameter_derivative(in, step, parameter, d_energy, d_stress);
    // Wrinkled: W_rel(p) = W(l1, w*(p); p) with s2(l1, w*) = 0, so dW_rel/dp =
    // dW/dp, and s1_rel = s1(l1, w*(p); p).
    const LawInput at_w{in.l1, r.natural_width, in.voltage};
    NominalStress  ds;
    LawResponse    t;
    if (!law->parameter_derivative(at_w, step, parameter, d_energy, ds) ||
        !law->evaluate(at_w, step, law_tangent, t))
      return false;
    const double dw_dp = -ds.s2 / t.tangent.s22;
    d_stress           = {ds.s1 + t.tangent.s12 * dw_dp, 0.};
    return true;
  }
} // namespace cdea
