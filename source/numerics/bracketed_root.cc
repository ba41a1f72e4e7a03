#include <cdea/numerics/bracketed_root.h>

#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace cdea
{
  namespace
  {
    // Thrown out of Boost's iteration to end it early.
    struct FailedEvaluation
    {
      double x;
    };
    struct SmallEnough
    {};
    struct OutOfEvaluations
    {};
  } // namespace

  BracketedRoot find_bracketed_root(const std::function<double(double)> &f, double lo,
                                    double f_lo, double hi, double f_hi,
                                    const BracketedRootSettings &settings)
  {
    BracketedRoot result;
    // The best point so far, and the tightest bracket the evaluations show
    // (TOMS 748 evaluates inside its current bracket only).
    const bool lo_positive = f_lo > 0.;
    double     bracket_lo = lo, bracket_hi = hi, f_bracket_lo = f_lo;
    const auto note        = [&](const double x, const double fx) {
      if (std::isnan(result.f) || std::abs(fx) < std::abs(result.f))
        {
          result.x = x;
          result.f = fx;
        }
      if ((fx > 0.) == lo_positive)
        {
          bracket_lo   = x;
          f_bracket_lo = fx;
        }
      else
        bracket_hi = x;
    };
    result.f = std::numeric_limits<double>::quiet_NaN();
    note(lo, f_lo);
    note(hi, f_hi);
    if (f_lo == 0. || f_hi == 0. || std::abs(result.f) <= settings.f_tolerance)
      {
        result.converged = true;
        result.lo        = lo;
        result.hi        = hi;
        return result;
      }
    if ((f_lo > 0.) == (f_hi > 0.))
      {
        result.message = "the interval does not bracket a sign change";
        result.lo      = lo;
        result.hi      = hi;
        return result;
      }

    const double eps    = std::numeric_limits<double>::epsilon();
    const auto   narrow = [&](const double a, const double b) {
      return std::abs(b - a) <= std::max(settings.x_tolerance,
                                         4. * eps * std::max(std::abs(a), std::abs(b)));
    };
    const auto evaluate = [&](const double x) {
      if (result.evaluations >= settings.max_evaluations)
        throw OutOfEvaluations();
      ++result.evaluations;
      const double fx = f(x);
      if (std::isnan(fx))
        throw FailedEvaluation{x};
      note(x, fx);
      if (fx == 0. || std::abs(fx) <= settings.f_tolerance)
        throw SmallEnough();
      return fx;
    };

    while (true)
      {
        try
          {
            // Boost wants the bracket in increasing order.
            std::uintmax_t iterations = settings.max_evaluations;
            const bool     increasing = lo < hi;
            const auto     bracket    = boost::math::tools::toms748_solve(
              evaluate, increasing ? lo : hi, increasing ? hi : lo, increasing ? f_lo : f_hi,
              increasing ? f_hi : f_lo, narrow, iterations);
            result.converged = narrow(bracket.first, bracket.second);
            if (!result.converged)
              result.message = "the bracket did not shrink to the tolerance";
            break;
          }
        catch (const SmallEnough &)
          {
            result.converged = true;
            break;
          }
        catch (const OutOfEvaluations &)
          {
            result.message = "out of evaluations (" + std::to_string(settings.max_evaluations) + ")";
            break;
          }
        catch (const FailedEvaluation &failure)
          {
            result.failed_evaluation = true;
            if (settings.stop_on_failure)
              {
                result.message = "an evaluation failed";
                break;
              }
            // Shrink towards the side that can be evaluated and go on there.
            lo         = bracket_lo;
            f_lo       = f_bracket_lo;
            hi         = failure.x;
            bracket_hi = hi;
            if (narrow(lo, hi))
              {
                result.message = "evaluations fail arbitrarily close to the last good point";
                break;
              }
          }
      }
    result.lo = std::min(bracket_lo, bracket_hi);
    result.hi = std::max(bracket_lo, bracket_hi);
    return result;
  }
} // namespace cdea
