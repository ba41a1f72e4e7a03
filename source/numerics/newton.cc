#include <cdea/numerics/newton.h>

#include <cmath>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// Backtracking from @p x along @p dx: the first alpha = 1, 1/2, 1/4, ...
    /// whose residual norm decreases by the fraction 1e-4 alpha of @p norm0
    /// (Armijo) or is below the tolerance; @p trial and @p r_trial hold that
    /// point and its residual. 0 if none within max_backtracks halvings.
    /// With @p residual_alone every trial's residual only (no tangent), with
    /// settings.residual_alone_at_backtracks that of every shortened trial.
    double line_search(NonlinearProblem &problem, const NewtonSettings &settings,
                       const Eigen::VectorXd &x, const Eigen::VectorXd &dx, const double norm0,
                       const bool residual_alone, Eigen::VectorXd &trial,
                       Eigen::VectorXd &r_trial)
    {
      double alpha = 1.;
      for (unsigned int b = 0; b <= settings.max_backtracks; ++b, alpha *= 0.5)
        {
          trial = x + alpha * dx;
          if (residual_alone || (b > 0 && settings.residual_alone_at_backtracks))
            problem.evaluate_residual(trial, r_trial);
          else
            problem.evaluate(trial, r_trial);
          const double norm = r_trial.norm();
          if (std::isfinite(norm) &&
              (norm <= (1. - 1e-4 * alpha) * norm0 ||
               norm / settings.residual_scale < settings.residual_tolerance))
            return alpha;
        }
      return 0.;
    }

    /// The scaled residual @p res at @p x is at (or below) the residual's
    /// round-off level, which lies above the tolerance (and the settings
    /// accept that as converged).
    bool at_round_off(const NonlinearProblem &problem, const NewtonSettings &settings,
                      const Eigen::VectorXd &x, const double res)
    {
      return settings.converge_at_round_off &&
             res * settings.residual_scale <= problem.residual_floor(x);
    }

    /// Converged after the step alpha dx (largest entry @p upd, scaled) to a
    /// scaled residual @p res: both below their tolerances; or, near the
    /// solution, where the error left after a full update u is O(u^2), an
    /// update below @p early_update (1e-2 sqrt(update tolerance)) leaves an
    /// error far below the tolerance, so another iteration is not needed.
    bool ends_solve(const NewtonSettings &settings, const double res, const double alpha,
                    const double upd, const double early_update)
    {
      return res < settings.residual_tolerance &&
             (alpha * upd < settings.update_tolerance || (alpha == 1. && upd < early_update));
    }

    std::string no_decrease_message(const NewtonSettings &settings, const unsigned int k,
                                    const double res)
    {
      std::ostringstream m;
      m << "the line search found no decrease of the residual at Newton iteration " << k
        << " (residual " << res << ")";
      if (res < 1e3 * settings.residual_tolerance)
        m << "; the residual has stalled near the tolerance, at the round-off level "
             "of this discretization: Solver/Residual tolerance may be below what it "
             "can reach";
      else if (!settings.exact_tangent)
        m << "; the material's tangent is inexact, so its Newton direction need not "
             "decrease the residual";
      return m.str();
    }
  } // namespace

  namespace
  {
    /// Below this full update (scaled) a converged residual ends the solve:
    /// 1e-2 sqrt(update tolerance), with an exact tangent only (an inexact
    /// one leaves an O(u) error, not O(u^2)).
    double early_update_bound(const NewtonSettings &settings)
    {
      return settings.exact_tangent ? std::sqrt(settings.update_tolerance) * 1e-2 : 0.;
    }

    std::string no_convergence_message(const NewtonSettings &settings, const double res)
    {
      std::ostringstream m;
      m << "Newton did not converge in " << settings.max_iterations
        << " iterations (scaled residual " << res << ")";
      if (!settings.exact_tangent)
        m << "; the material's tangent is inexact (Newton converges linearly), so "
             "Solver/Max Newton iterations may need raising";
      return m.str();
    }
  } // namespace

  SolveReport LineSearchNewton::solve(NonlinearProblem &problem, Eigen::VectorXd &x)
  {
    SolveReport     report;
    Eigen::VectorXd r, dx, trial, r_trial;
    problem.evaluate(x, r);
    double res = r.lpNorm<Eigen::Infinity>() / settings.residual_scale;
    // allFinite(): the largest entry of a residual with NaN entries (outside
    // the range, constrained entries zero) may come out as 0.
    if (!r.allFinite() || !std::isfinite(res))
      {
        report.message = "the initial guess lies outside the material's range";
        return report;
      }
    // An exact predictor (the homogeneous pre-stretch) needs no iteration.
    if (res < 1e-3 * settings.residual_tolerance)
      {
        report.converged = true;
        return report;
      }
    for (unsigned int k = 1; k <= settings.max_iterations; ++k)
      {
        report.iterations = k;
        problem.solve_linearized(r, dx);
        const double upd = dx.lpNorm<Eigen::Infinity>() / settings.update_scale;
        if (!std::isfinite(upd))
          {
            report.message = "the tangent is singular or not finite";
            return report;
          }
        // An update this small ends the solve if its trial's residual is
        // below the tolerance (the early test below): evaluate that alone.
        const double early_update = early_update_bound(settings);
        const bool   residual_alone = settings.residual_alone_when_converging &&
                                    upd < early_update;
        const double alpha =
          line_search(problem, settings, x, dx, r.norm(), residual_alone, trial, r_trial);
        const bool tangent_left_out =
          residual_alone || (alpha != 1. && settings.residual_alone_at_backtracks);
        if (alpha == 0. && tangent_left_out)
          problem.evaluate(trial, r_trial); // the last trial with its tangent, as without
        if (alpha == 0.)
          {
            // No decrease from a state already at its round-off level, with
            // an update below the tolerance: as converged as it can be.
            if (upd < settings.update_tolerance && at_round_off(problem, settings, x, res))
              {
                report.converged = true;
                return report;
              }
            report.message = no_decrease_message(settings, k, res);
            return report;
          }
        x.swap(trial);
        r.swap(r_trial);
        res = r.lpNorm<Eigen::Infinity>() / settings.residual_scale;
        if (ends_solve(settings, res, alpha, upd, early_update))
          {
            report.converged = true;
            return report;
          }
        // Not converged: the tangent of the accepted state.
        if (tangent_left_out)
          problem.evaluate(x, r);
        // The full Newton update, not the step the line search took: near a
        // fold (a nearly singular tangent) the line search shortens a large
        // update, and a state there is not converged.
        if (upd < settings.update_tolerance && at_round_off(problem, settings, x, res))
          {
            report.converged = true;
            return report;
          }
      }
    report.message = no_convergence_message(settings, res);
    return report;
  }
} // namespace cdea
