#include <cdea/shooting/root_finding.h>
#include <cdea/shooting/shooting_solver.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cdea::shooting
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// Shared driver: @p run(x, l1_guess) integrates for the unknown x.
    template <typename Run>
    ShootingSolution solve(const MeridianIntegrator &integrator,
                           const MeridianLoad &load, const double x0,
                           double lambda1_guess, const RootOptions &ro,
                           const bool with_samples, Run &&run)
    {
      ShootingSolution sol;
      const double     target = load.stretch * integrator.scene().outer_reference_radius();
      std::string      last_failure;
      // (x, l1(A)) of every successful integration, to restart the final
      // sampled pass from exactly the converged start values.
      std::vector<std::pair<double, double>> starts;

      const auto residual = [&](const double x) -> std::optional<double> {
        const Profile p = run(x, lambda1_guess, false);
        sol.rhs_evaluations += p.rhs_evaluations;
        ++sol.integrations;
        if (!p.ok)
          {
            last_failure = p.message;
            return std::nullopt;
          }
        lambda1_guess = p.lambda1_start;
        starts.emplace_back(x, p.lambda1_start);
        return p.r_end / target - 1.;
      };

      const RootResult root = find_root_local(residual, x0, ro);
      if (!root.converged)
        {
          sol.message = root.message + (load.force > 0. ? " (theta0)" : " (lambda1 at A)");
          if (root.status == RootStatus::no_sign_change)
            sol.message += "; the equilibrium branch may have passed a fold (limit point): "
                           "take a smaller load step or use arc-length continuation";
          if (!last_failure.empty())
            sol.message += "; last failed integration: " + last_failure;
          return sol;
        }
      double l1 = 0.;
      for (const auto &s : starts)
        if (s.first == root.x)
          l1 = s.second;
      sol.profile = integrator.integrate(load, load.force > 0. ? root.x : 0., l1,
                                         with_samples);
      sol.rhs_evaluations += sol.profile.rhs_evaluations;
      if (!sol.profile.ok)
        {
          sol.message = "final pass failed: " + sol.profile.message;
          return sol;
        }
      sol.residual  = sol.profile.r_end / target - 1.;
      sol.converged = true;
      return sol;
    }
  } // namespace

  ShootingSolution solve_cone(const MeridianIntegrator &integrator,
                              const MeridianLoad &load, const double theta0_guess,
                              const double lambda1_guess, const bool with_samples)
  {
    if (!(load.force > 0.))
      {
        ShootingSolution sol;
        sol.message = "solve_cone needs a positive dead load";
        return sol;
      }
    const ShootingOptions &o = integrator.options();
    RootOptions            ro;
    ro.residual_tolerance = o.root_tolerance;
    ro.collapse_tolerance = std::max(1e-8, 1e3 * o.root_tolerance);
    ro.max_evaluations    = o.max_root_iterations;
    ro.first_step         = 1e-4 + 1e-3 * theta0_guess;
    ro.max_step           = 0.25;
    ro.max_half_width     = 0.5;
    ro.lower              = 0.;
    ro.upper              = pi;
    return solve(integrator, load, theta0_guess, lambda1_guess, ro, with_samples,
                 [&](const double theta0, const double l1_guess, const bool samples) {
                   return integrator.shoot(load, theta0, l1_guess, samples);
                 });
  }

  ShootingSolution solve_flat(const MeridianIntegrator &integrator,
                              const MeridianLoad &load, const double lambda1_guess,
                              const bool with_samples)
  {
    if (load.force != 0.)
      {
        ShootingSolution sol;
        sol.message = "solve_flat needs F = 0";
        return sol;
      }
    const ShootingOptions &o     = integrator.options();
    const auto             range = integrator.law().meridian_stretch_range(load.stretch);
    const double guess = lambda1_guess > 0. ? lambda1_guess : load.stretch;
    RootOptions  ro;
    ro.residual_tolerance = o.root_tolerance;
    ro.collapse_tolerance = std::max(1e-8, 1e3 * o.root_tolerance);
    ro.max_evaluations    = o.max_root_iterations;
    ro.first_step         = 1e-4 * guess;
    ro.max_step           = 0.25 * guess;
    ro.max_half_width     = 0.5 * guess;
    ro.lower              = range.first;
    ro.upper              = range.second;
    return solve(integrator, load, guess, guess, ro, with_samples,
                 [&](const double l1, double, const bool samples) {
                   return integrator.integrate(load, 0., l1, samples);
                 });
  }
} // namespace cdea::shooting
