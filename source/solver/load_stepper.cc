#include <cdea/base/format.h>
#include <cdea/numerics/bracketed_root.h>
#include <cdea/numerics/arc_length.h>
#include <cdea/model/load_state.h>
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

  PostprocessorSetup postprocessor_setup(const Scene &scene, const SteppingSettings &settings)
  {
    PostprocessorSetup setup;
    setup.prestretch      = scene.prestretch;
    setup.frame_radius    = scene.frame_radius;
    setup.stability_check = settings.stability_check;
    setup.eigenvalue      = settings.stability_eigenvalue;
    setup.field_check     = settings.breakdown_field > 0.;
    return setup;
  }

  LoadStepper::LoadStepper(const Scene &scene, EquilibriumModel &model,
                           const SteppingSettings &settings)
    : scene(scene)
    , model(model)
    , settings(settings)
    , postprocessors(make_postprocessors(on_every_path, postprocessor_setup(scene, settings)))
  {
    crossings.push_back({[](const StepSummary &s) { return s.s2_min; },
                         [](const StepSummary &s) { return s.s2_min_radius; }, &result.onset,
                         &on_onset});
    if (settings.breakdown_field > 0.)
      {
        const double E_b = settings.breakdown_field;
        crossings.push_back({[E_b](const StepSummary &s) { return E_b - s.max_field; },
                             [](const StepSummary &s) { return s.max_field_radius; },
                             &result.breakdown, &on_breakdown});
      }
  }

  void LoadStepper::add_postprocessor(std::unique_ptr<Postprocessor> postprocessor)
  {
    postprocessors.push_back(std::move(postprocessor));
  }

  LoadState LoadStepper::load(const Stage stage, const double t) const
  {
    if (stage == Stage::voltage)
      return full_load(scene, scene.path.voltages(t), t);
    LoadState l;
    l.stage       = stage;
    l.load_factor = t;
    l.voltages.assign(scene.n_rings(), 0.);
    if (stage == Stage::prestretch)
      l.stretch = 1. + (scene.prestretch - 1.) * t;
    else
      {
        l.stretch = scene.prestretch;
        l.mass    = scene.mass * t;
        l.force   = scene.dead_load() * t;
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

  SolveReport LoadStepper::solve(const LoadState &target)
  {
    const SolveReport report = model.solve(target);
    ++result.solves;
    result.newton_iterations += report.iterations;
    return report;
  }

  LoadStepper::Evaluated LoadStepper::evaluate(const Stage stage, const double t)
  {
    StepContext context(model, stage, t);
    Evaluated   e;
    for (const auto &p : postprocessors)
      p->evaluate(context, e.summary);
    e.fields = context.computed_fields();
    return e;
  }

  void LoadStepper::report(const Evaluated &state, const unsigned int iterations)
  {
    StepSummary summary       = state.summary;
    summary.newton_iterations = iterations;
    reported_fields           = state.fields;
    ++result.steps;
    if (on_step)
      on_step(summary);
    reported_fields.reset();
  }

  const StepFields &LoadStepper::step_fields()
  {
    if (!reported_fields)
      reported_fields = std::make_shared<const StepFields>(model.fields());
    return *reported_fields;
  }

  double LoadStepper::locate_root(const Stage stage, const double t0, const ModelState &state0,
                                  const double f0, const double t1, const double f1,
                                  const std::function<double(const StepSummary &)> &f,
                                  Evaluated &at_root, unsigned int &iterations)
  {
    // Every evaluation starts from the converged state on the f >= 0 side
    // nearest to the root (t1 may lie below t0 on a branch followed backwards
    // by arc length); the evaluation with the smallest |f| is reported.
    ModelState   start  = state0;
    double       t_start = t0;
    double       best_t = t1, best_f = std::numeric_limits<double>::infinity();
    ModelState   best_state;
    const auto   margin = [&](const double t) {
      model.set_state(start);
      const SolveReport s = solve(load(stage, t));
      if (!s.converged)
        return std::numeric_limits<double>::quiet_NaN();
      const Evaluated e  = evaluate(stage, t);
      const double    ft = f(e.summary);
      if (std::abs(ft) < std::abs(best_f))
        {
          best_t     = t;
          best_f     = ft;
          best_state = model.state();
          at_root    = e;
          iterations = s.iterations;
        }
      if (ft >= 0. && std::abs(t - t0) > std::abs(t_start - t0))
        {
          start   = model.state();
          t_start = t;
        }
      return ft;
    };
    BracketedRootSettings root_settings;
    root_settings.x_tolerance = voltage_tolerance_in_t(stage, t0);
    find_bracketed_root(margin, t0, f0, t1, f1, root_settings);
    if (best_state.unknowns.empty())
      {
        // No evaluation converged: the far end is the estimate.
        model.set_state(start);
        solve(load(stage, best_t));
        at_root = evaluate(stage, best_t);
        return best_t;
      }
    model.set_state(best_state);
    return best_t;
  }

  bool LoadStepper::check_crossings(const Stage stage, const double t0, const ModelState &state0,
                                    const Evaluated &e0, const double t1, const Evaluated &e1)
  {
    const ModelState state1 = model.state();
    for (const Crossing &c : crossings)
      {
        const double m0 = c.margin(e0.summary), m1 = c.margin(e1.summary);
        if (stage == Stage::prestretch || c.record->found || !(m0 >= 0.) || !(m1 < 0.))
          continue;
        Evaluated    at_root;
        unsigned int iterations = 0;
        const double t = locate_root(stage, t0, state0, m0, t1, m1, c.margin, at_root, iterations);
        *c.record      = {true, load(stage, t).voltages, scene.prestretch * c.radius(at_root.summary),
                          t};
        if (*c.callback)
          (*c.callback)(*c.record);
        report(at_root, iterations);
        model.set_state(state1);
      }

    // Then a state outside the model's validity: bisect for the boundary, report
    // it and end the run there.
    if (!e1.summary.validity_limit.empty())
      {
        double       lo = t0, hi = t1;
        ModelState   state_lo   = state0;
        Evaluated    last_valid = e0;
        std::string  why        = e1.summary.validity_limit;
        const double t_tol      = voltage_tolerance_in_t(stage, t0);
        while (hi - lo > t_tol)
          {
            const double t = 0.5 * (lo + hi);
            model.set_state(state_lo);
            const SolveReport s = solve(load(stage, t));
            const Evaluated   e = s.converged ? evaluate(stage, t) : Evaluated();
            if (s.converged && e.summary.validity_limit.empty())
              {
                lo         = t;
                state_lo   = model.state();
                last_valid = e;
              }
            else
              {
                hi = t;
                if (s.converged)
                  why = e.summary.validity_limit;
              }
          }
        model.set_state(state_lo);
        if (lo > t0)
          report(last_valid, 0);
        result.message = "stage '" + stage_name(stage) + "': the model's validity ends between " +
                         format_kV(load(stage, lo).voltages, 8) +
                         " (last valid state, reported) and " +
                         format_kV(load(stage, hi).voltages, 8) + ": " + why;
        return false;
      }
    return true;
  }

  namespace
  {
    /// Why a stage ended at t: the step cannot change t any more.
    std::string unresolved_step_message(const Stage stage, const double t)
    {
      return "stage '" + stage_name(stage) + "': the load parameter cannot advance beyond t = " +
             format_number(t, 17) +
             " (the step is below the resolution of t; is the voltage path too steep or are "
             "two waypoints too close?)";
    }
  } // namespace

  StepController LoadStepper::stage_controller(const Stage stage, const double t_end) const
  {
    StepControlSettings s;
    s.max_step     = step_limit(stage, 0.);
    s.max_cutbacks = settings.max_cutbacks;
    return StepController(s, std::min(step_limit(stage, 0.), t_end));
  }

  // The smallest increment at t: Solver/Min voltage increment (V) where the
  // voltages change, 1e-8 of the stage parameter elsewhere.
  void LoadStepper::set_min_increment(StepController &control, const Stage stage,
                                      const double t) const
  {
    const double rate = stage == Stage::voltage ? scene.path.max_rate(t) : 0.;
    if (rate > 0.)
      control.set_min_step(settings.min_voltage_increment, rate);
    else
      control.set_min_step(1e-8);
  }

  SolveReport LoadStepper::solve_step(const Stage stage, const double t, const double t_next,
                                      const ModelState &state0, const ModelState &previous_state,
                                      const double previous_t)
  {
    // Linear predictor from the last two converged states of this stage.
    const bool extrapolated = settings.extrapolate && !previous_state.unknowns.empty();
    if (extrapolated && t > previous_t)
      model.predict(previous_state, (t_next - t) / (t - previous_t));
    const LoadState target = load(stage, t_next);
    SolveReport     report = solve(target);
    if (!report.converged && extrapolated)
      {
        // The predictor can overshoot near a limit point: retry from the
        // converged state before cutting the increment.
        model.set_state(state0);
        report = solve(target);
      }
    return report;
  }

  std::string LoadStepper::no_equilibrium_message(const Stage stage, const double t,
                                                  const double t_next, const unsigned int cutbacks,
                                                  const std::string &why) const
  {
    std::ostringstream m;
    m << "stage '" << stage_name(stage) << "': no equilibrium found beyond load "
      << "parameter t = " << t;
    if (stage == Stage::voltage)
      m << " (voltages " << format_kV(load(stage, t).voltages, 8) << ")";
    m << " after " << cutbacks << " cut-backs of the increment; last attempt at t = " << t_next
      << ": " << why;
    if (stage == Stage::voltage)
      m << ". This is typically a limit point (fold) of the voltage-displacement "
           "curve, which load stepping cannot pass (Solver/Continuation = arc "
           "length can).";
    return m.str();
  }

  bool LoadStepper::run_stage(const Stage stage, const double t_end)
  {
    StepController control = stage_controller(stage, t_end);
    double         t       = 0.;
    ModelState     previous_state;
    double         previous_t = 0.;
    Evaluated      e0         = evaluate(stage, 0.);

    while (t < t_end * (1. - 1e-14))
      {
        // Land exactly on segment ends (waypoints) and on the stage end.
        const double segment_end = std::min(t_end, std::floor(t + 1e-12) + 1.);
        const double t_next      = std::min(t + control.step(), segment_end);
        if (!(t_next > t))
          {
            result.message = unresolved_step_message(stage, t);
            return false;
          }
        const ModelState  state0 = model.state();
        const SolveReport solved =
          solve_step(stage, t, t_next, state0, previous_state, previous_t);
        if (!solved.converged)
          {
            model.set_state(state0);
            set_min_increment(control, stage, t);
            if (control.reject(t_next - t))
              continue;
            result.message =
              no_equilibrium_message(stage, t, t_next, control.cutbacks(), solved.message);
            return false;
          }

        const Evaluated e1 = evaluate(stage, t_next);
        if (!check_crossings(stage, t, state0, e0, t_next, e1))
          return false;
        previous_state = state0;
        previous_t     = t;
        t              = t_next;
        e0             = e1;
        report(e0, solved.iterations);
        control.set_max_step(step_limit(stage, t));
        control.accept(t - previous_t, solved.iterations);
      }
    return true;
  }

  /// The voltage stage followed by arc length: the continuation, its last
  /// converged point p with the model's state and the evaluation there, and
  /// the point q of the step being taken.
  struct LoadStepper::ArcPath
  {
    ContinuationProblem &problem;
    ArcLength            arc;
    ArcLength::Point     p, q;
    ModelState           state_p;
    Evaluated            e_p;
  };

  bool LoadStepper::stop_arc_length(const ArcPath &path, const std::string &why)
  {
    result.end     = why;
    result.message = "arc length: " + why + " at t = " + format_number(path.p.t, 8) +
                     " (voltages " + format_kV(load(Stage::voltage, path.p.t).voltages, 8) + ")";
    return false;
  }

  // The step from p went past the end of the path (forward): solve at the
  // end from p instead. Complete if that converges (after the crossings up
  // to the end), incomplete if a crossing ended the run, open if the solve
  // failed (a shorter step may reach the end).
  LoadStepper::PathEnd LoadStepper::land_on_path_end(ArcPath &path, const double t_end)
  {
    const Stage stage = Stage::voltage;
    model.set_state(path.state_p);
    const SolveReport s = solve(load(stage, t_end));
    if (!s.converged)
      return PathEnd::open;
    const Evaluated e_end = evaluate(stage, t_end);
    if (path.p.t_dot > 0. &&
        !check_crossings(stage, path.p.t, path.state_p, path.e_p, t_end, e_end))
      return PathEnd::incomplete;
    report(e_end, s.iterations);
    result.end = "reached the end of the voltage path";
    return PathEnd::complete;
  }

  // t' changed sign between p and q, a step of length ds: locate the limit
  // point, report it, and make q the current state again.
  void LoadStepper::report_limit_point(ArcPath &path, const double ds)
  {
    const Stage      stage = Stage::voltage;
    ArcLength::Point limit;
    if (!path.arc.locate_limit_point(path.p, ds, path.q.t_dot, limit))
      return;
    path.problem.set_current(limit.x, limit.t);
    const Evaluated e = evaluate(stage, limit.t);
    result.limit_points.push_back(
      {limit.t, load(stage, limit.t).voltages, e.summary.displacement});
    if (on_limit_point)
      on_limit_point(result.limit_points.back());
    report(e, limit.iterations);
    path.problem.set_current(path.q.x, path.q.t);
  }

  // The converged point q, a step of length ds from p: the limit point or
  // the crossings in between, its report, and whether the path ends at q.
  LoadStepper::PathEnd LoadStepper::advance_arc(ArcPath &path, const double ds)
  {
    const Stage             stage = Stage::voltage;
    const ArcLength::Point &q     = path.q;
    result.newton_iterations += q.iterations;
    ++result.solves;
    path.problem.set_current(q.x, q.t);

    const Evaluated e_q = evaluate(stage, q.t);
    if ((q.t_dot > 0.) != (path.p.t_dot > 0.))
      report_limit_point(path, ds);
    else if (!check_crossings(stage, path.p.t, path.state_p, path.e_p, q.t, e_q))
      return PathEnd::incomplete;

    path.e_p = e_q;
    if (!path.e_p.summary.validity_limit.empty())
      {
        result.message = "arc length: " + path.e_p.summary.validity_limit;
        return PathEnd::incomplete;
      }
    report(path.e_p, q.iterations);
    path.state_p = model.state();
    path.p       = q;
    if (q.t < 0.)
      {
        result.end = "the path parameter fell below 0 (voltages back to zero)";
        return PathEnd::complete;
      }
    if (settings.max_displacement > 0. &&
        path.e_p.summary.displacement > settings.max_displacement)
      {
        result.end = "the displacement passed Solver/Max displacement";
        return PathEnd::complete;
      }
    return PathEnd::open;
  }

  // The voltage stage by pseudo-arclength continuation in (unknowns, t). Ends
  // at the end of the path, when t falls below 0, or beyond the displacement
  // limit (complete: the curve has been followed as far as asked); after the
  // maximum number of steps, or with the dead load alone past the
  // displacement limit, the run is incomplete. result.end says which.
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
    ArcPath path{*problem, ArcLength(*problem, arc_settings), {}, {}, {}, {}};
    path.p.x = problem->current();
    path.p.t = 0.;
    problem->set_current(path.p.x, path.p.t);
    path.arc.tangent(path.p);
    path.state_p = model.state();
    path.e_p     = evaluate(stage, 0.);
    if (settings.max_displacement > 0. &&
        path.e_p.summary.displacement > settings.max_displacement)
      return stop_arc_length(path, "the displacement passed Solver/Max displacement before "
                                   "any voltage");

    StepController control = arc_length_controller();
    for (unsigned int k = 0; k < settings.max_arc_length_steps; ++k)
      {
        const double ds = control.step();
        std::string  why;
        if (!path.arc.step(path.p, ds, path.q, &why))
          {
            if (control.reject(ds))
              continue;
            problem->set_current(path.p.x, path.p.t);
            result.message = "arc length: no equilibrium found beyond load parameter t = " +
                             format_number(path.p.t, 6) + " (voltages " +
                             format_kV(load(stage, path.p.t).voltages, 8) + "): " + why;
            return false;
          }
        const bool    past_end = path.q.t > t_end && path.q.t_dot > 0.;
        const PathEnd end = past_end ? land_on_path_end(path, t_end) : advance_arc(path, ds);
        if (end != PathEnd::open)
          return end == PathEnd::complete;
        if (past_end)
          control.reject(ds); // a failed landing shortens the step; arc steps decide to give up
        else
          control.accept(ds, path.q.iterations);
      }
    return stop_arc_length(path, "Solver/Max arc-length steps reached");
  }

  // Steps of the arc length: at most one voltage increment at the start of
  // the path, at least the smallest one (V, with a rate of at least 1 V per
  // unit of t), growing by half after an easy step.
  StepController LoadStepper::arc_length_controller() const
  {
    StepControlSettings s;
    s.max_step = step_limit(Stage::voltage, 0.);
    s.min_step = settings.min_voltage_increment / std::max(scene.path.max_rate(0.), 1.);
    s.growth   = 1.5;
    return StepController(s, s.max_step);
  }

  RunResult LoadStepper::run()
  {
    result = RunResult();
    model.set_reference_state();
    report(evaluate(Stage::prestretch, 0.), 0);
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
