#pragma once
// Adaptive Dormand-Prince 5(4) integrator for a small fixed-size ODE system,
// with the 4th-order continuous extension (dense output) of each accepted step.
//
// The 5th-order solution is propagated (local extrapolation); the embedded
// 4th-order one only estimates the error. A step is accepted when
//   max_i |err_i| / (atol + rtol max(|y0_i|, |y1_i|)) <= 1,
// and the next step is h * clamp(0.9 err^(-1/5), 0.2, 5) (no growth right after
// a rejection). The last step of an interval is clipped so that it lands
// exactly on the interval's end. The first stage of a step is the last stage
// of the previous one (FSAL), so an accepted step costs 6 right-hand sides.
//
// The right-hand side is a callable bool(double x, const State &y, State &dy);
// returning false means "y is outside the domain of the model": the step is
// rejected and retried with a quarter of its size, and the integration fails
// when the step falls below min_step_fraction times the interval length.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace cdea::shooting
{
  template <int dim>
  class DormandPrince45
  {
  public:
    using State = Eigen::Matrix<double, dim, 1>;

    struct Control
    {
      double       rtol              = 1e-10;
      double       atol              = 1e-10;
      unsigned int max_steps         = 100000;
      double       min_step_fraction = 1e-13;
    };

    /// Continuous extension of one accepted step from x0 to x0 + h:
    ///   y(x0 + t h) = c0 + t (c1 + (1 - t) (c2 + t (c3 + (1 - t) c4))).
    struct DenseStep
    {
      double x0 = 0.;
      double h  = 0.;
      State  c[5];

      State operator()(const double x) const
      {
        const double t = (x - x0) / h;
        const double s = 1. - t;
        return c[0] + t * (c[1] + s * (c[2] + t * (c[3] + s * c[4])));
      }
    };

    struct Result
    {
      bool          ok = false;
      double        x  = 0.;  ///< where the integration stopped
      State         y;        ///< state there
      double        h_next = 0.; ///< proposed size of the next step
      unsigned long accepted_steps  = 0;
      unsigned long rejected_steps  = 0;
      unsigned long rhs_evaluations = 0;
      bool          domain_failure  = false; ///< failed because rhs refused a state
    };

    explicit DormandPrince45(const Control &control)
      : ctl(control)
    {}

    /// Integrate from (x0, y0) to x1 > x0. @p h0 is the first trial step; a
    /// value <= 0 asks for an automatic estimate. @p observe(step, x, y) is
    /// called after every accepted step with its dense output and end point.
    template <typename Rhs, typename Observer>
    Result integrate(Rhs &&rhs, const double x0, const double x1, const State &y0,
                     const double h0, Observer &&observe) const
    {
      // Butcher tableau of Dormand & Prince (1980).
      constexpr double c2 = 1. / 5, c3 = 3. / 10, c4 = 4. / 5, c5 = 8. / 9;
      constexpr double a21 = 1. / 5;
      constexpr double a31 = 3. / 40, a32 = 9. / 40;
      constexpr double a41 = 44. / 45, a42 = -56. / 15, a43 = 32. / 9;
      constexpr double a51 = 19372. / 6561, a52 = -25360. / 2187,
                       a53 = 64448. / 6561, a54 = -212. / 729;
      constexpr double a61 = 9017. / 3168, a62 = -355. / 33, a63 = 46732. / 5247,
                       a64 = 49. / 176, a65 = -5103. / 18656;
      constexpr double a71 = 35. / 384, a73 = 500. / 1113, a74 = 125. / 192,
                       a75 = -2187. / 6784, a76 = 11. / 84;
      // 5th- minus 4th-order weights.
      constexpr double e1 = 71. / 57600, e3 = -71. / 16695, e4 = 71. / 1920,
                       e5 = -17253. / 339200, e6 = 22. / 525, e7 = -1. / 40;
      // Dense-output correction (Hairer, Norsett & Wanner, sec. II.6).
      constexpr double d1 = -12715105075. / 11282082432.,
                       d3 = 87487479700. / 32700410799.,
                       d4 = -10690763975. / 1880347072.,
                       d5 = 701980252875. / 199316789632.,
                       d6 = -1453857185. / 822651844.,
                       d7 = 69997945. / 29380423.;

      Result res;
      res.x = x0;
      res.y = y0;
      const double span = x1 - x0;
      if (!(span > 0.))
        {
          res.ok = span == 0.;
          return res;
        }

      State k1, k2, k3, k4, k5, k6, k7, yt, y1;
      ++res.rhs_evaluations;
      if (!rhs(x0, y0, k1))
        {
          res.domain_failure = true;
          return res;
        }

      double h = h0 > 0. ? std::min(h0, span) :
                           initial_step(rhs, x0, y0, k1, span, res);
      if (!(h > 0.))
        return res;
      const double h_min         = ctl.min_step_fraction * span;
      double       x             = x0;
      State        y             = y0;
      bool         after_reject  = false;
      bool         domain_reject = false;

      while (true)
        {
          if (res.accepted_steps + res.rejected_steps >= ctl.max_steps)
            return res;
          bool         last       = false;
          const double h_proposed = h;
          if (x + 1.01 * h >= x1)
            {
              h    = x1 - x;
              last = true;
            }

          bool valid = true;
          yt         = y + h * a21 * k1;
          valid      = valid && (++res.rhs_evaluations, rhs(x + c2 * h, yt, k2));
          if (valid)
            {
              yt    = y + h * (a31 * k1 + a32 * k2);
              valid = (++res.rhs_evaluations, rhs(x + c3 * h, yt, k3));
            }
          if (valid)
            {
              yt    = y + h * (a41 * k1 + a42 * k2 + a43 * k3);
              valid = (++res.rhs_evaluations, rhs(x + c4 * h, yt, k4));
            }
          if (valid)
            {
              yt    = y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4);
              valid = (++res.rhs_evaluations, rhs(x + c5 * h, yt, k5));
            }
          if (valid)
            {
              yt = y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
              valid = (++res.rhs_evaluations, rhs(x + h, yt, k6));
            }
          if (valid)
            {
              y1 = y + h * (a71 * k1 + a73 * k3 + a74 * k4 + a75 * k5 + a76 * k6);
              valid = (++res.rhs_evaluations, rhs(x + h, y1, k7));
            }

          double err = 0.;
          if (valid)
            {
              const State e =
                h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
              for (int i = 0; i < dim; ++i)
                {
                  const double sk =
                    ctl.atol +
                    ctl.rtol * std::max(std::abs(y[i]), std::abs(y1[i]));
                  err = std::max(err, std::abs(e[i]) / sk);
                }
              valid = std::isfinite(err);
            }

          if (!valid)
            {
              // Outside the model's domain: retry much smaller.
              ++res.rejected_steps;
              domain_reject = true;
              after_reject  = true;
              h *= 0.25;
              if (h < h_min)
                {
                  res.domain_failure = true;
                  return res;
                }
              continue;
            }

          if (err <= 1.)
            {
              DenseStep dense;
              dense.x0        = x;
              dense.h         = h;
              const State dy  = y1 - y;
              const State bsp = h * k1 - dy;
              dense.c[0]      = y;
              dense.c[1]      = dy;
              dense.c[2]      = bsp;
              dense.c[3]      = dy - h * k7 - bsp;
              dense.c[4] =
                h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);

              ++res.accepted_steps;
              x  = last ? x1 : x + h;
              y  = y1;
              k1 = k7;
              observe(dense, x, y);

              double fac = err > 0. ? 0.9 * std::pow(err, -0.2) : 5.;
              fac        = std::clamp(fac, 0.2, after_reject ? 1. : 5.);
              after_reject = false;
              const double h_new = h * fac;
              if (last)
                {
                  res.ok     = true;
                  res.x      = x;
                  res.y      = y;
                  // A step clipped to the interval end says little about the
                  // step size the solution allows.
                  res.h_next = std::max(h_new, h_proposed);
                  return res;
                }
              h = h_new;
            }
          else
            {
              ++res.rejected_steps;
              after_reject = true;
              h *= std::max(0.2, 0.9 * std::pow(err, -0.2));
              if (h < h_min)
                {
                  res.domain_failure = domain_reject;
                  return res;
                }
            }
          res.x = x;
          res.y = y;
        }
    }

  private:
    Control ctl;

    /// First trial step from the size of y, f(y) and a finite-difference
    /// estimate of f' (Hairer, Norsett & Wanner, sec. II.4).
    template <typename Rhs>
    double initial_step(Rhs &rhs, const double x0, const State &y0,
                        const State &f0, const double span, Result &res) const
    {
      double d0 = 0., d1 = 0.;
      for (int i = 0; i < dim; ++i)
        {
          const double sk = ctl.atol + ctl.rtol * std::abs(y0[i]);
          d0 = std::max(d0, std::abs(y0[i]) / sk);
          d1 = std::max(d1, std::abs(f0[i]) / sk);
        }
      double h = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 * span : 0.01 * d0 / d1;
      h        = std::min(h, span);
      State y1 = y0 + h * f0, f1;
      ++res.rhs_evaluations;
      if (!rhs(x0 + h, y1, f1))
        return 0.01 * h;
      double d2 = 0.;
      for (int i = 0; i < dim; ++i)
        {
          const double sk = ctl.atol + ctl.rtol * std::abs(y0[i]);
          d2 = std::max(d2, std::abs(f1[i] - f0[i]) / sk);
        }
      d2 /= h;
      const double dmax = std::max(d1, d2);
      const double h1   = dmax <= 1e-15 ? std::max(1e-6 * span, 1e-3 * h) :
                                          std::pow(0.01 / dmax, 0.2);
      return std::min({100. * h, h1, span});
    }
  };
} // namespace cdea::shooting
