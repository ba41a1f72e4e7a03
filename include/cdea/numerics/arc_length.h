#pragma once
// Pseudo-arclength continuation (Keller) of r(x, t) = 0 in the unknowns x and a
// load parameter t, with a bordered Newton corrector solved by block
// elimination (two solves with one factorization of K = dr/dx).
//
// A point carries its unit tangent (x', t'), ||x'||_w^2 + t'^2 = 1 in the
// problem's weighted inner product. From a point P0 a step of length ds
// predicts P0 + ds (x0', t0') and corrects on
//
//   r(x, t) = 0,   N = <x0', x - x0>_w + t0' (t - t0) - ds = 0.
//
// The tangent at the new point solves K b = dr/dt, t' = 1 / (t0' - <x0', b>_w),
// x' = -t' b, then normalised: the bordered row keeps the direction of travel
// through a limit point, where t' changes sign. A limit point between two
// points is located by a bracketed root search for t' = 0 over the step
// length from the first point.

#include <cdea/numerics/bracketed_root.h>

#include <Eigen/Dense>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace cdea
{
  class ContinuationProblem
  {
  public:
    virtual ~ContinuationProblem() = default;
    /// Residual r(x, t), zero in constrained entries.
    virtual void residual(const Eigen::VectorXd &x, double t, Eigen::VectorXd &r) = 0;
    /// dr/dt at (x, t).
    virtual void residual_t(const Eigen::VectorXd &x, double t, Eigen::VectorXd &r_t) = 0;
    /// Factorize K = dr/dx at (x, t); solve() then uses that factorization.
    virtual void factorize(const Eigen::VectorXd &x, double t) = 0;
    virtual void solve(const Eigen::VectorXd &rhs, Eigen::VectorXd &solution) = 0;
    /// Dimensionless inner product of unknown vectors (the arc length's metric).
    virtual double dot(const Eigen::VectorXd &a, const Eigen::VectorXd &b) const = 0;
    /// Scales for convergence: largest residual entry / residual_scale and
    /// largest update entry / update_scale.
    virtual double residual_scale() const = 0;
    virtual double update_scale() const   = 0;
    /// The unknowns of the model's current state, and making (x, t) the
    /// model's current state (an equilibrium found by the continuation).
    virtual Eigen::VectorXd current() const                              = 0;
    virtual void            set_current(const Eigen::VectorXd &x, double t) = 0;
  };

  struct ArcLengthSettings
  {
    double       residual_tolerance = 1e-10;
    double       update_tolerance   = 1e-10;
    unsigned int max_iterations     = 12;
  };

  class ArcLength
  {
  public:
    struct Point
    {
      Eigen::VectorXd x;
      double          t = 0.;
      Eigen::VectorXd x_dot;
      double          t_dot      = 1.;
      unsigned int    iterations = 0;
    };

    ArcLength(ContinuationProblem &problem, const ArcLengthSettings &settings)
      : problem(problem)
      , settings(settings)
    {}

    /// Tangent at the equilibrium (x, t), oriented like @p previous (or, with
    /// no previous point, towards increasing t).
    void tangent(Point &p, const Point *previous = nullptr)
    {
      Eigen::VectorXd r_t, b;
      problem.residual_t(p.x, p.t, r_t);
      problem.factorize(p.x, p.t);
      problem.solve(r_t, b);
      double t_dot;
      if (previous)
        t_dot = 1. / (previous->t_dot - problem.dot(previous->x_dot, b));
      else
        t_dot = 1.;
      Eigen::VectorXd x_dot = -t_dot * b;
      const double    norm  = std::sqrt(problem.dot(x_dot, x_dot) + t_dot * t_dot);
      p.x_dot               = x_dot / norm;
      p.t_dot               = t_dot / norm;
    }

    /// One step of length ds from @p from (which carries its tangent); on
    /// success @p to holds the new point with its tangent.
    bool step(const Point &from, const double ds, Point &to, std::string *why = nullptr)
    {
      to.x = from.x + ds * from.x_dot;
      to.t = from.t + ds * from.t_dot;
      Eigen::VectorXd r, r_t, a, b;
      for (unsigned int k = 1; k <= settings.max_iterations; ++k)
        {
          problem.residual(to.x, to.t, r);
          if (!r.allFinite())
            return fail(why, "the corrector left the material's range");
          const double N = problem.dot(from.x_dot, to.x - from.x) + from.t_dot * (to.t - from.t) - ds;
          problem.residual_t(to.x, to.t, r_t);
          problem.factorize(to.x, to.t);
          problem.solve(-r, a);
          problem.solve(r_t, b);
          const double denominator = from.t_dot - problem.dot(from.x_dot, b);
          const double dt          = (-N - problem.dot(from.x_dot, a)) / denominator;
          const Eigen::VectorXd dx = a - dt * b;
          if (!dx.allFinite() || !std::isfinite(dt))
            return fail(why, "the bordered system is singular");
          to.x += dx;
          to.t += dt;
          to.iterations = k;
          problem.residual(to.x, to.t, r);
          const double res = r.lpNorm<Eigen::Infinity>() / problem.residual_scale();
          const double upd = dx.lpNorm<Eigen::Infinity>() / problem.update_scale();
          if (res < settings.residual_tolerance && upd < settings.update_tolerance)
            {
              tangent(to, &from);
              return true;
            }
        }
      return fail(why, "the arc-length corrector did not converge in " +
                         std::to_string(settings.max_iterations) + " iterations");
    }

    /// Between @p from (t' > 0, say) and a later point with t' of the other
    /// sign reached with step @p ds: the point with t' = 0 (a limit point),
    /// found by the project's bracketed root finder over the step length.
    bool locate_limit_point(const Point &from, const double ds, const double t_dot_end,
                            Point &limit, const double tolerance = 1e-12)
    {
      bool found = false;
      const auto t_dot = [&](const double s) {
        Point p;
        if (!step(from, s, p))
          return std::numeric_limits<double>::quiet_NaN();
        if (!found || std::abs(p.t_dot) < std::abs(limit.t_dot))
          limit = p;
        found = true;
        return p.t_dot;
      };
      BracketedRootSettings settings;
      settings.x_tolerance     = tolerance * ds;
      settings.f_tolerance     = tolerance;
      settings.stop_on_failure = true;
      find_bracketed_root(t_dot, 0., from.t_dot, ds, t_dot_end, settings);
      return found;
    }

  private:
    ContinuationProblem &problem;
    ArcLengthSettings    settings;

    static bool fail(std::string *why, const std::string &message)
    {
      if (why)
        *why = message;
      return false;
    }
  };
} // namespace cdea
