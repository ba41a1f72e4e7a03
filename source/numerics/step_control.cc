#include <cdea/numerics/step_control.h>

#include <algorithm>
#include <cmath>

namespace cdea
{
  std::string to_string(const StepStop reason)
  {
    switch (reason)
      {
        case StepStop::none:
          return "not stopped";
        case StepStop::below_min_step:
          return "the step fell below its minimum";
        case StepStop::too_many_cutbacks:
          return "too many cut-backs of the step";
      }
    return "unknown";
  }

  StepController::StepController(const StepControlSettings &settings, const double initial_step)
    : settings(settings)
    , step_(initial_step)
  {}

  void StepController::set_max_step(const double max_step) { settings.max_step = max_step; }

  void StepController::set_min_step(const double min_step, const double scale)
  {
    settings.min_step = min_step;
    min_step_scale    = scale;
  }

  double StepController::step_towards(const double remaining) const
  {
    return remaining <= step_ * (1. + 1e-6) ? remaining :
           remaining < 1.5 * step_          ? 0.5 * remaining :
                                              step_;
  }

  double StepController::base(const StepBase which, const double attempted) const
  {
    return which == StepBase::attempted ? attempted : step_;
  }

  StepStop StepController::stop_after(const double next_step, const unsigned int cutbacks) const
  {
    if (next_step * min_step_scale < settings.min_step)
      return StepStop::below_min_step;
    if (cutbacks > settings.max_cutbacks)
      return StepStop::too_many_cutbacks;
    return StepStop::none;
  }

  bool StepController::last_attempt(const double attempted) const
  {
    const double next = settings.cut_back * base(settings.after_reject, attempted);
    return stop_after(next, cutbacks_ + 1) != StepStop::none;
  }

  bool StepController::reject(const double attempted)
  {
    return reject_with_factor(attempted, settings.cut_back);
  }

  bool StepController::reject_with_factor(const double attempted, const double factor)
  {
    step_   = factor * base(settings.after_reject, attempted);
    reason_ = stop_after(step_, ++cutbacks_);
    return reason_ == StepStop::none;
  }

  void StepController::accept(const double attempted, const unsigned int iterations)
  {
    accept_with_factor(attempted, iterations <= settings.easy_iterations ? settings.growth : 1.);
  }

  void StepController::accept_with_factor(const double attempted, const double factor)
  {
    const double from = base(settings.after_accept, attempted);
    step_             = factor > 1. ? std::min(factor * from, settings.max_step) : factor * from;
    reason_           = StepStop::none;
    if (!settings.cutbacks_in_total)
      cutbacks_ = 0;
  }

  StepAcceptance::StepAcceptance(const unsigned int embedded_order, const bool error_control,
                                 const ErrorController controller)
    : k(embedded_order + 1.)
    , error_control_(error_control)
    , controller(controller)
  {}

  double StepAcceptance::rejected(const bool converged, const double ratio)
  {
    after_rejection = true;
    return converged ? std::clamp(0.9 * std::pow(ratio, -1. / k), 0.1, 0.9) : 0.25;
  }

  double StepAcceptance::accepted(const double ratio)
  {
    const double r      = std::max(ratio, 1e-10);
    const double factor = 0.9 * std::pow(r, -controller.alpha / k) *
                          std::pow(std::max(last_ratio, 1e-10), controller.beta / k);
    const double most   = controller.capped_after_rejection && after_rejection ? 1. : 5.;
    last_ratio          = r;
    after_rejection     = false;
    return std::clamp(factor, 0.2, most);
  }

  bool StepAcceptance::reject(StepController &control, const double attempted,
                              const bool converged, const double ratio)
  {
    const double factor = rejected(converged, ratio);
    return error_control_ ? control.reject_with_factor(attempted, factor) :
                            control.reject(attempted);
  }

  void StepAcceptance::accept(StepController &control, const double attempted,
                              const double ratio, const unsigned int iterations)
  {
    if (error_control_)
      control.accept_with_factor(attempted, accepted(ratio));
    else
      control.accept(attempted, iterations);
  }
} // namespace cdea
