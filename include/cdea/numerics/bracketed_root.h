#pragma once
// The project's one bracketed scalar root finder: TOMS 748 (Alefeld, Potra and
// Shi 1995) from Boost.Math, behind a small interface shared by the material
// relaxation, the load stepper's crossing search, the arc-length limit-point
// search, the sweep's line search and the shooting solver.
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
} // namespace cdea
