#pragma once
// Tension-field (relaxed) membrane law wrapped around any law that provides
// energy(), stress() and tangent() in the principal stretches (l1, l2).
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
// Gent limit, and ds1_rel/dl1 <= 0 (the relaxed law loses monotonicity in l1:
// loss of strong ellipticity, the onset of pull-in).

#include <cdea/material/gent_dielectric.h>

#include <cmath>

namespace cdea
{
  enum class TensionState : int
  {
    taut     = 0,
    wrinkled = 1,
    failed   = 2 ///< no natural width below the Gent limit
  };

  struct RelaxedEvaluation
  {
    TensionState  state         = TensionState::taut;
    double        natural_width = 0.; ///< w* (equals l2 when taut)
    double        energy        = 0.;
    NominalStress stress{0., 0.};
    StressTangent tangent{0., 0., 0.};
    /// Wrinkled and ds1_rel/dl1 <= 0: the relaxed law is not elliptic here.
    bool loses_ellipticity = false;
  };

  template <typename Law>
  class TensionFieldRelaxation
  {
  public:
    explicit TensionFieldRelaxation(const Law &law)
      : law(law)
    {}

    const Law &base() const { return law; }

    RelaxedEvaluation evaluate(const double l1, const double l2) const
    {
      RelaxedEvaluation e;
      const NominalStress s = law.stress(l1, l2);
      if (s.s2 >= 0.)
        {
          e.natural_width = l2;
          e.energy        = law.energy(l1, l2);
          e.stress        = s;
          e.tangent       = law.tangent(l1, l2);
          return e;
        }
      // March up in w until s2 changes sign, inside the Gent range, then
      // bisect-secant (Illinois) to full precision.
      const double w_max = gent_hoop_limit(l1);
      double       lo = l2, f_lo = s.s2, hi = l2, f_hi = s.s2;
      double       step = 1e-3 * l2;
      while (f_hi < 0.)
        {
          lo   = hi;
          f_lo = f_hi;
          hi   = std::min(hi + step, lo + 0.5 * (w_max - lo));
          if (!(hi > lo) || w_max - hi < 1e-14 * w_max)
            {
              e.state = TensionState::failed;
              return e;
            }
          f_hi = law.stress(l1, hi).s2;
          step *= 2.;
        }
      int side = 0;
      for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k)
        {
          const double w = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
          const double f = law.stress(l1, w).s2;
          if (f == 0.)
            lo = hi = w;
          else if (f < 0.)
            {
              lo   = w;
              f_lo = f;
              if (side == -1)
                f_hi *= 0.5;
              side = -1;
            }
          else
            {
              hi   = w;
              f_hi = f;
              if (side == 1)
                f_lo *= 0.5;
              side = 1;
            }
        }
      const double        w  = 0.5 * (lo + hi);
      const StressTangent t  = law.tangent(l1, w);
      e.state                = TensionState::wrinkled;
      e.natural_width        = w;
      e.energy               = law.energy(l1, w);
      e.stress               = {law.stress(l1, w).s1, 0.};
      e.tangent              = {t.s11 - t.s12 * t.s12 / t.s22, 0., 0.};
      e.loses_ellipticity    = !(e.tangent.s11 > 0.);
      return e;
    }

    /// Largest hoop stretch inside the Gent limit at meridian stretch l1:
    /// l1^2 + w^2 + l1^-2 w^-2 - 3 < Jlim, solved for the larger root in w^2.
    double gent_hoop_limit(const double l1) const
    {
      const double c = law.constants().jlim + 3. - l1 * l1; // w^2 + q/w^2 = c, q = l1^-2
      const double q = 1. / (l1 * l1);
      const double d = c * c - 4. * q;
      return d > 0. ? std::sqrt(0.5 * (c + std::sqrt(d))) : 0.;
    }

  private:
    Law law;
  };
} // namespace cdea
