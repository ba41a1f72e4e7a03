// LayoutEvaluator: the final and the zero-voltage state of a layout with their
// sensitivities, by a ramp from the unstretched film or by continuation in the
// design variables from the last layout reached (see optimize.h).

#include <cdea/design/optimize.h>
#include <cdea/model/load_state.h>
#include <cdea/numerics/step_control.h>

#include <algorithm>
#include <cmath>

namespace cdea
{
  namespace
  {
    /// Largest change of a free ring edge (r/a) in one continuation step,
    /// and of a voltage in units of Solver/Voltage increment: the tangent
    /// predictor allows longer steps than the ramp's linear one.
    constexpr double edge_increment    = 0.1;
    constexpr double voltage_increments = 4.;
    /// Halvings of a continuation step before the ramp takes over.
    constexpr unsigned int max_cutbacks = 6;
  } // namespace

  struct LayoutEvaluator::Reached
  {
    Layout          layout;
    ModelState      reference, loaded;
    Eigen::MatrixXd d_reference, d_loaded; ///< dx/dp of both states
    double          reference_displacement = 0., reference_volume = 0.;
    Eigen::VectorXd d_reference_displacement, d_reference_volume;
    LayoutEvaluation evaluation; ///< of the loaded state, with the reference's parts

    /// The model's current state (zero voltage) as the reference.
    void set_reference(MembraneModel &m, const std::vector<SceneParameter> &free)
    {
      const StateSensitivity at(m, free);
      reference                = m.state();
      d_reference              = at.state_derivative();
      reference_displacement   = at.displacement();
      reference_volume         = at.volume();
      d_reference_displacement = at.d_displacement();
      d_reference_volume       = at.d_volume();
    }
  };

  LayoutEvaluator::LayoutEvaluator(const Scene &base_in, const OptimizationSettings &settings_in,
                                   const FeDiscretization &disc, const NewtonSettings &newton_in,
                                   const SteppingSettings &stepping_in)
    : base(base_in)
    , settings(settings_in)
    , discretization(disc)
    , newton(newton_in)
    , stepping(stepping_in)
    , free(settings_in.free_parameters())
  {}

  LayoutEvaluator::~LayoutEvaluator() = default;

  MembraneModel &LayoutEvaluator::model_for(const std::vector<double> &edges)
  {
    if (!model || edges != model_edges)
      {
        Scene scene             = base;
        scene.ring_edges_over_a = edges;
        model       = std::make_unique<MembraneModel>(scene, discretization, newton);
        model_edges = edges;
      }
    return *model;
  }

  // The loads of LoadStepper at the end of the dead-load stage (reference) and
  // at the end of a one-waypoint voltage path (loaded).
  LoadState LayoutEvaluator::load_of(const Layout &layout, const bool loaded) const
  {
    if (loaded)
      return full_load(base, layout.voltages);
    return full_load(base, std::vector<double>(layout.voltages.size(), 0.), 1., Stage::dead_load);
  }

  bool LayoutEvaluator::solve(MembraneModel &m, const LoadState &load, const ModelState &guess)
  {
    m.set_state(guess);
    const SolveReport r = m.solve(load);
    ++solves_;
    iterations_ += r.iterations;
    return r.converged;
  }

  LayoutEvaluation LayoutEvaluator::result() const
  {
    LayoutEvaluation e = last->evaluation;
    e.stroke           = e.displacement - last->reference_displacement;
    e.d_stroke         = e.d_stroke - last->d_reference_displacement;
    e.volume_change    = e.volume_change - last->reference_volume;
    e.d_volume_change  = e.d_volume_change - last->d_reference_volume;
    if (!e.stable)
      {
        e.ok      = false;
        e.message = "the final state is unstable (its tangent is not positive definite)";
      }
    return e;
  }

  namespace
  {
    /// The loaded state's own part of an evaluation (stroke and volume
    /// change still absolute: the reference is subtracted in result()).
    LayoutEvaluation loaded_part(const StateSensitivity &s)
    {
      LayoutEvaluation e;
      e.ok              = true;
      e.displacement    = s.displacement();
      e.stroke          = s.displacement();
      e.d_stroke        = s.d_displacement();
      e.volume_change   = s.volume();
      e.d_volume_change = s.d_volume();
      e.points          = s.points();
      e.stable          = s.stable();
      return e;
    }
  } // namespace

