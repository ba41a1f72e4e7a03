#include <cdea/solver/load_stepper.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace cdea
{
  std::string stage_name(const Stage stage)
  {
    switch (stage)
      {
        case Stage::prestretch:
          return "pre-stretch";
        case Stage::dead_load:
          return "dead load";
        case Stage::voltage:
          return "voltage";
      }
    return "unknown";
  }

  LoadStepper::LoadStepper(const Scene &scene, EquilibriumModel &model,
                           const SteppingSettings &settings)
    : scene(scene)
    , model(model)
    , settings(settings)
  {}

  LoadState LoadStepper::load(const Stage stage, const double t) const
  {
    LoadState l;
    l.stage       = stage;
    l.load_factor = t;
    l.voltages.assign(scene.n_rings(), 0.);
    switch (stage)
      {
        case Stage::prestretch:
          l.stretch = 1. + (scene.prestretch - 1.) * t;
          break;
        case Stage::dead_load:
          l.stretch = scene.prestretch;
          l.mass    = scene.mass * t;
          l.force   = scene.dead_load() * t;
          break;
        case Stage::voltage:
          l.stretch  = scene.prestretch;
          l.mass     = scene.mass;
          l.force    = scene.dead_load();
          l.voltages = scene.path.voltages(t);
          break;
      }
    return l;
  }

  // Largest increment of the stage parameter at t: the pre-stretch and load
  // stages step in fixed fractions, the voltage stage so that no ring voltage
  // changes by more than the voltage increment.
  double LoadStepper::step_limit(const Stage stage, const double t) const
  {
    switch (stage)
      {
        case Stage::prestretch:
          return 1. / settings.prestretch_steps;
        case Stage::dead_load:
          return settings.load_increment;
        case Stage::voltage:
          {
            const double rate = scene.path.max_rate(t);
            return rate > 0. ? settings.voltage_increment / rate : 1.;
          }
      }
    return 1.;
  }

  void LoadStepper::report(const StepSummary &s, const Stage stage, const double t,
                           const unsigned int iterations)
  {
    StepSummary summary       = s;
    summary.stage             = stage;
    summary.load_factor       = t;
    summary.newton_iterations = iterations;
    summary.wrinkled          = stage != Stage::prestretch && summary.s2_min < 0.;
    if (stage == Stage::dead_load && t == 1.)
      {
        reference_displacement = summary.displacement;
        have_reference         = true;
      }
    summary.stroke            = have_reference ? summary.displacement - reference_displacement
                                               : std::numeric_limits<double>::quiet_NaN();
    ++result.steps;
    if (on_step)
      on_step(summary);
  }

  bool LoadStepper::run_stage(const Stage stage, const double t_end)
  {
    double              t       = 0.;
    double              dt      = std::min(step_limit(stage, 0.), t_end);
    unsigned int        cutbacks = 0;
    std::vector<double> previous_state;
    double              previous_t = 0.;

    while (t < t_end * (1. - 1e-14))
      {
        // Land exactly on segment ends (waypoints) and on the stage end.
        const double segment_end = std::min(t_end, std::floor(t + 1e-12) + 1.);
        const double t_next      = std::min(t + dt, segment_end);
        const std::vector<double> state0 = model.state();
        const double              f0     = model.summary().s2_min;

        // Linear predictor from the last two converged states of this stage.
        if (settings.extrapolate && !previous_state.empty() && t > previous_t)
          model.predict(previous_state, (t_next - t) / (t - previous_t));
        const LoadState target = load(stage, t_next);
        SolveReport     solve  = model.solve(target);
        ++result.solves;
        result.newton_iterations += solve.iterations;
        if (!solve.converged && settings.extrapolate && !previous_state.empty())
          {
            // The predictor can overshoot near a limit point: retry from the
            // converged state before cutting the increment.
            model.set_state(state0);
            solve = model.solve(target);
            ++result.solves;
            result.newton_iterations += solve.iterations;
          }
        if (!solve.converged)
          {
            model.set_state(state0);
            dt *= 0.5;
            ++cutbacks;
            const double rate = stage == Stage::voltage ? scene.path.max_rate(t) : 0.;
            const bool   too_small =
              rate > 0. ? dt * rate < settings.min_voltage_increment : dt < 1e-8;
            if (too_small || cutbacks > settings.max_cutbacks)
              {
                std::ostringstream m;
                m << "stage '" << stage_name(stage) << "': no equilibrium found beyond load "
                  << "parameter t = " << t;
                if (stage == Stage::voltage)
                  {
                    m << " (voltages";
                    for (const double v : load(stage, t).voltages)
                      m << ' ' << v * 1e-3;
                    m << " kV)";
                  }
                m << " after " << cutbacks << " cut-backs of the increment; last attempt at t = "
                  << t_next << ": " << solve.message;
                if (stage == Stage::voltage)
                  m << ". This is typically a limit point (fold) of the voltage-displacement "
                       "curve, which load stepping cannot pass.";
                result.message = m.str();
                return false;
              }
            continue;
          }

        const StepSummary s = model.summary();
        if (stage != Stage::prestretch && !result.onset.found && f0 >= 0. && s.s2_min < 0.)
          {
            const std::vector<double> state1 = model.state();
            locate_onset(stage, t, state0, f0, t_next, s.s2_min);
            model.set_state(state1);
          }
        previous_state = state0;
        previous_t     = t;
        t              = t_next;
        report(model.summary(), stage, t, solve.iterations);
        cutbacks = 0;
        if (solve.iterations <= 4)
          dt = std::min(2. * dt, step_limit(stage, t));
      }
    return true;
  }

  bool LoadStepper::locate_onset(const Stage stage, double lo, const std::vector<double> &state0,
                                 double f_lo, double hi, double f_hi)
  {
    const double rate      = stage == Stage::voltage ? scene.path.max_rate(lo) : 0.;
    const double t_tol     = rate > 0. ? settings.onset_tolerance / rate : 1e-10;
    const double f_tol     = 1e-12 * scene.material.shear_modulus;
    std::vector<double> state_lo = state0;
    int          side      = 0;
    bool         found     = false;
    bool         at_last   = false; ///< the model holds the last converged evaluation
    StepSummary  at_root;
    unsigned int iterations = 0;
    double       t_root     = hi;
    for (unsigned int k = 0; k < 100 && hi - lo > t_tol; ++k)
      {
        double t = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if (!(t > lo && t < hi))
          t = 0.5 * (lo + hi);
        model.set_state(state_lo);
        const SolveReport solve = model.solve(load(stage, t));
        ++result.solves;
        result.newton_iterations += solve.iterations;
        at_last = solve.converged;
        if (!solve.converged)
          {
            // Shrink towards the converged side and try again.
            hi   = t;
            side = 0;
            continue;
          }
        const StepSummary s = model.summary();
        iterations          = solve.iterations;
        t_root              = t;
        at_root             = s;
        found               = true;
        if (std::abs(s.s2_min) < f_tol)
          break;
        if (s.s2_min > 0.)
          {
            lo       = t;
            f_lo     = s.s2_min;
            state_lo = model.state();
            if (side == -1)
              f_hi *= 0.5; // Illinois: halve the stale end
            side = -1;
          }
        else
          {
            hi   = t;
            f_hi = s.s2_min;
            if (side == 1)
              f_lo *= 0.5;
            side = 1;
          }
      }
    if (!found)
      return false;
    // Report the last converged evaluation (within the tolerance of the root).
    if (!at_last)
      {
        model.set_state(state_lo);
        model.solve(load(stage, t_root));
      }
    result.onset.found    = true;
    result.onset.voltages = load(stage, t_root).voltages;
    result.onset.radius   = scene.prestretch * at_root.s2_min_radius;
    if (on_onset)
      on_onset(result.onset);
    report(at_root, stage, t_root, iterations);
    return true;
  }

  RunResult LoadStepper::run()
  {
    result = RunResult();
    have_reference = false;
    model.set_reference_state();
    report(model.summary(), Stage::prestretch, 0., 0);
    if (!run_stage(Stage::prestretch, 1.))
      return result;
    if (!run_stage(Stage::dead_load, 1.))
      return result;
    if (!run_stage(Stage::voltage, scene.path.n_segments()))
      return result;
    result.completed = true;
    return result;
  }
} // namespace cdea
