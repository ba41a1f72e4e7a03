#pragma once
// The project's one bracketed scalar root finder: TOMS 748 (Alefeld, Potra and
// Shi 1995) from Boost.Math, behind a small interface shared by the material
// relaxation, the load stepper's crossing search, the arc-length limit-point
// search, the sweep's line search and the shooting solver; and, where the
// derivative is cheap (lambda1 at a shooting ring edge), a safeguarded Newton
// on the same bracket.
//
// Evaluations may fail (an equilibrium solve that does not converge, say):
// f then returns NaN. `lo` is taken to be the side that can be evaluated, so
// a failed evaluation at x shrinks the bracket to [lo, x], keeping the value
// known at hi as the estimate at x, and the search goes on there (or stops,
// with `stop_on_failure`).

#include <functional>
#include <string>

namespace cdea
{
  /// How a root search ended, for callers that act on the reason (the
  /// message is for people).
  enum class RootStatus
  {
    converged,
    no_sign_change,     ///< no sign change to close in on
    out_of_evaluations, ///< the evaluation budget ran out
    failed_evaluation,  ///< evaluations failed where the root should be
    not_converged       ///< the bracket did not shrink to the tolerance
  };

  struct BracketedRootSettings
  {
    double       x_tolerance     = 0.;  ///< stop when the bracket is narrower (absolute)
    double       f_tolerance     = 0.;  ///< stop when |f| <= this at an evaluation
    unsigned int max_evaluations = 100;
    bool         stop_on_failure = false; ///< a failed evaluation ends the search
  };

  struct BracketedRoot
  {
    bool         converged = false; ///< a tolerance was met
    RootStatus   status    = RootStatus::not_converged;
    bool         failed_evaluation = false; ///< some evaluation returned NaN
    double       x = 0.;  ///< best estimate: the evaluated point with the smallest |f|
    double       f = 0.;  ///< f there
    double       lo = 0., hi = 0.; ///< the final bracket
    unsigned int evaluations = 0;
    std::string  message; ///< why not converged (empty otherwise)
  };

  /// Root of @p f on [lo, hi], where f(lo) = f_lo and f(hi) = f_hi have
  /// opposite signs (or one is zero). Neither end is evaluated again.
  BracketedRoot find_bracketed_root(const std::function<double(double)> &f, double lo,
                                    double f_lo, double hi, double f_hi,
                                    const BracketedRootSettings &settings);

  /// The same with the derivative @p df, for a cheap derivative and a smooth
  /// f: Newton steps from the end with the smaller |f|, each replaced by
  /// bisection when it would leave the bracket or the derivative has the
  /// wrong sign; stops when a step or the bracket is at rounding level (or
  /// after max_evaluations steps). x is the last iterate, f is f(x). NaN
  /// values are not handled (stop_on_failure is implied).
  BracketedRoot find_bracketed_root_newton(const std::function<double(double)> &f,
                                           const std::function<double(double)> &df,
                                           double lo, double f_lo, double hi, double f_hi,
                                           const BracketedRootSettings &settings);
} // namespace cdea
