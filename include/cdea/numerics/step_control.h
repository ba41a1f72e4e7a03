#pragma once
// The one step controller of every path followed in steps: the load stages
// and the arc length (solver/load_stepper), time (solver/time_stepper), the
// outer voltage of a design-map row (design/sweep_row) and the design
// variables between two layouts (design/layout_evaluator).
//
// It holds the step h to try next. A caller takes its attempt a from step()
// (shortened, if it likes, to land on a breakpoint; step_towards() does so
// without leaving a sliver before it), solves, and reports:
//   accept(a, iterations): an easy step (at most `easy_iterations` Newton
//     iterations) grows the step to min(growth b, max_step); otherwise the
//     step becomes b;
//   reject(a): the step is cut back to h = cut_back b, and the controller
//     gives up (false, with reason()) when h scale < min_step or after more
//     than `max_cutbacks` cut-backs;
// where b is the step proposed (h) or the one attempted (a), as the settings
// say for each case. accept_with_factor() and reject_with_factor() take the
// factor from the caller instead (from an error estimate, say), under the
// same cap, minimum and count of cut-backs.
//
// StepAcceptance is the other half for steps with an embedded error estimate
// (the ESDIRK steps of the time runs, the creep sensitivities and the
// periodic steady state): whether a step is accepted, and the factor of the
// next one from its error ratio r (the largest weighted error; accepted if
// r <= 1), with k the embedded order + 1:
//   rejected:  0.9 r^(-1/k) in [0.1, 0.9]; a failed solve 1/4;
//   accepted:  0.9 r_n^(-alpha/k) r_(n-1)^(beta/k) in [0.2, 5], at most 1
//              right after a rejection if the controller says so:
//              Gustafsson's PI controller (alpha 0.7, beta 0.4, capped after
//              a rejection) or the elementary one (alpha 1, beta 0).
// Without error control (fixed steps) only a failed solve rejects a step,
// and the StepController's own cut-back and growth size the next.

#include <limits>
#include <string>

namespace cdea
{
  /// Why a controller gave up.
  enum class StepStop
  {
    none,
    below_min_step,   ///< a cut-back left the step below its minimum
    too_many_cutbacks ///< more cut-backs than allowed
  };

  /// A short description of @p reason ("the step fell below its minimum").
  std::string to_string(StepStop reason);

  /// What the step after an attempt is computed from.
  enum class StepBase
  {
    proposed, ///< the controller's step, whatever the caller attempted
    attempted ///< the step the caller attempted (a landing may shorten it)
  };

  struct StepControlSettings
  {
    static constexpr unsigned int unlimited = std::numeric_limits<unsigned int>::max();

    /// Growth stops here; set_max_step() moves the cap along the path. A
    /// step is never lengthened to the cap, only limited by it when it grows.
    double       max_step = std::numeric_limits<double>::infinity();
    /// A cut-back below this gives up (0: never); see set_min_step().
    double       min_step = 0.;
    unsigned int max_cutbacks = unlimited;
    /// Count every cut-back on the path (true) or those since the last
    /// accepted step (false).
    bool         cutbacks_in_total = false;
    double       cut_back          = 0.5; ///< factor of a failed step
    double       growth            = 2.;  ///< factor after an easy step
    /// An accepted step is easy if its solve took at most this many
    /// iterations (unlimited: every accepted step grows the next).
    unsigned int easy_iterations   = 4;
    StepBase     after_reject      = StepBase::proposed;
    StepBase     after_accept      = StepBase::proposed;
  };

  class StepController
  {
  public:
    StepController(const StepControlSettings &settings, double initial_step);

    /// The step to try next.
    double step() const { return step_; }
    /// Cut-backs since the last accepted step (or in total, as set).
    unsigned int cutbacks() const { return cutbacks_; }
    /// Why the last reject() gave up (none if it did not).
    StepStop reason() const { return reason_; }
    /// The step towards a breakpoint @p remaining away, leaving no sliver of
    /// a step before it: all of it within one step (and a relative 1e-6),
    /// half of it within one and a half steps, else step(). Returns
    /// @p remaining itself when the step lands on the breakpoint.
    double step_towards(double remaining) const;

    void set_max_step(double max_step);
    /// Give up when a cut-back leaves h scale < @p min_step: @p scale converts
    /// the step into the quantity the minimum is given in (for a path
    /// parameter t, dV/dt turns the minimum into a voltage increment).
    void set_min_step(double min_step, double scale = 1.);

    /// Whether a failure of @p attempted would make the controller give up
    /// (a caller may try harder before it does).
    bool last_attempt(double attempted) const;

    /// The attempt @p attempted failed: cut back. False if the controller
    /// gives up (reason() says why).
    bool reject(double attempted);
    /// The same with the cut-back factor @p factor (< 1) from the caller.
    bool reject_with_factor(double attempted, double factor);

    /// The attempt @p attempted was reached in @p iterations iterations.
    void accept(double attempted, unsigned int iterations);
    /// The same with the factor of the next step from the caller (above 1:
    /// growth, capped at the maximum step).
    void accept_with_factor(double attempted, double factor);

  private:
    StepControlSettings settings;
    double              step_;
    double              min_step_scale = 1.;
    unsigned int        cutbacks_      = 0;
    StepStop            reason_        = StepStop::none;

    double   base(StepBase which, double attempted) const;
    StepStop stop_after(double next_step, unsigned int cutbacks) const;
  };

  /// The controller of the next step after an accepted one (see above).
  struct ErrorController
  {
    double alpha = 1.; ///< exponent of this step's ratio, over k
    double beta  = 0.; ///< exponent of the last step's ratio, over k
    bool   capped_after_rejection = false; ///< no growth right after a rejection

    /// Gustafsson's PI controller (the time runs).
    static ErrorController proportional_integral() { return {0.7, 0.4, true}; }
    /// 0.9 r^(-1/k) (the creep sensitivities and the periodic steady state).
    static ErrorController elementary() { return {1., 0., false}; }
  };

  class StepAcceptance
  {
  public:
    /// For an estimate of order @p embedded_order, with error control
    /// (@p error_control) or fixed steps.
    StepAcceptance(unsigned int embedded_order, bool error_control,
                   ErrorController controller);

    bool error_control() const { return error_control_; }
    /// Whether a step is accepted: its solve converged and, under error
    /// control, its error ratio @p ratio is at most 1.
    bool accepts(bool converged, double ratio) const
    {
      return converged && (!error_control_ || ratio <= 1.);
    }

    /// The factor of the next attempt after a rejected one.
    double rejected(bool converged, double ratio);
    /// The factor of the next step after an accepted one of error ratio @p ratio.
    double accepted(double ratio);

    /// The same through @p control for the attempt @p attempted: under error
    /// control with these factors, else by the controller's own rules (@p
    /// iterations of the solve). reject() is false if the controller gives up.
    bool reject(StepController &control, double attempted, bool converged, double ratio);
    void accept(StepController &control, double attempted, double ratio,
                unsigned int iterations);

  private:
    double          k;
    bool            error_control_;
    ErrorController controller;
    double          last_ratio      = 1.;
    bool            after_rejection = false;
  };
} // namespace cdea
