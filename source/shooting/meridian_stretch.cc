// The membrane law as the shooting integrator uses it (ShootingLaw of
// meridian.h: the plain law or its tension-field relaxation at one voltage)
// and the meridian stretch lambda1 that gives a required meridian stress s1
// at a hoop stretch lambda2 (solve_lambda1): a bracket grown from the
// guess, then TOMS 748 with Newton steps. The integrator is meridian.cc.
#include <cdea/material/gent_law.h>
#include <cdea/numerics/bracketed_root.h>
#include <cdea/shooting/meridian.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace cdea::shooting
{
  namespace
  {
    void set(std::string *why, const std::string &text)
    {
      if (why != nullptr)
        *why = text;
    }
  } // namespace

  ShootingLaw::ShootingLaw(std::shared_ptr<const MembraneLaw> plain_law,
                           const MaterialConstants &film, const double voltage,
                           const bool relaxed)
    : plain(std::move(plain_law))
    , relaxation(relaxed ? std::make_shared<const TensionField>(plain) : nullptr)
    , H(film.thickness)
    , mu(film.shear_modulus)
    , phi(voltage)
  {}

  bool ShootingLaw::respond(const double l1, const double l2, NominalStress &s,
                            StressTangent &t) const
  {
    // The relaxed law inside the plain law's range, as relaxed: also where
    // no natural width exists (TensionState::failed; the wrinkled zone's
    // own checks find that).
    LawResponse r;
    if (relaxation)
      {
        if (!(plain->range_margin(l1, l2) > 0.))
          return false;
        r = relaxation->relax({l1, l2, phi});
      }
    else if (!plain->evaluate({l1, l2, phi}, {}, law_stress | law_tangent, r))
      return false;
    s = r.stress;
    t = r.tangent;
    return true;
  }

  NominalStress ShootingLaw::stress(const double l1, const double l2) const
  {
    if (relaxation)
      return relaxation->relax({l1, l2, phi}).stress;
    return plain_stress(l1, l2);
  }

  double ShootingLaw::s11(const double l1, const double l2) const
  {
    NominalStress s{0., 0.};
    StressTangent t{0., 0., 0.};
    return respond(l1, l2, s, t) ? t.s11 : std::numeric_limits<double>::quiet_NaN();
  }

  NominalStress ShootingLaw::plain_stress(const double l1, const double l2) const
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    LawResponse      r;
    return plain->evaluate({l1, l2, phi}, {}, law_stress, r) ? r.stress : NominalStress{nan, nan};
  }

  std::string ShootingLaw::limit_reached() const
  {
    const LawLimit limit = plain->limit();
    return limit.name.empty() ? "the law's range was left" :
                                limit.name + " was reached (" + limit.margin + " <= 0)";
  }

  std::string ShootingLaw::margin_text(const double l1, const double l2) const
  {
    const LawLimit limit = plain->limit();
    if (limit.margin.empty())
      return {};
    std::ostringstream o;
    o << ", " << limit.margin << " = " << plain->range_margin(l1, l2);
    return o.str();
  }

  std::pair<double, double> gent_lambda1_range(const double jlim, const double lambda2)
  {
    return GentDielectricLaw::meridian_stretch_range(jlim, lambda2);
  }

  std::optional<double> solve_lambda1(const GentDielectric &law, const double l2,
                                      const double target, const double guess,
                                      std::string *why)
  {
    return solve_lambda1(
      ShootingLaw(std::make_shared<GentDielectricLaw>(law.constants()), law.constants(),
                  law.voltage(), false),
      l2, target, guess, why);
  }

  namespace
  {
    /// A bracket lo < hi with f(lo) <= 0 < f(hi) grown from @p guess in
    /// steps doubling from 2 % of it; never onto the domain ends l_lo, l_hi
    /// (f tends to -inf at l_lo and to +inf at l_hi). False with @p why if
    /// none is found.
    template <typename F>
    bool grow_bracket(const F &f, const double guess, const double l_lo, const double l_hi,
                      double &lo, double &flo, double &hi, double &fhi, std::string *why)
    {
      lo = hi  = guess;
      flo = fhi = f(guess);
      double       d = 0.02 * guess;
      unsigned int n = 0;
      while (flo > 0.)
        {
          hi       = lo;
          fhi      = flo;
          double c = lo - d;
          if (c <= l_lo)
            c = 0.5 * (lo + l_lo);
          if (c <= l_lo || c >= lo || ++n > 400)
            {
              set(why, "no lambda1 below the guess gives the required s1");
              return false;
            }
          lo  = c;
          flo = f(lo);
          d *= 2.;
        }
      while (fhi < 0.)
        {
          lo       = hi;
          flo      = fhi;
          double c = hi + d;
          if (c >= l_hi)
            c = 0.5 * (hi + l_hi);
          if (c >= l_hi || c <= hi || ++n > 400)
            {
              set(why, "no lambda1 above the guess gives the required s1");
              return false;
            }
          hi  = c;
          fhi = f(hi);
          d *= 2.;
        }
      return true;
    }

    /// Whether s1 rises from @p guess to the root @p x at every one of 33
    /// points: otherwise the law lost monotonicity (pull-in, loss of
    /// ellipticity) and the root lies on another branch of the law.
    bool rises_to_root(const ShootingLaw &law, const double l2, const double guess,
                       const double x, std::string *why)
    {
      constexpr unsigned int n_check = 32;
      for (unsigned int i = 0; i <= n_check; ++i)
        {
          const double l1 = guess + (x - guess) * i / n_check;
          if (!(law.s11(l1, l2) > 0.))
            {
              std::ostringstream o;
              o << "ds1/dlambda1 <= 0 at lambda1 = " << l1 << " between the start " << guess
                << " and the solution " << x << " (loss of monotonicity of the law, pull-in)";
              set(why, o.str());
              return false;
            }
        }
      return true;
    }
  } // namespace

  std::optional<double> solve_lambda1(const ShootingLaw &law, const double l2,
                                      const double target, double guess, std::string *why)
  {
    const auto [l_lo, l_hi] = law.meridian_stretch_range(l2);
    if (!(l_lo >= 0.) || !(l_hi > l_lo))
      {
        const std::string limit = law.limit().name;
        set(why, "hoop stretch beyond " + (limit.empty() ? "the law's range" : limit));
        return std::nullopt;
      }
    if (!std::isfinite(guess) || guess <= l_lo || guess >= l_hi)
      guess = std::isfinite(l_hi) && l_lo > 0. ? std::sqrt(l_lo * l_hi) : l2;
    const auto f = [&](const double l1) { return law.stress(l1, l2).s1 - target; };
    double     lo = 0., flo = 0., hi = 0., fhi = 0.;
    if (!grow_bracket(f, guess, l_lo, l_hi, lo, flo, hi, fhi, why))
      return std::nullopt;
    // The toolbox's safeguarded Newton to rounding level (the derivative is
    // cheap here; TOMS 748 without it made shooting runs up to 10 % slower).
    const auto df = [&](const double l1) { return law.s11(l1, l2); };
    BracketedRootSettings settings;
    settings.max_evaluations = 200;
    const BracketedRoot root  = find_bracketed_root_newton(f, df, lo, flo, hi, fhi, settings);
    const double        scale = std::abs(target) + law.shear_modulus();
    if (!(std::abs(root.f) <= 1e-9 * scale))
      {
        set(why, "the s1 equation for lambda1 did not converge");
        return std::nullopt;
      }
    if (!rises_to_root(law, l2, guess, root.x, why))
      return std::nullopt;
    return root.x;
  }
} // namespace cdea::shooting
