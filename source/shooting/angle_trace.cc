#include <cdea/shooting/angle_trace.h>
#include <cdea/shooting/root_finding.h>

#include <cmath>

namespace cdea::shooting
{
  AngleTrace::AngleTrace(const Scene &scene, const ShootingOptions &options)
    : scene(scene)
    , integrator(scene, options)
  {}

  MeridianLoad AngleTrace::load(const double t) const
  {
    return {scene.prestretch, scene.dead_load(), scene.path.voltages(t)};
  }

  AnglePoint AngleTrace::solve(const double theta0, const double t_guess,
                               const double lambda1_guess) const
  {
    AnglePoint   p;
    double       l1     = lambda1_guess;
    const double target = scene.prestretch * scene.outer_reference_radius();
    const auto   f      = [&](const double t) -> std::optional<double> {
      if (t < 0. || t > scene.path.n_segments())
        return std::nullopt;
      const Profile prof = integrator.shoot(load(t), theta0, l1, false);
      if (!prof.ok)
        return std::nullopt;
      l1 = prof.lambda1_start;
      return prof.r_end / target - 1.;
    };
    RootOptions options;
    options.residual_tolerance = 1e-13;
    options.first_step         = 1e-5;
    options.max_step           = 0.05;
    options.max_half_width     = 0.1;
    options.lower              = 0.;
    options.upper              = scene.path.n_segments();
    const RootResult root      = find_root_local(f, t_guess, options);
    if (!root.converged)
      {
        p.message = "no voltage gives r(B) = b at theta0 = " + std::to_string(theta0) + ": " +
                    root.message;
        return p;
      }
    const Profile prof = integrator.shoot(load(root.x), theta0, l1, false);
    p.ok               = prof.ok;
    p.theta0           = theta0;
    p.t                = root.x;
    p.lambda1_start    = prof.lambda1_start;
    p.displacement     = prof.displacement;
    p.message          = prof.message;
    return p;
  }

  std::optional<AnglePoint> AngleTrace::limit_point(const AnglePoint &start, const double dtheta,
                                                    const double tolerance,
                                                    std::string *why) const
  {
    // theta0 is not monotone along the path (it rises, then falls as l1 at
    // the disk grows): walk in the direction in which t increases.
    double     step = dtheta;
    AnglePoint a = start, b = solve(start.theta0 + step, start.t, start.lambda1_start);
    if (b.ok && b.t < a.t)
      {
        step = -dtheta;
        b    = solve(start.theta0 + step, start.t, start.lambda1_start);
      }
    if (!b.ok)
      {
        if (why)
          *why = b.message;
        return std::nullopt;
      }
    // Bracket the maximum of t(theta0): three points with the middle highest.
    while (true)
      {
        const AnglePoint c = solve(b.theta0 + step, b.t + (b.t - a.t), b.lambda1_start);
        if (!c.ok)
          {
            if (why)
              *why = c.message;
            return std::nullopt;
          }
        if (c.t < b.t)
          {
            // Golden-section search for the maximum on [a, c].
            const double g  = 0.5 * (std::sqrt(5.) - 1.);
            double       lo = std::min(a.theta0, c.theta0), hi = std::max(a.theta0, c.theta0);
            AnglePoint   x1 = solve(hi - g * (hi - lo), b.t, b.lambda1_start);
            AnglePoint   x2 = solve(lo + g * (hi - lo), b.t, b.lambda1_start);
            while (hi - lo > tolerance && x1.ok && x2.ok)
              if (x1.t > x2.t)
                {
                  hi = x2.theta0;
                  x2 = x1;
                  x1 = solve(hi - g * (hi - lo), x2.t, x2.lambda1_start);
                }
              else
                {
                  lo = x1.theta0;
                  x1 = x2;
                  x2 = solve(lo + g * (hi - lo), x1.t, x1.lambda1_start);
                }
            if (!x1.ok || !x2.ok)
              {
                if (why)
                  *why = x1.ok ? x2.message : x1.message;
                return std::nullopt;
              }
            return x1.t > x2.t ? x1 : x2;
          }
        a = b;
        b = c;
      }
  }
} // namespace cdea::shooting
