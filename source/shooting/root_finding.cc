#include <cdea/numerics/bracketed_root.h>
#include <cdea/shooting/root_finding.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace cdea::shooting
{
  namespace
  {
    struct Point
    {
      double x, f;
    };

    class Search
    {
    public:
      Search(const std::function<std::optional<double>(double)> &f,
             const RootOptions                                  &o)
        : func(f)
        , opt(o)
      {}

      std::optional<Point> eval(const double x)
      {
        if (res.evaluations >= opt.max_evaluations)
          {
            budget_exhausted = true;
            return std::nullopt;
          }
        ++res.evaluations;
        const auto v = func(x);
        if (!v || !std::isfinite(*v))
          return std::nullopt;
        if (!have_best || std::abs(*v) < std::abs(best.f))
          {
            best      = {x, *v};
            have_best = true;
          }
        return Point{x, *v};
      }

      bool small(const Point &p) const
      {
        return std::abs(p.f) <= opt.residual_tolerance;
      }

      RootResult done(const Point &p)
      {
        res.converged = true;
        res.status    = RootStatus::converged;
        res.x         = p.x;
        res.f         = p.f;
        res.message.clear();
        return res;
      }

      RootResult fail(const RootStatus status, const std::string &why)
      {
        res.converged = false;
        res.status    = budget_exhausted ? RootStatus::out_of_evaluations : status;
        if (have_best)
          {
            res.x = best.x;
            res.f = best.f;
          }
        std::ostringstream o;
        o << "root solve: " << why;
        if (budget_exhausted)
          o << " (evaluation budget of " << opt.max_evaluations << " exhausted)";
        if (have_best)
          o << "; smallest |residual| " << std::abs(best.f) << " at " << best.x;
        else
          o << "; no evaluation succeeded";
        res.message = o.str();
        return res;
      }

      /// Move x into the open domain, halfway towards a bound it crosses.
      double clip(const double x, const double from) const
      {
        if (x <= opt.lower)
          return 0.5 * (from + opt.lower);
        if (x >= opt.upper)
          return 0.5 * (from + opt.upper);
        return x;
      }

      // A sign change between a and b: the project's bracketed root finder.
      RootResult bracketed(const Point a, const Point b)
      {
        if (res.evaluations >= opt.max_evaluations)
          {
            budget_exhausted = true;
            return fail(RootStatus::not_converged, "no convergence");
          }
        BracketedRootSettings settings;
        settings.f_tolerance     = opt.residual_tolerance;
        settings.max_evaluations = opt.max_evaluations - res.evaluations;
        settings.stop_on_failure = true;
        const auto f = [&](const double x) {
          const auto p = eval(x);
          return p ? p->f : std::numeric_limits<double>::quiet_NaN();
        };
        const BracketedRoot r = find_bracketed_root(f, a.x, a.f, b.x, b.f, settings);
        const Point         p{r.x, r.f};
        if (small(p))
          return done(p);
        if (budget_exhausted || (!r.converged && !r.failed_evaluation))
          return fail(RootStatus::not_converged, "no convergence");
        if (r.failed_evaluation)
          return fail(RootStatus::failed_evaluation,
                      "the integration fails inside the bracket");
        // The bracket collapsed to rounding level.
        if (std::abs(p.f) <= opt.collapse_tolerance)
          return done(p);
        return fail(RootStatus::not_converged,
                    "the residual changes sign without vanishing (discontinuity)");
      }

      RootResult run(const double x0)
      {
        const auto p0 = eval(x0);
        if (p0 && small(*p0))
          return done(*p0);

        // Secant phase.
        if (p0)
          {
            double d  = opt.first_step;
            auto   p1 = eval(clip(x0 + d, x0));
            if (!p1)
              p1 = eval(clip(x0 - d, x0));
            if (p1)
              {
                Point a = *p0, b = *p1;
                for (unsigned int k = 0; k < opt.max_secant_steps; ++k)
                  {
                    if (small(b))
                      return done(b);
                    if (a.f * b.f < 0.)
                      return bracketed(a, b);
                    const double slope = (b.f - a.f) / (b.x - a.x);
                    if (!(std::abs(slope) > 0.) || !std::isfinite(slope))
                      break;
                    double step = -b.f / slope;
                    if (std::abs(step) > opt.max_step)
                      step = std::copysign(opt.max_step, step);
                    std::optional<Point> pn;
                    for (unsigned int h = 0; h < 6 && !pn && !budget_exhausted; ++h)
                      {
                        pn = eval(clip(b.x + step, b.x));
                        step *= 0.5;
                      }
                    if (!pn)
                      break;
                    a = b;
                    b = *pn;
                  }
                if (small(b))
                  return done(b);
                if (a.f * b.f < 0.)
                  return bracketed(a, b);
              }
          }
        if (budget_exhausted)
          return fail(RootStatus::not_converged, "no convergence");

        // Bracket phase: grow [x0 - d, x0 + d] until the residual changes sign
        // between neighbouring valid points on one side.
        std::optional<Point> near[2] = {p0, p0};
        double               prev[2] = {x0, x0};
        for (double d = 10. * opt.first_step; d <= opt.max_half_width * (1. + 1e-12);
             d *= 2.)
          for (int side = 0; side < 2; ++side)
            {
              const double sign = side == 0 ? 1. : -1.;
              const double x    = clip(x0 + sign * d, prev[side]);
              if (x == prev[side])
                continue;
              prev[side]   = x;
              const auto p = eval(x);
              if (budget_exhausted)
                return fail(RootStatus::no_sign_change, "no bracket found");
              if (!p)
                continue;
              if (small(*p))
                return done(*p);
              if (near[side] && near[side]->f * p->f < 0.)
                return bracketed(*near[side], *p);
              near[side] = p;
            }
        return fail(RootStatus::no_sign_change,
                    "no sign change of the residual near the guess");
      }

    private:
      const std::function<std::optional<double>(double)> &func;
      const RootOptions                                  &opt;
      RootResult                                          res;
      Point                                               best{0., 0.};
      bool                                                have_best        = false;
      bool                                                budget_exhausted = false;
    };
  } // namespace

  RootResult find_root_local(const std::function<std::optional<double>(double)> &f,
                             const double x0, const RootOptions &options)
  {
    Search search(f, options);
    return search.run(x0);
  }
} // namespace cdea::shooting
