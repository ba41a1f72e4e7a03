#include <cdea/base/format.h>
#include <cdea/model/output_fields.h>
#include <cdea/numerics/bracketed_root.h>
#include <cdea/solver/time_stepper.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  }

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
    LoadState l;
    l.stage       = Stage::voltage;
    l.load_factor = t;
    l.time        = t;
    l.stretch     = scene.prestretch;
    l.mass        = scene.mass;
    l.force       = scene.dead_load();
    l.voltages    = voltages_at(t);
    return l;
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
    model.set_time_step(std::numeric_limits<double>::infinity(), settings.scheme);
    stepper.on_step = [&](const StepSummary &s) {
      if (s.stage == Stage::voltage)
        return;
      if (!relaxed && s.stage == Stage::prestretch && s.load_factor == 1.)
        {
          // The pre-stretched film has relaxed; the weight is hung quickly.
          model.relax_internal_variables();
          model.set_time_step(0., settings.scheme);
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
    model.set_time_step(0., settings.scheme);
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
        if (settings.water_density > 0.)
          {
            // The column above the frame plane, frozen over the step.
            const double height   = (settings.water_volume - m.V) / settings.tube_area;
            inertia.volume_mass   = settings.water_density * std::max(height, 0.) /
                                  settings.tube_area;
            inertia.volume_target = m.V + dt * m.V_dot + dt * dt * (0.5 - beta) * m.V_ddot;
          }
      }
    model.set_time_step(dt, settings.scheme);
    model.set_inertia(inertia);
    SolveReport report = model.solve(load_at(t + dt));
    ++result.solves;
    result.newton_iterations += report.iterations;
    if (!report.converged)
      return report;

    const double z = model.disk_position();
    const double V = settings.water_density > 0. ? model.enclosed_volume() : m.V;
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

  RunResult TimeStepper::run()
  {
    result = RunResult();
    if (!run_quasi_static())
      return result;

    postprocessors = standard_postprocessors(scene.prestretch, time_stage_stability(),
                                             quasi_static.breakdown_field > 0.);
    for (const auto &make : factories)
      postprocessors.push_back(make());
    auto columns = std::make_unique<TimeColumns>();
    time_columns = columns.get();
    postprocessors.push_back(std::move(columns));

    // Stroke and volume change count from the start of the time integration.
    const double t_start = std::isinf(settings.rest_time) ? 0. : -settings.rest_time;
    {
      StepContext reference(model, Stage::dead_load, 1.);
      StepSummary ignored;
      for (const auto &p : postprocessors)
        p->evaluate(reference, ignored);
    }
    motion   = InertiaState();
    motion.z = model.disk_position();
    motion.V = settings.water_density > 0. ? model.enclosed_volume() : 0.;

    // Energy budget since t_start.
    EnergyBudget budget = model.energy_budget();
    const double stored_start = budget.mechanical + budget.electrostatic;
    double       work = 0., dissipated = 0.;
    const auto   kinetic = [&](const InertiaState &m, const double volume_mass) {
      return settings.inertia ? 0.5 * scene.mass * m.v * m.v + 0.5 * volume_mass * m.V_dot * m.V_dot :
                                0.;
    };

    const auto set_columns = [&](const double t, const double volume_mass) {
      time_columns->time          = t;
      time_columns->velocity      = motion.v;
      time_columns->work          = work;
      time_columns->dissipated    = dissipated;
      time_columns->stored_change = budget.mechanical + budget.electrostatic +
                                    kinetic(motion, volume_mass) - stored_start;
    };
    t_now = t_start;
    set_columns(t_now, 0.);
    StepSummary previous = evaluate(t_now);
    wants_fields         = true;
    report(previous, 0);

    const double t_end            = settings.waveform.end_time();
    double       next_fields_time = settings.fields_interval > 0. ?
                                      settings.fields_interval *
                                        (std::floor(t_now / settings.fields_interval) + 1.) :
                                      std::numeric_limits<double>::infinity();
    double       dt    = settings.max_step;
    unsigned int cutbacks = 0;
    // The unknowns of the last two accepted steps, for the predictor.
    ModelState   older, oldest;
    double       dt_older = 0., dt_oldest = 0.;
    while (t_now < t_end * (1. - 1e-14) - 1e-14)
      {
        // Land on the next breakpoint, and never leave a sliver of a step
        // before it: with less than one and a half steps to go, take halves.
        const double breakpoint =
          std::min(t_now < 0. ? 0. : settings.waveform.next_breakpoint(t_now), t_end);
        const double to_go  = breakpoint - t_now;
        const double t_next = to_go <= dt * (1. + 1e-6) ? breakpoint :
                              to_go < 1.5 * dt          ? t_now + 0.5 * to_go :
                                                          t_now + dt;
        const double h          = t_next - t_now;
        if (!(h > 0.))
          {
            result.message = "time " + format_number(t_now, 12) +
                             " s: the time step is below the resolution of t";
            return result;
          }
        const ModelState   state0  = model.state();
        const InertiaState motion0 = motion;
        if (!oldest.unknowns.empty())
          {
            // Quadratic extrapolation through the last three states, at
            // times -dt_older - dt_oldest, -dt_older, 0, to h.
            const double t2 = -dt_older - dt_oldest, t1 = -dt_older;
            const double w2 = (h - t1) * h / ((t2 - t1) * t2);
            const double w1 = (h - t2) * h / ((t1 - t2) * t1);
            const double w0 = 1. - w1 - w2;
            ModelState guess = state0;
            for (std::size_t i = 0; i < guess.unknowns.size(); ++i)
              guess.unknowns[i] = w0 * state0.unknowns[i] + w1 * older.unknowns[i] +
                                  w2 * oldest.unknowns[i];
            model.set_state(guess);
          }
        else if (!older.unknowns.empty())
          model.predict(older, h / dt_older);
        SolveReport report1 = advance(t_now, h, motion);
        if (!report1.converged && !older.unknowns.empty())
          {
            model.set_state(state0);
            motion  = motion0;
            report1 = advance(t_now, h, motion);
          }
        if (!report1.converged)
          {
            model.set_state(state0);
            motion = motion0;
            dt     = 0.5 * h;
            if (++cutbacks > settings.max_cutbacks || dt < settings.min_step)
              {
                std::ostringstream m;
                m << "time " << format_number(t_now, 10) << " s (voltages "
                  << format_kV(voltages_at(t_now), 8) << "): no equilibrium found for the step to "
                  << format_number(t_next, 10) << " s after " << cutbacks
                  << " cut-backs of the time step: " << report1.message;
                result.message = m.str();
                return result;
              }
            continue;
          }

        // Accept the step: internal variables, energy budget.
        const double volume_mass =
          settings.inertia && settings.water_density > 0. ?
            settings.water_density *
              std::max((settings.water_volume - motion0.V) / settings.tube_area, 0.) /
              settings.tube_area :
            0.;
        const double step_dissipation = model.step_dissipation();
        model.accept_time_step();
        model.set_time_step(0., settings.scheme);
        model.set_inertia(InertiaStep());
        const EnergyBudget budget1 = model.energy_budget();
        const auto         phi0 = voltages_at(t_now), phi1 = voltages_at(t_next);
        for (unsigned int k = 0; k < budget1.charge.size(); ++k)
          work += 0.5 * (phi0[k] + phi1[k]) * (budget1.charge[k] - budget.charge[k]);
        dissipated += step_dissipation;
        budget = budget1;

        const ModelState   state1  = model.state();
        const InertiaState motion1 = motion;
        set_columns(t_next, volume_mass);
        StepSummary current = evaluate(t_next);

        // Loss of tension inside the step: its time by a bracketed root in
        // the fraction of the step, each trial a step from the start.
        if (!result.onset.found && previous.s2_min >= 0. && current.s2_min < 0.)
          {
            double     best_f = current.s2_min, best_theta = 1.;
            ModelState best_state = state1;
            InertiaState best_motion = motion1;
            const auto s2 = [&](const double theta) {
              model.set_state(state0);
              motion = motion0;
              if (!advance(t_now, theta * h, motion).converged)
                return nan;
              model.accept_time_step();
              model.set_time_step(0., settings.scheme);
              model.set_inertia(InertiaStep());
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
            find_bracketed_root(s2, 0., previous.s2_min, 1., current.s2_min, root);
            model.set_state(best_state);
            motion                 = best_motion;
            const double t_onset   = t_now + best_theta * h;
            time_columns->time     = t_onset;
            time_columns->velocity = motion.v;
            time_columns->work = time_columns->stored_change = time_columns->dissipated = nan;
            const StepSummary at_onset = evaluate(t_onset);
            result.onset = {true, voltages_at(t_onset),
                            scene.prestretch * at_onset.s2_min_radius, t_onset};
            if (on_onset)
              on_onset(result.onset);
            wants_fields = true;
            report(at_onset, 0);
            model.set_state(state1);
            motion = motion1;
            set_columns(t_next, volume_mass);
            current = evaluate(t_next);
          }

        oldest    = std::move(older);
        dt_oldest = dt_older;
        older     = state0;
        dt_older  = h;
        t_now    = t_next;
        wants_fields = t_now == breakpoint || t_now >= next_fields_time - 1e-9 * h;
        if (wants_fields && settings.fields_interval > 0.)
          next_fields_time = settings.fields_interval * (std::floor(t_now / settings.fields_interval + 1e-9) + 1.);
        report(current, report1.iterations);
        previous = current;
        cutbacks = 0;
        if (report1.iterations <= 4)
          dt = std::min(2. * h, settings.max_step);
        else
          dt = h;
      }
    result.completed = true;
    return result;
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
