// The error-controlled ESDIRK path of the time stepper (time_stepper.h):
// the step from its start state, the step-size factor from the error
// estimate, and the accepted or rejected step with the shared step
// controller. The fixed-step path is time_stepper.cc.
#include <cdea/base/format.h>
#include <cdea/model/output_fields.h>
#include <cdea/model/load_state.h>
#include <cdea/solver/time_stepper.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cdea
{
  // The ESDIRK step, the state it starts from and the weight of velocity
  // errors: the disk's angular frequency sqrt(k/m) at the start (1 rad/s
  // without inertia).
  void TimeStepper::start_esdirk()
  {
    EsdirkStepSettings e;
    e.tableau   = esdirk_tableau(settings.method);
    e.disk_mass = settings.inertia ? scene.mass : 0.;
    if (settings.inertia && settings.water_density > 0.)
      {
        e.water_mass_per_volume =
          settings.water_density / (settings.tube_area * settings.tube_area);
        e.water_volume = settings.water_volume;
        e.tube_area    = settings.tube_area;
      }
    e.relative_tolerance     = settings.relative_tolerance;
    e.displacement_tolerance = settings.displacement_tolerance;
    e.internal_tolerance     = settings.internal_tolerance;
    if (e.disk_mass > 0.)
      e.angular_frequency = std::sqrt(std::max(model.disk_stiffness(), 0.) / e.disk_mass);
    if (!(e.angular_frequency > 0.))
      e.angular_frequency = 1.;
    esdirk = std::make_unique<EsdirkStep>(
      model, e, [this](const double t, const double inside) { return load_on_piece(t, inside); },
      [this](const double t, const double inside) { return voltage_rates(t, inside); });
    point                  = TimePoint();
    point.t                = t_now;
    point.state            = model.state();
    point.motion           = motion;
    point.dissipation_rate = model.dissipation_rate();
    point.charges          = energy.last.charge;
    result.error_estimate  = 0.;
    last_ratio             = 1.;
    after_rejection        = false;
  }

  // The PI controller's factor for the next step after an accepted one
  // (Gustafsson's: 0.9 r_n^(-0.7/k) r_(n-1)^(0.4/k), k = embedded order + 1),
  // in [0.2, 5], at most 1 right after a rejection.
  double TimeStepper::next_step_factor(const double ratio)
  {
    const double k = esdirk_tableau(settings.method)->embedded_order + 1.;
    const double r = std::max(ratio, 1e-10);
    double       factor =
      0.9 * std::pow(r, -0.7 / k) * std::pow(std::max(last_ratio, 1e-10), 0.4 / k);
    factor = std::clamp(factor, 0.2, after_rejection ? 1. : 5.);
    last_ratio      = r;
    after_rejection = false;
    return factor;
  }

  bool TimeStepper::reject_esdirk_step(StepController &control, const double h,
                                       const SolveReport &solved)
  {
    model.set_state(point.state);
    motion = point.motion;
    ++result.rejected_steps;
    after_rejection = true;
    const bool error_control = settings.control == TimeStepControl::error;
    double     factor        = 0.25;
    if (solved.converged)
      factor = std::clamp(0.9 * std::pow(esdirk->error_ratio(),
                                         -1. / (esdirk_tableau(settings.method)->embedded_order + 1.)),
                          0.1, 0.9);
    if (error_control ? control.reject_with_factor(h, factor) : control.reject(h))
      return true;
    const double t_next = t_now + h;
    result.message = solved.converged ?
                       "time " + format_number(t_now, 10) +
                         " s: the error control cut the time step below Time/Min time step (s) (" +
                         to_string(control.reason()) + ")" :
                       no_equilibrium_message(t_next, control.cutbacks(), solved.message);
    return false;
  }

  // The accepted step: internal variables, energy budget, motion (without
  // inertia the velocities as differences), the error estimate's sum.
  void TimeStepper::accept_esdirk_step(const double h)
  {
    model.accept_time_step();
    model.set_time_step(0., TimeScheme::backward_euler);
    model.set_inertia(InertiaStep());
    const TimePoint start = point;
    point                 = esdirk->end();
    point.state           = model.state();
    if (!settings.inertia)
      {
        point.motion.v     = (point.motion.z - start.motion.z) / h;
        point.motion.V     = settings.water_density > 0. ? model.enclosed_volume() : 0.;
        point.motion.V_dot = (point.motion.V - start.motion.V) / h;
      }
    motion = point.motion;
    energy.work += esdirk->work();
    energy.dissipated += esdirk->dissipated();
    energy.last = model.energy_budget();
    result.error_estimate += std::abs(esdirk->displacement_error());
  }

  bool TimeStepper::take_esdirk_step(StepController &control, const double breakpoint,
                                     StepSummary &previous)
  {
    double t_next = 0., h = 0.;
    if (!next_step(control, breakpoint, t_next, h))
      return false;
    const SolveReport solved = esdirk->take(point, h);
    result.solves += esdirk->solves();
    result.newton_iterations += esdirk->iterations();
    const bool error_control = settings.control == TimeStepControl::error;
    if (!solved.converged || (error_control && !(esdirk->error_ratio() <= 1.)))
      return reject_esdirk_step(control, h, solved);

    StepEnds ends;
    ends.state0                 = point.state;
    ends.motion0                = point.motion;
    const TimePoint start       = point;
    accept_esdirk_step(h);
    const double volume_mass = settings.water_density > 0. ? esdirk->water_mass(motion.V) : 0.;
    const auto step_from_start = [&](const double theta) {
      model.set_state(start.state);
      if (!esdirk->take(start, theta * h).converged)
        return false;
      model.accept_time_step();
      model.set_time_step(0., TimeScheme::backward_euler);
      model.set_inertia(InertiaStep());
      motion = esdirk->end().motion;
      return true;
    };
    const unsigned int per_stage =
      (esdirk->iterations() + esdirk->solves() - 1) / std::max(esdirk->solves(), 1u);
    finish_step(ends, h, t_next, breakpoint, volume_mass, esdirk->iterations(), step_from_start,
                previous);
    if (error_control)
      control.accept_with_factor(h, next_step_factor(esdirk->error_ratio()));
    else
      control.accept(h, per_stage);
    return true;
  }
} // namespace cdea
