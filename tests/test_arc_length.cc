// Pseudo-arclength continuation on problems with known folds:
// (1) a scalar snap-through r(x, t) = x^3 - 3 x - t: limit points at
//     (x, t) = (-1, 2) and (1, -2) on the S-shaped curve;
// (2) the same in two unknowns with a coupling that keeps the fold, to test the
//     weighted inner product and the bordered solve with a matrix.

#include <cdea/numerics/arc_length.h>

#include "check.h"

#include <cmath>
#include <vector>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// r_0 = x0^3 - 3 x0 - t + c x1,  r_1 = k (x1 - x0^2) (x1 follows x0^2).
  class Snap : public ContinuationProblem
  {
  public:
    Snap(double coupling, double stiffness, unsigned int n)
      : c(coupling)
      , k(stiffness)
      , n(n)
    {}

    void residual(const Eigen::VectorXd &x, const double t, Eigen::VectorXd &r) override
    {
      r.resize(n);
      r(0) = x(0) * x(0) * x(0) - 3. * x(0) - t + (n > 1 ? c * x(1) : 0.);
      if (n > 1)
        r(1) = k * (x(1) - x(0) * x(0));
    }
    void residual_t(const Eigen::VectorXd &, double, Eigen::VectorXd &r_t) override
    {
      r_t = Eigen::VectorXd::Zero(n);
      r_t(0) = -1.;
    }
    void factorize(const Eigen::VectorXd &x, double) override
    {
      K.resize(n, n);
      K(0, 0) = 3. * x(0) * x(0) - 3.;
      if (n > 1)
        {
          K(0, 1) = c;
          K(1, 0) = -2. * k * x(0);
          K(1, 1) = k;
        }
      lu.compute(K);
    }
    void solve(const Eigen::VectorXd &rhs, Eigen::VectorXd &s) override { s = lu.solve(rhs); }
    double dot(const Eigen::VectorXd &a, const Eigen::VectorXd &b) const override
    {
      return a.dot(b);
    }
    double          residual_scale() const override { return 1.; }
    Eigen::VectorXd current() const override { return Eigen::VectorXd::Zero(n); }
    void            set_current(const Eigen::VectorXd &, double) override {}
    double update_scale() const override { return 1.; }

  private:
    double                           c, k;
    unsigned int                     n;
    Eigen::MatrixXd                  K;
    Eigen::FullPivLU<Eigen::MatrixXd> lu;
  };

  /// Trace from x = -2.5 along increasing t, collect the limit points.
  std::vector<ArcLength::Point> trace(ContinuationProblem &problem, const Eigen::VectorXd &x0,
                                      const double t0)
  {
    ArcLength        arc(problem, ArcLengthSettings());
    ArcLength::Point p;
    p.x = x0;
    p.t = t0;
    arc.tangent(p);
    std::vector<ArcLength::Point> limits;
    for (int k = 0; k < 2000 && p.x(0) < 2.5; ++k)
      {
        ArcLength::Point q;
        const double     ds = 0.05;
        if (!arc.step(p, ds, q))
          break;
        if ((q.t_dot > 0.) != (p.t_dot > 0.))
          {
            ArcLength::Point limit;
            if (arc.locate_limit_point(p, ds, q.t_dot, limit))
              limits.push_back(limit);
          }
        p = q;
      }
    return limits;
  }
} // namespace

CDEA_TEST_MAIN()
{
  {
    Snap            scalar(0., 1., 1);
    Eigen::VectorXd x0(1);
    x0 << -2.5;
    const double t0     = std::pow(-2.5, 3) + 7.5;
    const auto   limits = trace(scalar, x0, t0);
    check(limits.size() == 2, "scalar S-curve: two limit points passed");
    if (limits.size() == 2)
      {
        check_close(limits[0].x(0), -1., 1e-8, "first limit point x");
        check_close(limits[0].t, 2., 1e-12, "first limit point t (extremal: quadratic accuracy)");
        check_close(limits[1].x(0), 1., 1e-8, "second limit point x");
        check_close(limits[1].t, -2., 1e-12, "second limit point t");
      }
  }
  {
    // With x1 = x0^2 and coupling c: r0 = x0^3 + c x0^2 - 3 x0 - t, whose
    // extrema in x0 solve 3 x^2 + 2 c x - 3 = 0.
    const double    c = 0.4;
    Snap            coupled(c, 50., 2);
    Eigen::VectorXd x0(2);
    x0 << -2.5, 6.25;
    const double t0     = std::pow(-2.5, 3) + c * 6.25 + 7.5;
    const auto   limits = trace(coupled, x0, t0);
    const double xa     = (-2. * c - std::sqrt(4. * c * c + 36.)) / 6.;
    const double xb     = (-2. * c + std::sqrt(4. * c * c + 36.)) / 6.;
    auto         t_of   = [&](double x) { return x * x * x + c * x * x - 3. * x; };
    check(limits.size() == 2, "coupled system: two limit points passed");
    if (limits.size() == 2)
      {
        check_close(limits[0].x(0), xa, 1e-8, "first limit point x0");
        check_close(limits[0].t, t_of(xa), 1e-12, "first limit point t");
        check_close(limits[1].x(0), xb, 1e-8, "second limit point x0");
        check_close(limits[1].t, t_of(xb), 1e-12, "second limit point t");
      }
  }
  return finish();
}
