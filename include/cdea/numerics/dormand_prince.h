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
      Result res;
      res.x = x0;
      res.y = y0;
      const double span = x1 - x0;
      if (!(span > 0.))
        {
          res.ok = span == 0.;
          return res;
        }
      Stages k;
      ++res.rhs_evaluations;
      if (!rhs(x0, y0, k.k1))
        {
          res.domain_failure = true;
          return res;
        }
      double h = h0 > 0. ? std::min(h0, span) : initial_step(rhs, x0, y0, k.k1, span, res);
      if (!(h > 0.))
        return res;
      const double h_min = ctl.min_step_fraction * span;
      double       x     = x0;
      State        y     = y0, y1;
      bool         after_reject = false, domain_reject = false;
      while (res.accepted_steps + res.rejected_steps < ctl.max_steps)
        {
          const double h_proposed = h;
          const bool   last       = x + 1.01 * h >= x1;
          if (last)
            h = x1 - x;
          double err = 0.;
          if (!step(rhs, x, y, h, k, y1, res) || !std::isfinite(err = error(y, y1, h, k)))
            {
              // Outside the model's domain: retry much smaller.
              ++res.rejected_steps;
              domain_reject = after_reject = true;
              h *= 0.25;
              if (h < h_min)
                {
                  res.domain_failure = true;
                  return res;
                }
              continue;
            }
          if (err > 1.)
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
          else
            {
              const DenseStep dense = dense_step(x, h, y, y1, k);
              ++res.accepted_steps;
              x    = last ? x1 : x + h;
              y    = y1;
              k.k1 = k.k7;
              observe(dense, x, y);
              const double h_new = h * growth(err, after_reject);
              after_reject       = false;
              if (last)
                return finished(res, x, y, std::max(h_new, h_proposed));
              h = h_new;
            }
          res.x = x;
          res.y = y;
        }
      return res;
    }

  private:
    Control ctl;

    // Butcher tableau of Dormand & Prince (1980).
    static constexpr double c2 = 1. / 5, c3 = 3. / 10, c4 = 4. / 5, c5 = 8. / 9;
    static constexpr double a21 = 1. / 5;
    static constexpr double a31 = 3. / 40, a32 = 9. / 40;
    static constexpr double a41 = 44. / 45, a42 = -56. / 15, a43 = 32. / 9;
    static constexpr double a51 = 19372. / 6561, a52 = -25360. / 2187, a53 = 64448. / 6561,
                            a54 = -212. / 729;
    static constexpr double a61 = 9017. / 3168, a62 = -355. / 33, a63 = 46732. / 5247,
                            a64 = 49. / 176, a65 = -5103. / 18656;
    static constexpr double a71 = 35. / 384, a73 = 500. / 1113, a74 = 125. / 192,
                            a75 = -2187. / 6784, a76 = 11. / 84;
    // 5th- minus 4th-order weights.
    static constexpr double e1 = 71. / 57600, e3 = -71. / 16695, e4 = 71. / 1920,
                            e5 = -17253. / 339200, e6 = 22. / 525, e7 = -1. / 40;
    // Dense-output correction (Hairer, Norsett & Wanner, sec. II.6).
    static constexpr double dense1 = -12715105075. / 11282082432.,
                            dense3 = 87487479700. / 32700410799.,
                            dense4 = -10690763975. / 1880347072.,
                            dense5 = 701980252875. / 199316789632.,
                            dense6 = -1453857185. / 822651844., dense7 = 69997945. / 29380423.;

    /// The stages of a step: k1 = f(x, y) (the last stage of the step
    /// before) to k7 = f(x + h, y1).
    struct Stages
    {
      State k1, k2, k3, k4, k5, k6, k7;
    };

    /// Stages k2 to k7 and the 5th-order solution y1 of the step h from
    /// (x, y); false as soon as rhs refuses a state.
    template <typename Rhs>
    static bool step(Rhs &rhs, const double x, const State &y, const double h, Stages &k,
                     State &y1, Result &res)
    {
      State yt = y + h * a21 * k.k1;
      if (!(++res.rhs_evaluations, rhs(x + c2 * h, yt, k.k2)))
        return false;
      yt = y + h * (a31 * k.k1 + a32 * k.k2);
      if (!(++res.rhs_evaluations, rhs(x + c3 * h, yt, k.k3)))
        return false;
      yt = y + h * (a41 * k.k1 + a42 * k.k2 + a43 * k.k3);
      if (!(++res.rhs_evaluations, rhs(x + c4 * h, yt, k.k4)))
        return false;
      yt = y + h * (a51 * k.k1 + a52 * k.k2 + a53 * k.k3 + a54 * k.k4);
      if (!(++res.rhs_evaluations, rhs(x + c5 * h, yt, k.k5)))
        return false;
      yt = y + h * (a61 * k.k1 + a62 * k.k2 + a63 * k.k3 + a64 * k.k4 + a65 * k.k5);
      if (!(++res.rhs_evaluations, rhs(x + h, yt, k.k6)))
        return false;
      y1 = y + h * (a71 * k.k1 + a73 * k.k3 + a74 * k.k4 + a75 * k.k5 + a76 * k.k6);
      return ++res.rhs_evaluations, rhs(x + h, y1, k.k7);
    }

    /// The step's error max_i |err_i| / (atol + rtol max(|y_i|, |y1_i|)).
    double error(const State &y, const State &y1, const double h, const Stages &k) const
    {
      const State e = h * (e1 * k.k1 + e3 * k.k3 + e4 * k.k4 + e5 * k.k5 + e6 * k.k6 + e7 * k.k7);
      double      err = 0.;
      for (int i = 0; i < dim; ++i)
        {
          const double sk = ctl.atol + ctl.rtol * std::max(std::abs(y[i]), std::abs(y1[i]));
          err             = std::max(err, std::abs(e[i]) / sk);
        }
      return err;
    }

    /// The continuous extension of the accepted step h from (x, y) to y1.
    static DenseStep dense_step(const double x, const double h, const State &y, const State &y1,
                                const Stages &k)
    {
      DenseStep   dense;
      const State dy  = y1 - y;
      const State bsp = h * k.k1 - dy;
      dense.x0        = x;
      dense.h         = h;
      dense.c[0]      = y;
      dense.c[1]      = dy;
      dense.c[2]      = bsp;
      dense.c[3]      = dy - h * k.k7 - bsp;
      dense.c[4]      = h * (dense1 * k.k1 + dense3 * k.k3 + dense4 * k.k4 + dense5 * k.k5 +
                        dense6 * k.k6 + dense7 * k.k7);
      return dense;
    }

    /// The factor of the next step after an accepted one of error @p err:
    /// 0.9 err^(-1/5) within [0.2, 5], at most 1 right after a rejection.
    static double growth(const double err, const bool after_reject)
    {
      const double fac = err > 0. ? 0.9 * std::pow(err, -0.2) : 5.;
      return std::clamp(fac, 0.2, after_reject ? 1. : 5.);
    }

    /// @p res of an integration that reached its end (x, y); the next step
    /// h_next (a step clipped to the interval end says little about the step
    /// size the solution allows, so not below the one proposed for it).
    static Result &finished(Result &res, const double x, const State &y, const double h_next)
    {
      res.ok     = true;
      res.x      = x;
      res.y      = y;
      res.h_next = h_next;
      return res;
    }

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
