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

    /// One search by TOMS 748, which evaluates inside its current bracket
    /// only: the best point so far and the tightest bracket the evaluations
    /// show, and the search resumed on the side that can be evaluated after
    /// a failed evaluation.
    class Search
    {
    public:
      Search(const std::function<double(double)> &f, const double lo, const double f_lo,
             const double hi, const double f_hi, const BracketedRootSettings &settings)
        : f(f)
        , settings(settings)
        , lo(lo)
        , f_lo(f_lo)
        , hi(hi)
        , f_hi(f_hi)
        , lo_positive(f_lo > 0.)
        , bracket_lo(lo)
        , bracket_hi(hi)
        , f_bracket_lo(f_lo)
      {
        result.f = std::numeric_limits<double>::quiet_NaN();
        note(lo, f_lo);
        note(hi, f_hi);
      }

      BracketedRoot run()
      {
        if (settled_by_the_ends())
          return result;
        bool ended = false;
        while (!ended)
          ended = toms748();
        result.lo = std::min(bracket_lo, bracket_hi);
        result.hi = std::max(bracket_lo, bracket_hi);
        return result;
      }

    private:
      const std::function<double(double)> &f;
      const BracketedRootSettings         &settings;
      double                               lo, f_lo, hi, f_hi;
      const bool                           lo_positive;
      double                               bracket_lo, bracket_hi, f_bracket_lo;
      BracketedRoot                        result;

      void note(const double x, const double fx)
      {
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
      }

      /// A root at an end, or no sign change: the search ends before it starts.
      bool settled_by_the_ends()
      {
        result.lo = lo;
        result.hi = hi;
        if (f_lo == 0. || f_hi == 0. || std::abs(result.f) <= settings.f_tolerance)
          {
            result.converged = true;
            result.status    = RootStatus::converged;
            return true;
          }
        if ((f_lo > 0.) == (f_hi > 0.))
          {
            result.message = "the interval does not bracket a sign change";
            result.status  = RootStatus::no_sign_change;
            return true;
          }
        return false;
      }

      bool narrow(const double a, const double b) const
      {
        const double eps = std::numeric_limits<double>::epsilon();
        return std::abs(b - a) <=
               std::max(settings.x_tolerance, 4. * eps * std::max(std::abs(a), std::abs(b)));
      }

      double evaluate(const double x)
      {
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
      }

      /// One run of Boost's TOMS 748 on [lo, hi]; true when the search has
      /// ended, false to resume after a failed evaluation.
      bool toms748()
      {
        try
          {
            // Boost wants the bracket in increasing order.
            std::uintmax_t iterations = settings.max_evaluations;
            const bool     increasing = lo < hi;
            const auto     bracket    = boost::math::tools::toms748_solve(
              [this](const double x) { return evaluate(x); }, increasing ? lo : hi,
              increasing ? hi : lo, increasing ? f_lo : f_hi, increasing ? f_hi : f_lo,
              [this](const double a, const double b) { return narrow(a, b); }, iterations);
            result.converged = narrow(bracket.first, bracket.second);
            if (result.converged)
              result.status = RootStatus::converged;
            else
              result.message = "the bracket did not shrink to the tolerance";
          }
        catch (const SmallEnough &)
          {
            result.converged = true;
            result.status    = RootStatus::converged;
          }
        catch (const OutOfEvaluations &)
          {
            result.message = "out of evaluations (" + std::to_string(settings.max_evaluations) + ")";
            result.status  = RootStatus::out_of_evaluations;
          }
        catch (const FailedEvaluation &failure)
          {
            return retreat(failure.x);
          }
        return true;
      }

      /// After a failed evaluation at @p x: shrink towards the side that can
      /// be evaluated and go on there (false), or end the search (true).
      bool retreat(const double x)
      {
        result.failed_evaluation = true;
        if (settings.stop_on_failure)
          {
            result.message = "an evaluation failed";
            result.status  = RootStatus::failed_evaluation;
            return true;
          }
        lo         = bracket_lo;
        f_lo       = f_bracket_lo;
        hi         = x;
        bracket_hi = hi;
        if (!narrow(lo, hi))
          return false;
        result.message = "evaluations fail arbitrarily close to the last good point";
        result.status  = RootStatus::failed_evaluation;
        return true;
      }
    };
  } // namespace

  BracketedRoot find_bracketed_root(const std::function<double(double)> &f, const double lo,
                                    const double f_lo, const double hi, const double f_hi,
                                    const BracketedRootSettings &settings)
  {
    return Search(f, lo, f_lo, hi, f_hi, settings).run();
  }

  BracketedRoot find_bracketed_root_newton(const std::function<double(double)> &f,
                                           const std::function<double(double)> &df, double lo,
                                           double f_lo, double hi, double f_hi,
                                           const BracketedRootSettings &settings)
  {
    BracketedRoot result;
    if ((f_lo > 0.) == (f_hi > 0.) && f_lo != 0. && f_hi != 0.)
      {
        result.message = "the interval does not bracket a sign change";
        result.status  = RootStatus::no_sign_change;
        result.x       = std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
        result.f       = std::min(std::abs(f_lo), std::abs(f_hi));
        result.lo      = std::min(lo, hi);
        result.hi      = std::max(lo, hi);
        return result;
      }
    // Orient the bracket: f(a) <= 0 <= f(b), whichever way round a and b are.
    double       a = f_lo <= 0. ? lo : hi, b = f_lo <= 0. ? hi : lo;
    const bool   rising = a < b;
    const double eps    = std::numeric_limits<double>::epsilon();
    double       x      = std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
    if (f_lo == 0. || f_hi == 0.)
      a = b = x;
    bool done = a == b;
    for (unsigned int step = 0; step < settings.max_evaluations && !done; ++step)
      {
        const double fx = f(x);
        ++result.evaluations;
        if (fx == 0.)
          break;
        (fx < 0. ? a : b) = x;
        const double dfx        = df(x);
        double       next       = x - fx / dfx;
        const double inner      = std::min(a, b), outer = std::max(a, b);
        const bool   right_sign = rising ? dfx > 0. : dfx < 0.;
        if (!right_sign || !(next > inner) || !(next < outer))
          next = 0.5 * (a + b);
        done = std::abs(next - x) <= 4. * eps * std::abs(x) ||
               outer - inner <= 4. * eps * std::abs(x);
        x = next;
      }
    result.x = x;
    result.f = f(x);
    ++result.evaluations;
    result.lo = std::min(a, b);
    result.hi = std::max(a, b);
    const bool narrow = result.f == 0. || std::abs(result.f) <= settings.f_tolerance ||
                        result.hi - result.lo <= std::max(settings.x_tolerance,
                                                          4. * eps * std::abs(x)) ||
                        done;
    result.converged = narrow;
    result.status    = narrow ? RootStatus::converged : RootStatus::out_of_evaluations;
    if (!narrow)
      result.message = "out of evaluations (" + std::to_string(settings.max_evaluations) + ")";
    return result;
  }
} // namespace cdea
