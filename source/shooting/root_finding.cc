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
        res.x         = p.x;
        res.f         = p.f;
        res.message.clear();
        return res;
      }

      RootResult fail(const std::string &why)
      {
        res.converged = false;
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

      // Illinois: a is the retained end point; its value is halved each time
      // it is retained twice in a row, which keeps superlinear convergence.
      RootResult illinois(Point a, Point b)
      {
        const double eps = std::numeric_limits<double>::epsilon();
        while (true)
          {
            if (std::abs(b.x - a.x) <= 4. * eps * (std::abs(a.x) + std::abs(b.x)))
              {
                const Point &p = std::abs(a.f) < std::abs(b.f) ? a : b;
                if (std::abs(p.f) <= opt.collapse_tolerance)
                  return done(p);
                return fail("the residual changes sign without vanishing "
                            "(discontinuity)");
              }
            double c = (a.f * b.x - b.f * a.x) / (a.f - b.f);
            const double lo = std::min(a.x, b.x), hi = std::max(a.x, b.x);
            if (!(c > lo && c < hi))
              c = 0.5 * (a.x + b.x);
            auto pc = eval(c);
            if (!pc && !budget_exhausted)
              pc = eval(0.5 * (a.x + b.x));
            if (!pc)
              return fail("the integration fails inside the bracket");
            if (small(*pc))
              return done(*pc);
            if (pc->f * b.f < 0.)
              a = b;
            else
              a.f *= 0.5;
            b = *pc;
          }
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
                      return illinois(a, b);
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
                  return illinois(a, b);
              }
          }
        if (budget_exhausted)
          return fail("no convergence");

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
                return fail("no bracket found");
              if (!p)
                continue;
              if (small(*p))
                return done(*p);
              if (near[side] && near[side]->f * p->f < 0.)
                return illinois(*near[side], *p);
              near[side] = p;
            }
        return fail("no sign change of the residual near the guess");
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
