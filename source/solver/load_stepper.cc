#include <cdea/solver/arc_length.h>
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

  namespace
  {
    std::string kv(const std::vector<double> &volts)
    {
      std::ostringstream o;
      o.precision(8);
      for (std::size_t i = 0; i < volts.size(); ++i)
        o << (i ? ", " : "") << volts[i] * 1e-3;
      return o.str() + " kV";
    }
  } // namespace

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

  // The onset tolerance (volts) as an interval of the stage parameter.
  double LoadStepper::voltage_tolerance_in_t(const Stage stage, const double t) const
  {
    const double rate = stage == Stage::voltage ? scene.path.max_rate(t) : 0.;
    return rate > 0. ? settings.onset_tolerance / rate : 1e-10;
  }

  StepSummary LoadStepper::current_summary() const
  {
    StepSummary s = model.summary();
    if (settings.stability_check)
      s.min_eigenvalue = model.min_tangent_eigenvalue();
    if (settings.breakdown_field > 0.)
      {
        const StepFields f = model.fields();
        s.max_field        = 0.;
        for (std::size_t i = 0; i < f.E.size(); ++i)
          if (f.E[i] > s.max_field)
            {
              s.max_field        = f.E[i];
              s.max_field_radius = f.R[i];
            }
      }
    return s;
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
    summary.stroke = have_reference ? summary.displacement - reference_displacement
                                    : std::numeric_limits<double>::quiet_NaN();
    ++result.steps;
    if (on_step)
      on_step(summary);
  }

  double LoadStepper::locate_root(const Stage stage, double lo, std::vector<double> state_lo,
                                  double f_lo, double hi, double f_hi,
                                  const std::function<double(const StepSummary &)> &f,
                                  StepSummary &at_root, unsigned int &iterations)
  {
    const double t_tol  = voltage_tolerance_in_t(stage, lo);
    int          side   = 0;
    double       t_root = hi;
    bool         at_last = false; // the model holds the last converged evaluation
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
        const StepSummary s  = current_summary();
        const double      fs = f(s);
        iterations           = solve.iterations;
        t_root               = t;
        at_root              = s;
        if (fs == 0.)
          break;
        if (fs > 0.)
          {
            lo       = t;
            f_lo     = fs;
            state_lo = model.state();
            if (side == -1)
              f_hi *= 0.5; // Illinois: halve the stale end
            side = -1;
          }
        else
          {
            hi   = t;
            f_hi = fs;
            if (side == 1)
              f_lo *= 0.5;
            side = 1;
          }
      }
    if (!at_last)
      {
        model.set_state(state_lo);
        model.solve(load(stage, t_root));
        at_root = current_summary();
      }
    return t_root;
  }

  bool LoadStepper::check_crossings(const Stage stage, const double t0,
                                    const std::vector<double> &state0,
                                    const StepSummary &summary0, const double t1,
                                    const StepSummary &summary1)
  {
    const std::vector<double> state1 = model.state();

    if (stage != Stage::prestretch && !result.onset.found && summary0.s2_min >= 0. &&
        summary1.s2_min < 0.)
      {
        StepSummary  at_root;
        unsigned int iterations = 0;
        const double t =
          locate_root(stage, t0, state0, summary0.s2_min, t1, summary1.s2_min,
                      [](const StepSummary &s) { return s.s2_min; }, at_root, iterations);
        result.onset = {true, load(stage, t).voltages, scene.prestretch * at_root.s2_min_radius,
                        t};
        if (on_onset)
          on_onset(result.onset);
        report(at_root, stage, t, iterations);
        model.set_state(state1);
      }

    const double E_b = settings.breakdown_field;
    if (E_b > 0. && !result.breakdown.found && summary0.max_field < E_b &&
        summary1.max_field >= E_b)
      {
        StepSummary  at_root;
        unsigned int iterations = 0;
        const auto   margin     = [E_b](const StepSummary &s) { return E_b - s.max_field; };
        const double t = locate_root(stage, t0, state0, margin(summary0), t1, margin(summary1),
                                     margin, at_root, iterations);
        result.breakdown = {true, load(stage, t).voltages,
                            scene.prestretch * at_root.max_field_radius, t};
        if (on_breakdown)
          on_breakdown(result.breakdown);
        report(at_root, stage, t, iterations);
        model.set_state(state1);
      }
    // Then a state outside the model's validity: bisect for the boundary, report
    // it and end the run there.
    if (!summary1.validity_limit.empty())
      {
        double              lo = t0, hi = t1;
        std::vector<double> state_lo = state0;
        StepSummary         last_valid = summary0, first_invalid = summary1;
        const double        t_tol      = voltage_tolerance_in_t(stage, t0);
        while (hi - lo > t_tol)
          {
            const double t = 0.5 * (lo + hi);
            model.set_state(state_lo);
            const SolveReport solve = model.solve(load(stage, t));
            ++result.solves;
            result.newton_iterations += solve.iterations;
            const StepSummary s = solve.converged ? current_summary() : StepSummary();
            if (solve.converged && s.validity_limit.empty())
              {
                lo         = t;
                state_lo   = model.state();
                last_valid = s;
              }
            else
              {
                hi = t;
                if (solve.converged)
                  first_invalid = s;
              }
          }
        model.set_state(state_lo);
        if (lo > t0)
          report(last_valid, stage, lo, 0);
        std::ostringstream m;
        m << "stage '" << stage_name(stage) << "': the model's validity ends between "
          << kv(load(stage, lo).voltages) << " (last valid state, reported) and "
          << kv(load(stage, hi).voltages) << ": " << first_invalid.validity_limit;
        result.message = m.str();
        return false;
      }

    return true;
  }

  bool LoadStepper::run_stage(const Stage stage, const double t_end)
  {
    double              t        = 0.;
    double              dt       = std::min(step_limit(stage, 0.), t_end);
    unsigned int        cutbacks = 0;
    std::vector<double> previous_state;
    double              previous_t = 0.;
    StepSummary         summary0   = current_summary();

    while (t < t_end * (1. - 1e-14))
      {
        // Land exactly on segment ends (waypoints) and on the stage end.
        const double segment_end = std::min(t_end, std::floor(t + 1e-12) + 1.);
        const double t_next      = std::min(t + dt, segment_end);
        const std::vector<double> state0 = model.state();

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
                  m << " (voltages " << kv(load(stage, t).voltages) << ")";
                m << " after " << cutbacks << " cut-backs of the increment; last attempt at t = "
                  << t_next << ": " << solve.message;
                if (stage == Stage::voltage)
                  m << ". This is typically a limit point (fold) of the voltage-displacement "
                       "curve, which load stepping cannot pass (Solver/Continuation = arc "
                       "length can).";
                result.message = m.str();
                return false;
              }
            continue;
          }

        const StepSummary summary1 = current_summary();
        if (!check_crossings(stage, t, state0, summary0, t_next, summary1))
          return false;
        previous_state = state0;
        previous_t     = t;
        t              = t_next;
        summary0       = summary1;
        report(summary0, stage, t, solve.iterations);
        cutbacks = 0;
        if (solve.iterations <= 4)
          dt = std::min(2. * dt, step_limit(stage, t));
      }
    return true;
  }

  // The voltage stage by pseudo-arclength continuation in (unknowns, t). Ends
  // at the end of the path, when t falls below 0, after the maximum number of
  // steps, or beyond the displacement limit; result.end says which.
  bool LoadStepper::run_arc_length(const double t_end)
  {
    const Stage          stage = Stage::voltage;
    ContinuationProblem *problem =
      model.continuation([this](const double t) { return load(Stage::voltage, t); });
    if (!problem)
      {
        result.message = "this model offers no arc-length continuation (use load stepping)";
        return false;
      }
    ArcLengthSettings arc_settings;
    arc_settings.residual_tolerance = settings.residual_tolerance;
    arc_settings.update_tolerance   = settings.update_tolerance;
    ArcLength arc(*problem, arc_settings);

    ArcLength::Point p;
    p.x = problem->current();
    p.t = 0.;
    problem->set_current(p.x, p.t);
    arc.tangent(p);
    std::vector<double> state_p   = model.state();
    StepSummary         summary_p = current_summary();

    const double ds_max = step_limit(stage, 0.);
    const double ds_min = settings.min_voltage_increment /
                          std::max(scene.path.max_rate(0.), 1.);
    double       ds     = ds_max;
    for (unsigned int k = 0; k < settings.max_arc_length_steps; ++k)
      {
        ArcLength::Point q;
        std::string      why;
        if (!arc.step(p, ds, q, &why))
          {
            ds *= 0.5;
            if (ds < ds_min)
              {
                problem->set_current(p.x, p.t);
                result.message = "arc length: no equilibrium found beyond load parameter t = " +
                                 std::to_string(p.t) + " (voltages " +
                                 kv(load(stage, p.t).voltages) + "): " + why;
                return false;
              }
            continue;
          }

        // Past the end of the path (going forward): land on it exactly.
        if (q.t > t_end && q.t_dot > 0.)
          {
            model.set_state(state_p);
            const SolveReport solve = model.solve(load(stage, t_end));
            ++result.solves;
            result.newton_iterations += solve.iterations;
            if (!solve.converged)
              {
                ds *= 0.5;
                continue;
              }
            const StepSummary summary_end = current_summary();
            if (p.t_dot > 0. &&
                !check_crossings(stage, p.t, state_p, summary_p, t_end, summary_end))
              return false;
            report(summary_end, stage, t_end, solve.iterations);
            result.end = "reached the end of the voltage path";
            return true;
          }
        result.newton_iterations += q.iterations;
        ++result.solves;
        problem->set_current(q.x, q.t);

        const StepSummary summary_q = current_summary();
        // A limit point between p and q: t' changed sign.
        if ((q.t_dot > 0.) != (p.t_dot > 0.))
          {
            ArcLength::Point limit;
            if (arc.locate_limit_point(p, ds, q.t_dot, limit))
              {
                problem->set_current(limit.x, limit.t);
                const StepSummary s = current_summary();
                result.limit_points.push_back(
                  {limit.t, load(stage, limit.t).voltages, s.displacement});
                if (on_limit_point)
                  on_limit_point(result.limit_points.back());
                report(s, stage, limit.t, limit.iterations);
                problem->set_current(q.x, q.t);
              }
          }
        else if (!check_crossings(stage, p.t, state_p, summary_p, q.t, summary_q))
          return false;

        summary_p = summary_q;
        if (!summary_p.validity_limit.empty())
          {
            result.message = "arc length: " + summary_p.validity_limit;
            return false;
          }
        report(summary_p, stage, q.t, q.iterations);
        state_p = model.state();
        p       = q;
        if (q.t < 0.)
          {
            result.end = "the path parameter fell below 0 (voltages back to zero)";
            return true;
          }
        if (settings.max_displacement > 0. && summary_p.displacement > settings.max_displacement)
          {
            result.end = "the displacement passed Solver/Max displacement";
            return true;
          }
        if (q.iterations <= 4)
          ds = std::min(1.5 * ds, ds_max);
      }
    result.end = "Solver/Max arc-length steps reached";
    return true;
  }

  RunResult LoadStepper::run()
  {
    result         = RunResult();
    have_reference = false;
    model.set_reference_state();
    report(current_summary(), Stage::prestretch, 0., 0);
    if (!run_stage(Stage::prestretch, 1.))
      return result;
    if (!run_stage(Stage::dead_load, 1.))
      return result;
    const double t_end = scene.path.n_segments();
    if (settings.arc_length ? !run_arc_length(t_end) : !run_stage(Stage::voltage, t_end))
      return result;
    result.completed = true;
    return result;
  }
} // namespace cdea