  LayoutEvaluation LayoutEvaluator::ramp(const Layout &layout)
  {
    ++ramps_;
    const Scene    scene = layout_scene(base, layout);
    MembraneModel &m     = model_for(layout.edges);
    auto           reached = std::make_unique<Reached>();
    reached->layout        = layout;
    LoadStepper stepper(scene, m, stepping);
    stepper.on_step = [&](const StepSummary &s) {
      if (s.stage == Stage::dead_load && s.load_factor == 1.)
        reached->set_reference(m, free);
    };
    const RunResult run = stepper.run();
    solves_ += run.solves;
    iterations_ += run.newton_iterations;
    if (!run.completed)
      {
        LayoutEvaluation failed;
        failed.message = run.message;
        return failed;
      }
    const StateSensitivity at(m, free);
    reached->loaded     = m.state();
    reached->d_loaded   = at.state_derivative();
    reached->evaluation                = loaded_part(at);
    reached->evaluation.min_eigenvalue = m.min_tangent_eigenvalue();
    last                               = std::move(reached);
    return result();
  }

  // One continuation step to the fraction @p next of the way from the free
  // values @p from to @p to, from the tangent predictor x + dx/dp dp of both
  // states of the last layout reached; on success that layout is the new
  // last one. A step that lands beyond a fold (on an unstable branch) fails
  // too.
  bool LayoutEvaluator::step_to(const std::vector<double> &from, const std::vector<double> &to,
                                const double next)
  {
    std::vector<double>       values(free.size());
    Eigen::VectorXd           dp(free.size());
    const std::vector<double> now = last->layout.free_values(free);
    for (std::size_t j = 0; j < free.size(); ++j)
      {
        values[j] = next == 1. ? to[j] : from[j] + next * (to[j] - from[j]);
        dp[j]     = values[j] - now[j];
      }
    Layout layout = last->layout;
    layout.set_free_values(free, values);

    MembraneModel &m             = model_for(layout.edges);
    const bool     edges_changed = layout.edges != last->layout.edges;
    auto           reached       = std::make_unique<Reached>(*last);
    reached->layout              = layout;
    bool ok                      = true;
    if (edges_changed)
      {
        ok = solve(m, load_of(layout, false),
                   predicted_state(last->reference, last->d_reference, dp));
        if (ok)
          reached->set_reference(m, free);
      }
    if (ok)
      {
        ModelState guess = predicted_state(last->loaded, last->d_loaded, dp);
        guess.load       = load_of(layout, true);
        ok               = solve(m, guess.load, guess);
      }
    if (!ok)
      return false;
    const StateSensitivity at(m, free);
    if (!at.stable())
      return false;
    reached->loaded     = m.state();
    reached->d_loaded   = at.state_derivative();
    reached->evaluation = loaded_part(at);
    last                = std::move(reached);
    return true;
  }

  // From the last layout to @p target in steps no larger than the ramp's
  // (voltage) and edge_increment (edges); a failed step is halved, at most
  // max_cutbacks times on the way, and the step doubles after every step
  // reached.
  bool LayoutEvaluator::continue_to(const Layout &target)
  {
    const std::vector<double> from  = last->layout.free_values(free);
    const std::vector<double> to    = target.free_values(free);
    double                    steps = 1.;
    for (std::size_t j = 0; j < free.size(); ++j)
      steps = std::max(steps, std::abs(to[j] - from[j]) /
                                (free[j].kind == ParameterKind::voltage ?
                                   voltage_increments * stepping.voltage_increment :
                                   edge_increment));
    StepControlSettings s;
    s.max_step          = 1. / std::ceil(steps);
    s.max_cutbacks      = max_cutbacks;
    s.cutbacks_in_total = true;
    s.easy_iterations   = StepControlSettings::unlimited;
    StepController control(s, s.max_step);
    double         done = 0.; // fraction of the way
    while (done < 1.)
      {
        const double       next              = std::min(1., done + control.step());
        const unsigned int iterations_before = iterations_;
        if (!step_to(from, to, next))
          {
            if (!control.reject(next - done))
              return false;
            continue;
          }
        control.accept(next - done, iterations_ - iterations_before);
        done = next;
      }
    return true;
  }

  LayoutEvaluation LayoutEvaluator::evaluate(const Layout &layout)
  {
    if (!last)
      return ramp(layout);
    // A layout that cannot be reached leaves the last one reached as it was.
    const Reached before = *last;
    if (continue_to(layout))
      return result();
    LayoutEvaluation e = ramp(layout);
    if (!e.ok)
      last = std::make_unique<Reached>(before);
    return e;
  }
} // namespace cdea
