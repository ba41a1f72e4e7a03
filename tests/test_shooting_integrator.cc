// The Dormand-Prince 5(4) integrator of the shooting model on problems with
// known solutions: global error under the tolerance, order of the local error
// and of the dense output, exact landing on the interval end, refusal of
// states outside the domain.

#include <cdea/numerics/dormand_prince.h>

#include "check.h"

#include <cmath>
#include <iostream>

using cdea_test::check;
using cdea_test::check_close;
using Integrator = cdea::shooting::DormandPrince45<4>;
using State      = Integrator::State;

namespace
{
  // y0 = sin x, y1 = cos x, y2 = exp(-x^2/2), y3 = 1 + x^3.
  State exact(const double x)
  {
    return State(std::sin(x), std::cos(x), std::exp(-0.5 * x * x), 1. + x * x * x);
  }

  bool rhs(const double x, const State &y, State &dy)
  {
    dy = State(y[1], -y[0], -x * y[2], 3. * x * x);
    return true;
  }

  /// One step of size h from the exact state at x0: errors of the step's end
  /// and of its dense output at the midpoint.
  std::pair<double, double> one_step(const double x0, const double h)
  {
    Integrator::Control c;
    c.rtol = c.atol = 1.; // accept the first trial step
    const Integrator rk(c);
    double           mid_err = 0.;
    const auto       res     = rk.integrate(rhs, x0, x0 + h, exact(x0), h,
                                   [&](const Integrator::DenseStep &s, double, const State &) {
                                     const double xm = x0 + 0.5 * h;
                                     mid_err = (s(xm) - exact(xm)).cwiseAbs().maxCoeff();
                                   });
    check(res.ok && res.accepted_steps == 1, "single step accepted");
    return {(res.y - exact(x0 + h)).cwiseAbs().maxCoeff(), mid_err};
  }
} // namespace

CDEA_TEST_MAIN()
{
  std::cout.precision(6);
  for (const double tol : {1e-6, 1e-8, 1e-10})
    {
      Integrator::Control c;
      c.rtol = c.atol = tol;
      const Integrator rk(c);
      double           dense_err = 0.;
      const auto res = rk.integrate(rhs, 0., 4., exact(0.), 0.,
                                    [&](const Integrator::DenseStep &s, const double x,
                                        const State &) {
                                      for (int j = 1; j < 8; ++j)
                                        {
                                          const double xs = s.x0 + j * (x - s.x0) / 8.;
                                          dense_err = std::max(
                                            dense_err,
                                            (s(xs) - exact(xs)).cwiseAbs().maxCoeff());
                                        }
                                    });
      const double err = (res.y - exact(4.)).cwiseAbs().maxCoeff();
      std::cout << "  tol " << tol << ": " << res.accepted_steps << " steps, "
                << res.rejected_steps << " rejected, " << res.rhs_evaluations
                << " rhs, end error " << err << ", dense error " << dense_err << "\n";
      check(res.ok && res.x == 4., "lands exactly on the interval end");
      check(err < 50. * tol, "global error within 50 tol");
      check(dense_err < 50. * tol, "dense output error within 50 tol");
      check(res.rhs_evaluations == 6 * (res.accepted_steps + res.rejected_steps) + 2,
            "FSAL: 6 rhs per step attempt plus the first and the step estimate");
    }

  // Local errors: O(h^6) for the step, O(h^5) for the 4th-order dense output.
  const auto e1 = one_step(0.3, 0.2), e2 = one_step(0.3, 0.1);
  const double p_step = std::log2(e1.first / e2.first);
  const double p_dense = std::log2(e1.second / e2.second);
  std::cout << "  observed local orders: step " << p_step << ", dense " << p_dense << "\n";
  check(p_step > 5.5, "local error of a step is O(h^6)");
  check(p_dense > 4.5 && p_dense < 6.5, "dense output error is O(h^5)");

  // A right-hand side that refuses y3 > 2 (reached at x = 1) makes the
  // integration fail there, instead of running on.
  {
    Integrator::Control c;
    const Integrator    rk(c);
    const auto          res = rk.integrate(
      [](const double x, const State &y, State &dy) { return y[3] <= 2. && rhs(x, y, dy); },
      0., 4., exact(0.), 0., [](const Integrator::DenseStep &, double, const State &) {});
    check(!res.ok && res.domain_failure, "refused states stop the integration");
    check_close(res.x, 1., 1e-6, "it stops where the domain ends");
  }
  return cdea_test::finish();
}
