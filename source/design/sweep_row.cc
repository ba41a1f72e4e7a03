// One row of a design map (one r_v/a): the state with both rings at the inner
// voltage, continuation along the outer voltage in both directions, and the
// red and blue lines by bracketed root finding between converged states.

#include <cdea/design/sweep.h>
#include <cdea/base/format.h>
#include <cdea/numerics/bracketed_root.h>
#include <cdea/numerics/step_control.h>
#include <cdea/model/load_state.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <sstream>
#include <utility>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// Degree of the polynomial extrapolation along the outer voltage (the
    /// number of earlier states used). Converged steps of a figure-8 map need
    /// 2.19 Newton iterations with degree 2, 1.62 with 4, 1.39 with 6
    /// (bench_sweep); 4 keeps the extrapolation weights moderate (at most 10
    /// on an even grid) where the steps shrink towards a fold.
    constexpr std::size_t predictor_order = 4;

    /// The two line functions of a state: red = s2 at the outer ring's inner
    /// edge, blue = s2(inner edge of ring 1) - s2(inner edge of ring 2).
    double red_function(const StepSummary &s) { return s.s2_ring_inner[1]; }
    double blue_function(const StepSummary &s)
    {
      return s.s2_ring_inner[0] - s.s2_ring_inner[1];
    }


    /// A converged state on the continuation path.
    struct PathPoint
    {
      double              voltage = nan; ///< outer ring (V)
      ModelState          state;
      StepSummary         summary;
    };

    /// Up to predictor_order earlier converged states of a branch (outer
    /// voltage, state), newest first.
    using History = std::vector<std::pair<double, ModelState>>;

    /// A sign change of a line function between two neighbouring converged
    /// states of the path (a: nearer to the base state, b: farther).
    struct Bracket
    {
      bool      found = false;
      PathPoint a, b;
    };

    /// The nested factors f_j of the extrapolation at @p next through the
    /// first k + 1 @p nodes (see predict()); false if one is not well defined.
    bool nested_factors(const std::vector<double> &nodes, const std::size_t k, const double next,
                        std::vector<double> &f)
    {
      f.assign(k, 0.);
      double P = 1.;
      for (std::size_t j = 0; j < k; ++j)
        {
          double w = 1.;
          for (std::size_t i = 0; i <= k; ++i)
            if (i != j)
              w *= (next - nodes[i]) / (nodes[j] - nodes[i]);
          f[j] = w / P - 1.;
          if (!(std::isfinite(f[j]) && std::abs(f[j]) > 1e-12))
            return false;
          P = -P * f[j];
        }
      return true;
    }

    /// Starting guess at outer voltage @p next: the polynomial extrapolation
    /// in the voltage through the current state x_0 and the earlier ones
    /// x_1 .. x_k of @p history, i.e. sum_j w_j x_j with the Lagrange weights
    /// w_j at @p next. Built from k calls of predict(), x + f (x - x_older),
    /// nested from the oldest state on: y_k = x_k, y_j = x_j + f_j (x_j - y_{j+1}),
    /// guess y_0; its weights are w_j = P_j (1 + f_j) with P_0 = 1,
    /// P_{j+1} = -P_j f_j (and w_k = P_k). The order is lowered until the
    /// nested factors are well defined.
    void predict(EquilibriumModel &model, const PathPoint &current, const History &history,
                 const double next)
    {
      std::vector<double> nodes{current.voltage};
      for (const auto &h : history)
        nodes.push_back(h.first);
      std::vector<double> f;
      for (std::size_t k = nodes.size() - 1; k >= 1; --k)
        {
          if (!nested_factors(nodes, k, next, f))
            continue;
          ModelState y = history[k - 1].second; // y_k = x_k
          for (std::size_t j = k - 1; j >= 1; --j)
            {
              model.set_state(history[j - 1].second); // x_j
              model.predict(y, f[j]);
              y = model.state();
            }
          model.set_state(current.state);
          model.predict(y, f[0]);
          return;
        }
    }

    /// Why a branch of the row stopped: a step of @p step V from @p from failed.
    std::string fold_message(const double direction, const double from, const double step,
                             const std::string &why)
    {
      std::ostringstream m;
      m << "outer voltage " << (direction > 0 ? "raised" : "lowered")
        << ": no equilibrium found beyond " << format_kV(from, 7) << " (a step of " << step
        << " V failed: " << why << "); typically a fold of the voltage-displacement curve";
      return m.str();
    }

    class RowSolver
    {
    public:
      using Record  = std::function<void(std::size_t, const StepSummary &)>;
      using Skipped = std::function<void(std::size_t)>;

      RowSolver(EquilibriumModel &model, const Scene &scene, const SweepSettings &settings,
                const SteppingSettings &stepping, SweepRow &row)
        : model(model)
        , scene(scene)
        , settings(settings)
        , stepping(stepping)
        , row(row)
      {}

      /// Continue from @p base through the grid indices @p targets (in order
      /// of distance from the base voltage), recording every grid point and
      /// the first sign change of each line function. Returns false if the
      /// solver could not go on (the message is recorded in the row).
      bool continue_path(const PathPoint &base, const std::vector<std::size_t> &targets,
                         Bracket &red, Bracket &blue, const Record &record,
                         const Skipped &skipped)
      {
        model.set_state(base.state);
        PathPoint      current = base;
        History        history;
        StepController control = path_controller();
        for (std::size_t n = 0; n < targets.size(); ++n)
          {
            const double target = settings.outer_voltages[targets[n]];
            while (current.voltage != target)
              {
                const double direction = target > current.voltage ? 1. : -1.;
                const double h         = control.step();
                const double next      = std::abs(target - current.voltage) <= h ?
                                           target :
                                           current.voltage + direction * h;
                const double      step = std::abs(next - current.voltage);
                const SolveReport report =
                  step_to(current, history, next, control.last_attempt(step));
                if (!report.converged)
                  {
                    model.set_state(current.state);
                    if (control.reject(step))
                      continue;
                    row.message = fold_message(direction, current.voltage, step, report.message);
                    for (std::size_t k = n; k < targets.size(); ++k)
                      skipped(targets[k]);
                    return false;
                  }
                PathPoint point{next, model.state(), model.summary()};
                note_crossings(current, point, red, blue);
                history.insert(history.begin(), {current.voltage, std::move(current.state)});
                if (history.size() > predictor_order)
                  history.pop_back();
                current = std::move(point);
                control.accept(step, report.iterations);
              }
            record(targets[n], current.summary);
          }
        return true;
      }

      /// The root of @p f on the bracket's voltages by the project's bracketed
      /// root finder; every evaluation is an equilibrium solve from the linear
      /// interpolation of the bracket's end states.
      SweepLine locate(const Bracket &bracket, double (*f)(const StepSummary &))
      {
        SweepLine line;
        if (!bracket.found)
          return line;
        const double va = bracket.a.voltage, vb = bracket.b.voltage;
        std::vector<std::pair<double, StepSummary>> evaluated{{va, bracket.a.summary},
                                                               {vb, bracket.b.summary}};
        auto evaluate = [&](const double v) -> double {
          ++line.evaluations;
          if (!solve_between(bracket, v))
            return nan;
          const StepSummary summary = model.summary();
          evaluated.emplace_back(v, summary);
          return f(summary);
        };

        BracketedRootSettings root_settings;
        root_settings.x_tolerance     = settings.line_tolerance;
        root_settings.stop_on_failure = true;
        const BracketedRoot root =
          find_bracketed_root(evaluate, va, f(bracket.a.summary), vb, f(bracket.b.summary),
                              root_settings);
        if (root.failed_evaluation)
          row.message += std::string(row.message.empty() ? "" : "; ") +
                         "a root search stopped at a failed solve near " +
                         format_kV(root.hi, 7);
        // The estimate is the evaluated state with the smallest |f|.
        for (const auto &[v, summary] : evaluated)
          if (v == root.x)
            {
              line.outer_voltage = v;
              line.displacement  = summary.displacement;
              line.s2_inner[0]   = summary.s2_ring_inner[0];
              line.s2_inner[1]   = summary.s2_ring_inner[1];
              break;
            }
        line.bracket_width = root.failed_evaluation ? std::abs(vb - va) : root.hi - root.lo;
        return line;
      }

    private:
      EquilibriumModel       &model;
      const Scene            &scene;
      const SweepSettings    &settings;
      const SteppingSettings &stepping;
      SweepRow               &row;

      LoadState load(const double outer) const
      {
        return full_load(scene, {settings.inner_voltage, outer}, scene.path.n_segments());
      }

      SolveReport solve(const double outer)
      {
        const SolveReport r = model.solve(load(outer));
        ++row.solves;
        row.newton_iterations += r.iterations;
        if (!r.converged)
          {
            ++row.failed_solves;
            row.failed_iterations += r.iterations;
          }
        return r;
      }

      /// Steps in the outer voltage of at most Solver/Voltage increment. Near
      /// a fold a failed step is halved until a step this small fails: finer
      /// than the line tolerance is of no use for the map.
      StepController path_controller() const
      {
        StepControlSettings s;
        s.max_step     = stepping.voltage_increment;
        s.min_step     = std::max(stepping.min_voltage_increment, settings.line_tolerance);
        s.max_cutbacks = stepping.max_cutbacks;
        s.after_reject = StepBase::attempted;
        return StepController(s, s.max_step);
      }

      /// A solve at @p next from the extrapolation of @p current and
      /// @p history. On the @p last_try before giving up, a failure is tried
      /// once more from the converged state (the predictor may have
      /// overshot); earlier, a cut-back is cheaper: such retries hardly ever
      /// succeed.
      SolveReport step_to(const PathPoint &current, const History &history, const double next,
                          const bool last_try)
      {
        const bool predicted = !history.empty();
        if (predicted)
          predict(model, current, history, next);
        SolveReport report = solve(next);
        if (!report.converged && predicted && last_try)
          {
            model.set_state(current.state);
            report = solve(next);
          }
        return report;
      }

      /// The first sign change of each line function along the branch.
      static void note_crossings(const PathPoint &current, const PathPoint &point, Bracket &red,
                                 Bracket &blue)
      {
        for (auto *bracket : {&red, &blue})
          if (!bracket->found)
            {
              const auto   f  = bracket == &red ? red_function : blue_function;
              const double f0 = f(current.summary), f1 = f(point.summary);
              if ((f0 < 0.) != (f1 < 0.) || f1 == 0.)
                {
                  bracket->found = true;
                  bracket->a     = current;
                  bracket->b     = point;
                }
            }
      }

      /// An equilibrium at @p v from the linear interpolation of the
      /// bracket's end states, x = x_a + s (x_b - x_a) = x_b + (s - 1) (x_b - x_a),
      /// and from the end state a if that fails.
      bool solve_between(const Bracket &bracket, const double v)
      {
        const double s = (v - bracket.a.voltage) / (bracket.b.voltage - bracket.a.voltage);
        model.set_state(bracket.b.state);
        model.predict(bracket.a.state, s - 1.);
        SolveReport report = solve(v);
        if (!report.converged)
          {
            model.set_state(bracket.a.state);
            report = solve(v);
          }
        return report.converged;
      }
    };

    double seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /// Both rings to the inner voltage, as in a normal run: the base state
    /// of the row (false if not reached, the row's message says why), in the
    /// time since the row's @p start.
    bool reach_base(EquilibriumModel &model, const Scene &scene, const SweepSettings &settings,
                    const SteppingSettings                     &stepping,
                    const std::chrono::steady_clock::time_point start, SweepRow &row,
                    PathPoint &base)
    {
      LoadStepper     stepper(scene, model, stepping);
      const RunResult run = stepper.run();
      row.solves += run.solves;
      row.newton_iterations += run.newton_iterations;
      row.base_solves     = run.solves;
      row.base_iterations = run.newton_iterations;
      row.base_seconds    = seconds_since(start);
      if (!run.completed)
        {
          row.message = "both rings did not reach the inner voltage: " + run.message;
          return false;
        }
      base.voltage          = settings.inner_voltage;
      base.state            = model.state();
      base.summary          = model.summary();
      row.base_reached      = true;
      row.base_displacement = base.summary.displacement;
      row.base_s2_inner[0]  = base.summary.s2_ring_inner[0];
      row.base_s2_inner[1]  = base.summary.s2_ring_inner[1];
      row.lowest_voltage = row.highest_voltage = base.voltage;
      return true;
    }

    /// The grid points of a row as they are reached (the values there, the
    /// progress), with the stroke and its increase over the base state's.
    class RowRecorder
    {
    public:
      RowRecorder(SweepRow &row, const SweepSettings &settings, const double zero_displacement,
                  const double base_displacement,
                  const std::function<void(std::size_t)> &on_points)
        : row(row)
        , settings(settings)
        , zero(zero_displacement)
        , base_stroke(base_displacement - zero_displacement)
        , on_points(on_points)
      {}

      double increase(const double displacement) const
      {
        return 100. * ((displacement - zero) / base_stroke - 1.);
      }

      void record(const std::size_t k, const StepSummary &s)
      {
        row.displacement[k]    = s.displacement;
        row.stroke[k]          = s.displacement - zero;
        row.stroke_increase[k] = increase(s.displacement);
        row.s2_inner_ring1[k]  = s.s2_ring_inner[0];
        row.s2_inner_ring2[k]  = s.s2_ring_inner[1];
        row.lowest_voltage     = std::min(row.lowest_voltage, settings.outer_voltages[k]);
        row.highest_voltage    = std::max(row.highest_voltage, settings.outer_voltages[k]);
        skipped(k);
      }

      void skipped(std::size_t) const
      {
        if (on_points)
          on_points(1);
      }

    private:
      SweepRow                               &row;
      const SweepSettings                    &settings;
      const double                            zero, base_stroke;
      const std::function<void(std::size_t)> &on_points;
    };

    /// Grid points at the inner voltage are the base state (recorded now);
    /// the others are reached by continuation up and down from it, in order
    /// of distance.
    void split_grid(const SweepSettings &settings, const PathPoint &base, RowRecorder &recorder,
                    std::vector<std::size_t> &up, std::vector<std::size_t> &down)
    {
      const double same = 1e-9 * std::max(1., settings.inner_voltage);
      for (std::size_t k = 0; k < settings.outer_voltages.size(); ++k)
        {
          const double v = settings.outer_voltages[k];
          if (std::abs(v - settings.inner_voltage) <= same)
            recorder.record(k, base.summary);
          else if (v > settings.inner_voltage)
            up.push_back(k);
          else
            down.insert(down.begin(), k);
        }
    }

    /// The lines: the first crossing above the inner voltage, else below it.
    void locate_lines(RowSolver &solver, const RowRecorder &recorder, const Bracket (&up)[2],
                      const Bracket (&down)[2], SweepRow &row)
    {
      const unsigned int solves_before = row.solves, iterations_before = row.newton_iterations;
      const auto         start         = std::chrono::steady_clock::now();
      row.red  = solver.locate(up[0].found ? up[0] : down[0], red_function);
      row.blue = solver.locate(up[1].found ? up[1] : down[1], blue_function);
      row.line_solves     = row.solves - solves_before;
      row.line_iterations = row.newton_iterations - iterations_before;
      row.line_seconds    = seconds_since(start);
      for (SweepLine *line : {&row.red, &row.blue})
        line->stroke_increase = recorder.increase(line->displacement);
    }
  } // namespace

  Scene sweep_scene(const Scene &base, const double rv_over_a, const double inner_voltage)
  {
    Scene scene             = base;
    scene.ring_edges_over_a = {1., rv_over_a, base.frame_radius / base.disk_radius};
    scene.path = VoltagePath(std::vector<std::vector<double>>{{inner_voltage, inner_voltage}});
    return scene;
  }

  SweepRow compute_sweep_row(EquilibriumModel &model, const Scene &scene,
                             const SweepSettings &settings, const SteppingSettings &stepping,
                             const double zero_voltage_displacement,
                             const std::function<void(std::size_t)> &on_points)
  {
    const auto        start = std::chrono::steady_clock::now();
    const std::size_t m     = settings.outer_voltages.size();
    SweepRow          row;
    row.rv_over_a = scene.ring_edges_over_a.at(1);
    for (auto *v : {&row.displacement, &row.stroke, &row.stroke_increase, &row.s2_inner_ring1,
                    &row.s2_inner_ring2})
      v->assign(m, nan);

    PathPoint base;
    if (!reach_base(model, scene, settings, stepping, start, row, base))
      {
        if (on_points)
          on_points(m);
        row.seconds = seconds_since(start);
        return row;
      }
    RowRecorder recorder(row, settings, zero_voltage_displacement, base.summary.displacement,
                         on_points);
    std::vector<std::size_t> up, down;
    split_grid(settings, base, recorder, up, down);

    RowSolver           solver(model, scene, settings, stepping, row);
    Bracket             brackets_up[2], brackets_down[2]; // red, blue
    std::string         message_up;
    const auto          record  = [&](std::size_t k, const StepSummary &s) { recorder.record(k, s); };
    const auto          skipped = [&](std::size_t k) { recorder.skipped(k); };
    solver.continue_path(base, up, brackets_up[0], brackets_up[1], record, skipped);
    std::swap(message_up, row.message);
    solver.continue_path(base, down, brackets_down[0], brackets_down[1], record, skipped);
    if (!message_up.empty())
      row.message = message_up + (row.message.empty() ? "" : "; " + row.message);
    locate_lines(solver, recorder, brackets_up, brackets_down, row);
    row.seconds = seconds_since(start);
    return row;
  }

  double zero_voltage_displacement(const Scene &base, const FeDiscretization &disc,
                                   const NewtonSettings &newton, const SteppingSettings &stepping)
  {
    Scene scene             = base;
    scene.ring_edges_over_a = {1., base.frame_radius / base.disk_radius};
    scene.path              = VoltagePath(std::vector<std::vector<double>>{{0.}});
    MembraneModel model(scene, disc, newton);
    LoadStepper   stepper(scene, model, stepping);
    const RunResult run = stepper.run();
    if (!run.completed)
      throw std::runtime_error("the zero-voltage state under the dead load was not reached: " +
                               run.message);
    return model.summary().displacement;
  }
} // namespace cdea
