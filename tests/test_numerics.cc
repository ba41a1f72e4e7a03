// The numerics toolbox: the bracketed root finder (convergence, tolerances,
// failed evaluations), the band matrix with its LU, the rank-one update by
// Sherman-Morrison and the smallest eigenvalue of the symmetric part, all
// against dense Eigen computations of the same matrices.

#include <cdea/numerics/bracketed_root.h>
#include <cdea/numerics/band_eigenvalue.h>
#include <cdea/numerics/sherman_morrison.h>

#include <Eigen/Dense>

#include "check.h"

#include <cmath>
#include <limits>

using namespace cdea;
using namespace cdea_test;

CDEA_TEST_MAIN()
{
  std::cout << "Bracketed root finder\n";
  {
    // cos x = x: root 0.7390851332151607.
    unsigned int calls = 0;
    const auto   f     = [&](const double x) {
      ++calls;
      return std::cos(x) - x;
    };
    BracketedRootSettings s;
    s.x_tolerance        = 1e-14;
    const BracketedRoot r = find_bracketed_root(f, 0., f(0.), 1., f(1.), s);
    check(r.converged, "cos x = x converges");
    check_close(r.x, 0.7390851332151607, 1e-14, "cos x = x: the root");
    check(r.hi - r.lo <= 1e-14 || std::abs(r.f) == 0., "the final bracket is within the tolerance");
    check(r.evaluations <= 12, "superlinear: " + std::to_string(r.evaluations) + " evaluations");
    // Reversed bracket (hi below lo) and a function tolerance.
    s.x_tolerance  = 0.;
    s.f_tolerance  = 1e-6;
    const auto rev = find_bracketed_root(f, 1., f(1.), 0., f(0.), s);
    check(rev.converged && std::abs(rev.f) <= 1e-6, "reversed bracket, |f| tolerance");
    // No sign change: not converged, said why.
    const auto none = find_bracketed_root(f, 0., f(0.), 0.5, f(0.5), s);
    check(!none.converged && !none.message.empty() && none.status == RootStatus::no_sign_change,
          "no sign change is reported, with its status");
    check(r.status == RootStatus::converged, "a converged search has the status converged");

    // The safeguarded Newton on the same bracket, either way round (f falls:
    // the bracket's low end has f > 0), to rounding level in a few steps.
    const auto df = [](const double x) { return -std::sin(x) - 1.; };
    calls         = 0;
    const auto newton = find_bracketed_root_newton(f, df, 0., f(0.), 1., f(1.), s);
    check(newton.converged && newton.status == RootStatus::converged, "Newton converges");
    check_close(newton.x, 0.7390851332151607, 4e-16, "Newton: the root to rounding");
    check(calls <= 10, "Newton: " + std::to_string(calls) + " evaluations (quadratic)");
    const auto newton_reversed = find_bracketed_root_newton(f, df, 1., f(1.), 0., f(0.), s);
    check_close(newton_reversed.x, 0.7390851332151607, 4e-16, "Newton, reversed bracket");
    // A derivative of the wrong sign (here: none at all) falls back to bisection.
    const auto flat   = [](const double) { return 0.; };
    const auto halved = find_bracketed_root_newton(f, flat, 0., f(0.), 1., f(1.), s);
    check_close(halved.x, 0.7390851332151607, 1e-15, "Newton without a derivative: bisection");
    const auto newton_none = find_bracketed_root_newton(f, df, 0., f(0.), 0.5, f(0.5), s);
    check(newton_none.status == RootStatus::no_sign_change, "Newton: no sign change reported");
  }
  {
    // Evaluations fail beyond x = 0.6 (NaN): the root 0.5 of x - 0.5 is still
    // found by shrinking the bracket towards the evaluable side. The value
    // given at hi = 1 is small, so the first secant step lands beyond 0.6.
    const auto f = [](const double x) {
      return x > 0.6 ? std::numeric_limits<double>::quiet_NaN() : x - 0.5;
    };
    BracketedRootSettings s;
    s.x_tolerance       = 1e-12;
    const auto r        = find_bracketed_root(f, 0., -0.5, 1., 0.01, s);
    check(r.failed_evaluation, "a failed evaluation is noted");
    check_close(r.x, 0.5, 1e-12, "root found past failed evaluations");
    s.stop_on_failure = true;
    const auto stopped = find_bracketed_root(f, 0., -0.5, 1., 0.01, s);
    check(stopped.failed_evaluation && !stopped.converged,
          "stop_on_failure ends the search at the first failed evaluation");
  }

  std::cout << "Band matrix, LU, Sherman-Morrison, smallest eigenvalue\n";
  {
    const unsigned int n = 23, bw = 4;
    BandMatrix         K;
    K.reinit(n, bw);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > bw ? i - bw : 0); j <= std::min(n - 1, i + bw); ++j)
        {
          // Unsymmetric, not diagonally dominant in every row: pivoting matters.
          const double v = (i == j ? 0.5 + 0.1 * i : 1. / (1. + i + 2. * j)) * (i % 3 ? 1. : -1.);
          K(i, j)        = v;
          D(i, j)        = v;
        }
    Eigen::VectorXd b(n);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = std::sin(1. + i);
    Eigen::VectorXd y(n);
    K.vmult(b.data(), y.data());
    check_close((y - D * b).norm(), 0., 1e-13, "vmult = dense product");

    BandedLU lu;
    check(lu.factorize(K), "band LU factorizes");
    Eigen::VectorXd u = b;
    check(lu.solve(u), "band LU solves");
    const Eigen::VectorXd dense = D.partialPivLu().solve(b);
    check_close((u - dense).norm() / dense.norm(), 0., 1e-12, "band LU = dense LU");

    Eigen::VectorXd g(n);
    for (unsigned int i = 0; i < n; ++i)
      g[i] = std::cos(0.3 * i);
    const double    k = 2.7;
    ShermanMorrison sm;
    check(sm.prepare(lu, k, g), "Sherman-Morrison prepares");
    Eigen::VectorXd v = b;
    check(sm.solve(lu, v), "Sherman-Morrison solves");
    const Eigen::MatrixXd D1 = D + k * g * g.transpose();
    check_close((v - D1.partialPivLu().solve(b)).norm() / v.norm(), 0., 1e-12,
                "(K + k g g^T)^-1 b by Sherman-Morrison = dense");

    // Smallest eigenvalue of the symmetric part without rows/columns 0, 5, 22.
    const std::vector<unsigned int> excluded{0, 5, 22};
    std::vector<int>                keep;
    for (unsigned int i = 0; i < n; ++i)
      if (i != 0 && i != 5 && i != 22)
        keep.push_back(i);
    Eigen::MatrixXd S(keep.size(), keep.size());
    for (std::size_t i = 0; i < keep.size(); ++i)
      for (std::size_t j = 0; j < keep.size(); ++j)
        S(i, j) = 0.5 * (D(keep[i], keep[j]) + D(keep[j], keep[i]));
    const double expected = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues()(0);
    check(expected < 0., "the test matrix is indefinite");
    check_close(smallest_symmetric_eigenvalue(K, excluded), expected, 1e-12,
                "smallest eigenvalue of the free block = dense");

    K.constrain(7, 3.);
    check(K.entry(7, 6) == 0. && K.entry(6, 7) == 0. && K.entry(7, 7) == 3. &&
            K.entry(7, 12) == 0.,
          "constrain: row and column decoupled, diagonal set");
  }
  return finish();
}
