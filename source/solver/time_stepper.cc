#include <cdea/base/units.h>
#include <cdea/base/format.h>
#include <cdea/model/output_fields.h>
#include <cdea/numerics/bracketed_root.h>
#include <cdea/model/load_state.h>
#include <cdea/solver/time_stepper.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The dashpots' scheme of a fixed-step method (the ESDIRK stages are
    /// backward Euler steps from shifted starts).
    TimeScheme dashpot_scheme(const TimeMethod method)
    {
      return method == TimeMethod::trapezoidal ? TimeScheme::trapezoidal :
                                                 TimeScheme::backward_euler;
    }
  } // namespace

  /// Time, disk velocity and the energy budget since the start of the time
  /// integration: electrical work sum (Phi0 + Phi1)/2 (Q1 - Q0) in, change of
  /// the stored energy (elastic, weight, water, electrostatic, kinetic) and
  /// the material's dissipation. Values are set by the stepper before each
  /// evaluation (NaN: not part of a time step).
  class TimeStepper::TimeColumns final : public Postprocessor
  {
  public:
    double time = nan, velocity = nan, work = nan, stored_change = nan, dissipated = nan;

    void evaluate(StepContext &, StepSummary &summary) override
    {
      summary.columns.set(summary_column::waveform_time, time);
      summary.columns.set(summary_column::disk_velocity, velocity);
      summary.columns.set(summary_column::electrical_work, work);
      summary.columns.set(summary_column::stored_energy_change, stored_change);
      summary.columns.set(summary_column::dissipated_energy, dissipated);
    }
  };

  TimeStepper::TimeStepper(const Scene &scene, TransientModel &model,
                           const SteppingSettings &quasi_static, const TimeSettings &settings)
    : scene(scene)
    , model(model)
    , quasi_static(quasi_static)
    , settings(settings)
  {}

  void TimeStepper::add_postprocessor(const PostprocessorFactory &make)
  {
    factories.push_back(make);
  }

  bool TimeStepper::fields_wanted() const { return quasi_static_stepper || wants_fields; }

  const StepFields &TimeStepper::step_fields()
  {
    if (quasi_static_stepper)
      return quasi_static_stepper->step_fields();
    if (!reported_fields)
      reported_fields = std::make_shared<const StepFields>(model.fields());
    return *reported_fields;
  }

  std::vector<double> TimeStepper::voltages_at(const double t) const
  {
    return t < 0. ? std::vector<double>(scene.n_rings(), 0.) : settings.waveform.voltages(t);
  }

  LoadState TimeStepper::load_at(const double t) const
  {
    LoadState l = full_load(scene, voltages_at(t), t);
    l.time      = t;
    return l;
  }

  double TimeStepper::largest_step(const TimeSettings &settings)
  {
    const Waveform &w = settings.waveform;
    return esdirk_tableau(settings.method) && w.kind() == WaveformKind::sine ?
             std::min(settings.max_step, 1. / (16. * w.frequency())) :
             settings.max_step;
  }

  // Stages 0 and 1 by the quasi-static driver, on the scene with a zero
  // voltage path (its one zero-voltage step is not reported).
  bool TimeStepper::run_quasi_static()
  {
    Scene still = scene;
    still.path  = VoltagePath({std::vector<double>(scene.n_rings(), 0.)});
    LoadStepper stepper(still, model, quasi_static);
    for (const auto &make : factories)
      stepper.add_postprocessor(make());
    const bool relaxed = std::isinf(settings.rest_time);
    model.set_inertia(InertiaStep());
    model.set_time_step(std::numeric_limits<double>::infinity(), dashpot_scheme(settings.method));
    stepper.on_step = [&](const StepSummary &s) {
      if (s.stage == Stage::voltage)
        return;
      if (!relaxed && s.stage == Stage::prestretch && s.load_factor == 1.)
        {
          // The pre-stretched film has relaxed; the weight is hung quickly.
          model.relax_internal_variables();
          model.set_time_step(0., dashpot_scheme(settings.method));
        }
      ++result.steps;
      if (on_step)
        on_step(s);
    };
    stepper.on_onset = [&](const OnsetRecord &onset) {
      result.onset = onset;
      if (on_onset)
        on_onset(onset);
    };
    quasi_static_stepper  = &stepper;
    const RunResult stage = stepper.run();
    quasi_static_stepper  = nullptr;
    result.newton_iterations += stage.newton_iterations;
    result.solves += stage.solves;
    if (!stage.completed)
      {
        result.message = stage.message;
        return false;
      }
    // The internal variables (and their rates) of the state the time
    // integration starts from: relaxed, or held since the weight was hung.
    if (relaxed)
      model.relax_internal_variables();
    model.set_time_step(0., dashpot_scheme(settings.method));
    if (!model.solve(model.load()).converged)
      {
        result.message = "the state at the end of the dead-load stage is no equilibrium";
        return false;
      }
    model.accept_time_step();
    return true;
  }

  SolveReport TimeStepper::advance(const double t, const double dt, InertiaState &m)
  {
    const double beta = settings.newmark_beta, gamma = settings.newmark_gamma;
    InertiaStep  inertia;
    if (settings.inertia)
      {
        inertia.dt          = dt;
        inertia.beta        = beta;
        inertia.disk_mass   = scene.mass;
        inertia.disk_target = m.z + dt * m.v + dt * dt * (0.5 - beta) * m.a;
        if (settings.column.present())
          {
            inertia.volume_mass   = water_column_mass(m);
            inertia.volume_target = m.V + dt * m.V_dot + dt * dt * (0.5 - beta) * m.V_ddot;
          }
      }
    model.set_time_step(dt, dashpot_scheme(settings.method));
    model.set_inertia(inertia);
    SolveReport report = model.solve(load_at(t + dt));
    ++result.solves;
    result.newton_iterations += report.iterations;
    if (!report.converged)
      return report;

    const double z = model.disk_position();
    const double V = settings.column.present() ? model.enclosed_volume() : m.V;
    if (settings.inertia)
      {
        const double a = (z - inertia.disk_target) / (beta * dt * dt);
        m.v += dt * ((1. - gamma) * m.a + gamma * a);
        m.a = a;
        if (inertia.volume_mass > 0.)
          {
            const double V_ddot = (V - inertia.volume_target) / (beta * dt * dt);
            m.V_dot += dt * ((1. - gamma) * m.V_ddot + gamma * V_ddot);
            m.V_ddot = V_ddot;
          }
      }
    else
      {
        m.v     = (z - m.z) / dt;
        m.V_dot = (V - m.V) / dt;
      }
    m.z = z;
    m.V = V;
    return report;
  }

  StepSummary TimeStepper::evaluate(const double t)
  {
    StepContext context(model, Stage::voltage, t);
    StepSummary summary;
    for (const auto &p : postprocessors)
      p->evaluate(context, summary);
    reported_fields = context.computed_fields();
    return summary;
  }

  // The liquid column above the frame plane (as a mass on the enclosed
  // volume), frozen over a step that starts with @p m.
  double TimeStepper::water_column_mass(const InertiaState &m) const
  {
    return settings.column.present() ? settings.column.mass(m.V) : 0.;
  }

  double TimeStepper::kinetic_energy(const double volume_mass) const
  {
    return settings.inertia ? 0.5 * scene.mass * motion.v * motion.v +
                                0.5 * volume_mass * motion.V_dot * motion.V_dot :
                              0.;
  }

  void TimeStepper::set_columns(const double t, const double volume_mass)
  {
    time_columns->time          = t;
    time_columns->velocity      = motion.v;
    time_columns->work          = energy.work;
    time_columns->dissipated    = energy.dissipated;
    time_columns->stored_change = energy.last.mechanical + energy.last.electrostatic +
                                  kinetic_energy(volume_mass) - energy.stored_start;
  }

  // The postprocessors of the time stage, the state it starts from (its
  // stroke and volume, the motion, the energy budget) and its first report.
  StepSummary TimeStepper::start_time_stage()
  {
    PostprocessorSetup setup = postprocessor_setup(scene, quasi_static);
    setup.stability_check    = time_stage_stability();
    postprocessors           = make_postprocessors(on_every_path, setup);
    for (const auto &make : factories)
      postprocessors.push_back(make());
    auto columns = std::make_unique<TimeColumns>();
    time_columns = columns.get();
    postprocessors.push_back(std::move(columns));

    // Stroke and volume change count from the start of the time integration.
    {
      StepContext reference(model, Stage::dead_load, 1.);
      StepSummary ignored;
      for (const auto &p : postprocessors)
        p->evaluate(reference, ignored);
    }
    motion   = InertiaState();
    motion.z = model.disk_position();
    motion.V = settings.column.present() ? model.enclosed_volume() : 0.;

    energy              = EnergyAccount();
    energy.last         = model.energy_budget();
    energy.stored_start = energy.last.mechanical + energy.last.electrostatic;
    history             = History();

    t_now = std::isinf(settings.rest_time) ? 0. : -settings.rest_time;
    set_columns(t_now, 0.);
    StepSummary first = evaluate(t_now);
    wants_fields      = true;
    report(first, 0);
    next_fields_time = settings.fields_interval > 0. ?
                         settings.fields_interval *
                           (std::floor(t_now / settings.fields_interval) + 1.) :
                         std::numeric_limits<double>::infinity();
    return first;
  }

  // One implicit step of length h from state0: from the extrapolation of the
  // last accepted states, and once more from state0 if that fails.
  SolveReport TimeStepper::attempt_step(const ModelState &state0, const InertiaState &motion0,
                                        const double h)
  {
    if (!history.oldest.unknowns.empty())
      {
        // Quadratic extrapolation through the last three states, at
        // times -dt_older - dt_oldest, -dt_older, 0, to h.
        const double t2 = -history.dt_older - history.dt_oldest, t1 = -history.dt_older;
        const double w2 = (h - t1) * h / ((t2 - t1) * t2);
        const double w1 = (h - t2) * h / ((t1 - t2) * t1);
        const double w0 = 1. - w1 - w2;
        ModelState   guess = state0;
        for (std::size_t i = 0; i < guess.unknowns.size(); ++i)
          guess.unknowns[i] = w0 * state0.unknowns[i] + w1 * history.older.unknowns[i] +
                              w2 * history.oldest.unknowns[i];
        model.set_state(guess);
      }
    else if (!history.older.unknowns.empty())
      model.predict(history.older, h / history.dt_older);
    SolveReport report = advance(t_now, h, motion);
    if (!report.converged && !history.older.unknowns.empty())
      {
        model.set_state(state0);
        motion = motion0;
        report = advance(t_now, h, motion);
      }
    return report;
  }

  // A converged step to t_next: its internal variables accepted, and its
  // electrical work and dissipation added to the energy budget.
  void TimeStepper::accept_step(const double t_next)
  {
    const double step_dissipation = model.step_dissipation();
    model.accept_time_step();
    model.set_time_step(0., dashpot_scheme(settings.method));
    model.set_inertia(InertiaStep());
    const EnergyBudget budget1 = model.energy_budget();
    const auto         phi0 = voltages_at(t_now), phi1 = voltages_at(t_next);
    for (unsigned int k = 0; k < budget1.charge.size(); ++k)
      energy.work += 0.5 * (phi0[k] + phi1[k]) * (budget1.charge[k] - energy.last.charge[k]);
    energy.dissipated += step_dissipation;
    energy.last = budget1;
  }

  // Loss of tension inside the step of length h from ends.state0 (where s2_min
  // is s2_start >= 0) to ends.state1 (s2_end < 0): its time by a bracketed
  // root in the fraction of the step, each trial a step from the start,
  // reported as a step of its own. Leaves the model at the best trial.
  void TimeStepper::locate_onset(const StepEnds &ends, const double h, const double s2_start,
                                 const double s2_end,
                                 const std::function<bool(double)> &step_from_start)
  {
    double       best_f = s2_end, best_theta = 1.;
    ModelState   best_state  = ends.state1;
    InertiaState best_motion = ends.motion1;
    const auto   s2          = [&](const double theta) {
      if (!step_from_start(theta))
        return nan;
      const double f = model.hoop_stresses().s2_min;
      if (std::abs(f) < std::abs(best_f))
        {
          best_f      = f;
          best_theta  = theta;
          best_state  = model.state();
          best_motion = motion;
        }
      return f;
    };
    BracketedRootSettings root;
    root.x_tolerance = 1e-9 * settings.max_step / h;
    find_bracketed_root(s2, 0., s2_start, 1., s2_end, root);
    model.set_state(best_state);
    motion                 = best_motion;
    const double t_onset   = t_now + best_theta * h;
    time_columns->time     = t_onset;
    time_columns->velocity = motion.v;
    time_columns->work = time_columns->stored_change = time_columns->dissipated = nan;
    const StepSummary at_onset = evaluate(t_onset);
    result.onset =
      {true, voltages_at(t_onset), scene.prestretch * at_onset.s2_min_radius, t_onset};
    if (on_onset)
      on_onset(result.onset);
    wants_fields = true;
    report(at_onset, 0);
  }

  std::string TimeStepper::no_equilibrium_message(const double t_next,
                                                  const unsigned int cutbacks,
                                                  const std::string &why) const
  {
    std::ostringstream m;
    m << "time " << format_number(t_now, 10) << " s (voltages "
      << format_kV(voltages_at(t_now), 8) << "): no equilibrium found for the step to "
      << format_number(t_next, 10) << " s after " << cutbacks
      << " cut-backs of the time step: " << why;
    return m.str();
  }

  // The next step's end @p t_next (the breakpoint itself when the
  // controller reaches it, so no round-off step is left) and length @p h;
  // false with the message when h is below the resolution of t.
  bool TimeStepper::next_step(StepController &control, const double breakpoint, double &t_next,
                              double &h)
  {
    const double to_go = breakpoint - t_now;
    const double step  = control.step_towards(to_go);
    t_next             = step == to_go ? breakpoint : t_now + step;
    h                  = t_next - t_now;
    if (h > 0.)
      return true;
    result.message =
      "time " + format_number(t_now, 12) + " s: the time step is below the resolution of t";
    return false;
  }

  // One step from t_now towards @p breakpoint, accepted (true, the model and
  // t_now at its end) or cut back (true, nothing changed); false if the run
  // ends here (the message in the result).
  bool TimeStepper::take_step(StepController &control, const double breakpoint,
                              StepSummary &previous)
  {
    double t_next = 0., h = 0.;
    if (!next_step(control, breakpoint, t_next, h))
      return false;
    StepEnds ends;
    ends.state0             = model.state();
    ends.motion0            = motion;
    const SolveReport solved = attempt_step(ends.state0, ends.motion0, h);
    if (!solved.converged)
      {
        model.set_state(ends.state0);
        motion = ends.motion0;
        if (control.reject(h))
          return true;
        result.message = no_equilibrium_message(t_next, control.cutbacks(), solved.message);
        return false;
      }

    const double volume_mass = settings.inertia ? water_column_mass(ends.motion0) : 0.;
    accept_step(t_next);
    const auto step_from_start = [&](const double theta) {
      model.set_state(ends.state0);
      motion = ends.motion0;
      if (!advance(t_now, theta * h, motion).converged)
        return false;
      model.accept_time_step();
      model.set_time_step(0., dashpot_scheme(settings.method));
      model.set_inertia(InertiaStep());
      return true;
    };
    history.oldest    = std::move(history.older);
    history.dt_oldest = history.dt_older;
    history.older     = ends.state0;
    history.dt_older  = h;
    finish_step(ends, h, t_next, breakpoint, volume_mass, solved.iterations, step_from_start,
                previous);
    control.accept(h, solved.iterations);
    return true;
  }

  // The accepted step's end: its row (after the onset's, if the hoop stress
  // turned negative inside it), the fields wanted, t_now moved on.
  void TimeStepper::finish_step(StepEnds &ends, const double h, const double t_next,
                                const double breakpoint, const double volume_mass,
                                const unsigned int                 iterations,
                                const std::function<bool(double)> &step_from_start,
                                StepSummary                       &previous)
  {
    ends.state1  = model.state();
    ends.motion1 = motion;
    set_columns(t_next, volume_mass);
    StepSummary current = evaluate(t_next);
    if (!result.onset.found && previous.s2_min >= 0. && current.s2_min < 0.)
      {
        locate_onset(ends, h, previous.s2_min, current.s2_min, step_from_start);
        model.set_state(ends.state1);
        motion = ends.motion1;
        set_columns(t_next, volume_mass);
        current = evaluate(t_next);
      }
    for (const double v : voltages_at(t_next))
      largest_voltage = std::max(largest_voltage, std::abs(v));
    ++result.time_steps;
    t_now        = t_next;
    wants_fields = t_now == breakpoint || t_now >= next_fields_time - 1e-9 * h;
    if (wants_fields && settings.fields_interval > 0.)
      next_fields_time = settings.fields_interval *
                         (std::floor(t_now / settings.fields_interval + 1e-9) + 1.);
    report(current, iterations);
    previous = current;
  }

  // Steps of at most Time/Max step, cut back to half the step that failed
  // and doubled from the step taken after an easy one.
  StepControlSettings TimeStepper::step_control() const
  {
    StepControlSettings s;
    s.max_step     = largest_step(settings);
    s.min_step     = settings.min_step;
    s.max_cutbacks = settings.max_cutbacks;
    s.after_reject = StepBase::attempted;
    s.after_accept = StepBase::attempted;
    return s;
  }

  // Fixed steps start at the largest step; the error control a tenth of it,
  // growing by at most five per step.
  double TimeStepper::initial_step() const
  {
    return esdirk && settings.control == TimeStepControl::error ? 0.1 * largest_step(settings) :
                                                                    largest_step(settings);
  }

  RunResult TimeStepper::run()
  {
    result = RunResult();
    if (!run_quasi_static())
      return result;
    StepSummary previous = start_time_stage();
    if (esdirk_tableau(settings.method))
      start_esdirk();
    const double   t_end = settings.waveform.end_time();
    StepController control(step_control(), initial_step());
    while (t_now < t_end * (1. - 1e-14) - 1e-14)
      {
        // Land on the next breakpoint of the waveform.
        const double breakpoint =
          std::min(t_now < 0. ? 0. : settings.waveform.next_breakpoint(t_now), t_end);
        if (!(esdirk ? take_esdirk_step(control, breakpoint, previous) :
                       take_step(control, breakpoint, previous)))
          {
            finish_run();
            return result;
          }
      }
    result.completed = true;
    finish_run();
    return result;
  }

  // An ESDIRK run whose voltages stayed at zero in every step (steps too
  // coarse for the drive, say) is worth a warning: the run would look complete.
  void TimeStepper::finish_run()
  {
    double peak = 0.;
    for (const double v : settings.waveform.peak())
      peak = std::max(peak, std::abs(v));
    if (esdirk && peak > 0. && result.completed && largest_voltage < 1e-3 * peak)
      result.warning = "the drive never rose: the largest ring voltage in any time step was " +
                       format_number(units::kV.from_si(largest_voltage), 4) + " kV of the waveform's peak " +
                       format_number(units::kV.from_si(peak), 4) + " kV";
  }

  void TimeStepper::report(const StepSummary &state, const unsigned int iterations)
  {
    // @p state is the last evaluate(), whose fields are reported_fields.
    StepSummary summary       = state;
    summary.newton_iterations = iterations;
    ++result.steps;
    if (on_step)
      on_step(summary);
    reported_fields.reset();
    wants_fields = false;
  }
} // namespace cdea
