// The error-controlled ESDIRK path of the time stepper (time_stepper.h):
// the step from its start state, accepted or rejected by its error estimate
// (StepAcceptance with Gustafsson's PI controller) through the shared step
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
  std::unique_ptr<EsdirkStep> make_esdirk_step(TransientModel &model, const Scene &scene,
                                               const TimeSettings &settings,
                                               const Waveform     &waveform)
  {
    EsdirkStepSettings e;
    e.tableau   = esdirk_tableau(settings.method);
    e.disk_mass = settings.inertia ? scene.mass : 0.;
    if (settings.inertia && settings.column.present())
      e.column = settings.column;
    e.relative_tolerance     = settings.relative_tolerance;
    e.displacement_tolerance = settings.displacement_tolerance;
    e.internal_tolerance     = settings.internal_tolerance;
    if (e.disk_mass > 0.)
      e.angular_frequency = std::sqrt(std::max(model.disk_stiffness(), 0.) / e.disk_mass);
    if (!(e.angular_frequency > 0.))
      e.angular_frequency = 1.;
    const std::vector<double> rest(scene.n_rings(), 0.);
    return std::make_unique<EsdirkStep>(
      model, e,
      [&scene, &waveform, rest](const double t, const double inside) {
        LoadState l =
          full_load(scene, inside < 0. ? rest : waveform.voltages_on_piece(t, inside), t);
        l.time = t;
        return l;
      },
      [&waveform, rest](const double t, const double inside) {
        return inside < 0. ? rest : waveform.rates_on_piece(t, inside);
      });
  }

  // The ESDIRK step and the state it starts from.
  void TimeStepper::start_esdirk()
  {
    esdirk                 = make_esdirk_step(model, scene, settings, settings.waveform);
    point                  = TimePoint();
    point.t                = t_now;
    point.state            = model.state();
    point.motion           = motion;
    point.dissipation_rate = model.dissipation_rate();
    point.charges          = energy.last.charge;
    result.error_estimate  = 0.;
    acceptance             = std::make_unique<StepAcceptance>(
      esdirk_tableau(settings.method)->embedded_order, settings.control == TimeStepControl::error,
      ErrorController::proportional_integral());
  }

  bool TimeStepper::reject_esdirk_step(StepController &control, const double h,
                                       const SolveReport &solved)
  {
    model.set_state(point.state);
    motion = point.motion;
    ++result.rejected_steps;
    if (acceptance->reject(control, h, solved.converged, esdirk->error_ratio()))
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
        point.motion.V     = settings.column.present() ? model.enclosed_volume() : 0.;
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
    if (!acceptance->accepts(solved.converged, esdirk->error_ratio()))
      return reject_esdirk_step(control, h, solved);

    StepEnds ends;
    ends.state0                 = point.state;
    ends.motion0                = point.motion;
    const TimePoint start       = point;
    accept_esdirk_step(h);
    const double volume_mass = settings.column.present() ? esdirk->column_mass(motion.V) : 0.;
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
    acceptance->accept(control, h, esdirk->error_ratio(), per_stage);
    return true;
  }
} // namespace cdea
