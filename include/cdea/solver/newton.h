#pragma once
// Newton's method with a backtracking line search, written against a small
// interface so that the FE model (and later strategies) can swap it.
//
// Converged means both: the largest residual entry over residual_scale is below
// residual_tolerance, and the largest entry of the last update over update_scale
// is below update_tolerance. The line search halves the step until the residual
// 2-norm decreases (Armijo with c = 1e-4); a residual that is not finite (a
// trial state outside the Gent limit, say) counts as no decrease.

#include <cdea/solver/equilibrium_model.h>

#include <cmath>
#include <sstream>

namespace cdea
{
  struct NewtonSettings
  {
    double       residual_tolerance = 1e-10;
    double       update_tolerance   = 1e-10;
    unsigned int max_iterations     = 25;
    unsigned int max_backtracks     = 10;
    double       residual_scale     = 1.; ///< force scale of the residual
    double       update_scale       = 1.; ///< length scale of the unknowns
  };

  /// F(x) = 0 as Newton sees it. VectorType needs copy, add(a, v),
  /// l2_norm() and linfty_norm() (dealii::Vector<double> has them).
  template <typename VectorType>
  class NonlinearProblem
  {
  public:
    virtual ~NonlinearProblem() = default;
    /// Residual at @p x (zero in constrained entries).
    virtual void residual(const VectorType &x, VectorType &r) = 0;
    /// Solve J(x) dx = -r for the update dx (zero in constrained entries).
    virtual void newton_update(const VectorType &x, const VectorType &r, VectorType &dx) = 0;
  };

  template <typename VectorType>
  class NewtonStrategy
  {
  public:
    virtual ~NewtonStrategy() = default;
    /// Solve from the initial guess @p x; on failure @p x is unspecified.
    virtual SolveReport solve(NonlinearProblem<VectorType> &problem, VectorType &x) = 0;
  };

  template <typename VectorType>
  class LineSearchNewton : public NewtonStrategy<VectorType>
  {
  public:
    explicit LineSearchNewton(const NewtonSettings &settings)
      : settings(settings)
    {}

    SolveReport solve(NonlinearProblem<VectorType> &problem, VectorType &x) override
    {
      SolveReport report;
      VectorType  r(x), dx(x), trial(x), r_trial(x);
      problem.residual(x, r);
      double res = r.linfty_norm() / settings.residual_scale;
      if (!std::isfinite(res))
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
          problem.newton_update(x, r, dx);
          const double upd = dx.linfty_norm() / settings.update_scale;
          if (!std::isfinite(upd))
            {
              report.message = "the tangent is singular or not finite";
              return report;
            }
          const double norm0 = r.l2_norm();
          double       alpha = 1.;
          bool         accepted = false;
          for (unsigned int b = 0; b <= settings.max_backtracks; ++b, alpha *= 0.5)
            {
              trial = x;
              trial.add(alpha, dx);
              problem.residual(trial, r_trial);
              const double norm = r_trial.l2_norm();
              if (std::isfinite(norm) && (norm <= (1. - 1e-4 * alpha) * norm0 ||
                                          norm / settings.residual_scale <
                                            settings.residual_tolerance))
                {
                  accepted = true;
                  break;
                }
            }
          if (!accepted)
            {
              std::ostringstream m;
              m << "the line search found no decrease of the residual at Newton iteration "
                << k << " (residual " << res << ")";
              if (res < 1e3 * settings.residual_tolerance)
                m << "; the residual has stalled near the tolerance, at the round-off level "
                     "of this discretization: Solver/Residual tolerance may be below what it "
                     "can reach";
              report.message = m.str();
              return report;
            }
          x   = trial;
          r   = r_trial;
          res = r.linfty_norm() / settings.residual_scale;
          if (res < settings.residual_tolerance &&
              alpha * upd < settings.update_tolerance)
            {
              report.converged = true;
              return report;
            }
          // Near the solution the error left after a full update u is O(u^2):
          // an update below 1e-2 sqrt(update tolerance) already leaves an
          // error far below the tolerance, so another iteration is not needed.
          if (res < settings.residual_tolerance && alpha == 1. &&
              upd < std::sqrt(settings.update_tolerance) * 1e-2)
            {
              report.converged = true;
              return report;
            }
        }
      std::ostringstream m;
      m << "Newton did not converge in " << settings.max_iterations
        << " iterations (scaled residual " << res << ")";
      report.message = m.str();
      return report;
    }

  private:
    NewtonSettings settings;
  };
} // namespace cdea
