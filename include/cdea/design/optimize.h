#pragma once
// `cdea optimize FILE.prm`: the electrode layout (ring edges and voltages)
// with the largest stroke, or enclosed volume change, under the constraints of
// subsection Optimization (doc/optimization.md):
//   s2 >= s2_min at every quadrature point and ring inner edge, E <= E_max
//   there, the variables within their bounds, every ring at least w_min wide
//   on the pre-stretched flat film, and the final state stable,
// where the final state is the one reached by ramping all ring voltages
// proportionally from zero (the branch continued from zero voltage).
//
// A layout is evaluated by LayoutEvaluator: the equilibrium at the layout's
// voltages and the zero-voltage state under the same load on the layout's
// mesh, with their exact sensitivities (fe/sensitivities.h). The first layout
// of a start is reached by the ramp of `cdea run`; later ones by continuation
// in the design variables from the previous layout (tangent predictor
// dx/dp dp, steps no larger than the ramp's), and the best layout of every
// start is confirmed by a ramp again. NLopt (SLSQP or MMA) moves the layout
// with the exact gradients; a layout whose ramp meets a fold, or whose
// final state is unstable, is rejected (objective +inf), which makes the
// optimizer shorten its step.

#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/sensitivities.h>
#include <cdea/model/product.h>
#include <cdea/solver/load_stepper.h>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  struct Parameters;

  /// What is designed and within which limits (SI: V, Pa, V/m; edges r/a).
  struct OptimizationSettings
  {
    static constexpr double free = std::numeric_limits<double>::quiet_NaN();
    unsigned int        n_rings = 2;
    std::vector<double> voltages; ///< V per ring; NaN: free
    std::vector<double> edges;    ///< N+1 in r/a: 1, the interior ones (NaN: free), b/a
    double              edge_lower = 1.2, edge_upper = 2.6;  ///< r/a
    double              voltage_lower = 0., voltage_upper = 8e3; ///< V
    double              min_hoop_stress = 0.;  ///< Pa
    double              max_field = std::numeric_limits<double>::infinity(); ///< V/m
    double              min_ring_width = 0.1; ///< r/a (the width in mm over a)
    DesignObjective     objective       = DesignObjective::stroke;
    unsigned int        starts          = 8;
    DesignAlgorithm     algorithm       = DesignAlgorithm::slsqp;
    unsigned int        max_evaluations = 300;
    double              tolerance       = 1e-9;

    /// The free variables: the free voltages by ring, then the free edges.
    std::vector<SceneParameter> free_parameters() const;
  };

  /// The settings from parsed parameters; every check of subsection
  /// Optimization is made here. Throws InputError naming the parameter.
  OptimizationSettings optimization_settings(const Parameters &p, const Scene &scene);

  /// A layout: N+1 edges (r/a) and N voltages (V).
  struct Layout
  {
    std::vector<double> edges, voltages;
    /// The free variables (as OptimizationSettings::free_parameters()).
    std::vector<double> free_values(const std::vector<SceneParameter> &free) const;
    void                set_free_values(const std::vector<SceneParameter> &free,
                                        const std::vector<double>         &values);
  };

  /// The scene of @p layout: @p base with its edges and the path that ramps
  /// all voltages proportionally from zero to the layout's.
  Scene layout_scene(const Scene &base, const Layout &layout);

  /// An evaluated layout; gradients are with respect to the free variables.
  struct LayoutEvaluation
  {
    bool            ok = false;
    std::string     message; ///< why not (a fold on the ramp, an unstable state)
    double          displacement  = 0.; ///< m
    double          stroke        = 0.; ///< m
    double          volume_change = 0.; ///< m^3
    bool            stable = false;     ///< tangent positive definite (loads held)
    /// N/m, smallest eigenvalue of the final state's tangent (computed on
    /// the ramps from zero only; NaN otherwise).
    double          min_eigenvalue = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXd d_stroke, d_volume_change;
    PointValues     points; ///< s2 and E with their gradients
  };

  class LayoutEvaluator
  {
  public:
    LayoutEvaluator(const Scene &base, const OptimizationSettings &settings,
                    const FeDiscretization &discretization, const NewtonSettings &newton,
                    const SteppingSettings &stepping);
    ~LayoutEvaluator();

    /// By continuation from the last layout evaluated (a ramp if none).
    LayoutEvaluation evaluate(const Layout &layout);
    /// Along the load stages of `cdea run` from the unstretched film.
    LayoutEvaluation ramp(const Layout &layout);

    unsigned int solves() const { return solves_; }
    unsigned int newton_iterations() const { return iterations_; }
    unsigned int ramps() const { return ramps_; }

  private:
    /// The last layout reached, with both states and their sensitivities.
    struct Reached;
    const Scene                       base;
    const OptimizationSettings        settings;
    const FeDiscretization            discretization;
    const NewtonSettings              newton;
    const SteppingSettings            stepping;
    const std::vector<SceneParameter> free;
    std::unique_ptr<MembraneModel>    model;
    std::vector<double>               model_edges;
    std::unique_ptr<Reached>          last;
    unsigned int                      solves_ = 0, iterations_ = 0, ramps_ = 0;

    MembraneModel   &model_for(const std::vector<double> &edges);
    LoadState        load_of(const Layout &layout, bool loaded) const;
    bool             solve(MembraneModel &m, const LoadState &load, const ModelState &guess);
    bool             continue_to(const Layout &target);
    bool             step_to(const std::vector<double> &from, const std::vector<double> &to,
                             double next);
    LayoutEvaluation result() const;
  };

  /// One row of the history: an evaluation of the optimizer.
  struct HistoryRow
  {
    unsigned int        start = 0, evaluation = 0;
    double              objective = 0.;        ///< mm or mm^3; NaN if the layout failed
    double              worst_constraint = 0.; ///< largest scaled violation (<= 0: feasible)
    std::vector<double> free_values;           ///< kV and r/a
    std::string         message;               ///< why the layout failed (empty if not)
  };

  /// The result of one start.
  struct StartResult
  {
    unsigned int     start = 0;
    Layout           initial, best;
    /// Feasible, first-order optimal (KKT), confirmed by a ramp.
    bool             converged = false;
    std::string      status;    ///< NLopt's result, and why not converged
    LayoutEvaluation at_best;   ///< confirmed by a ramp from zero
    double           objective = -std::numeric_limits<double>::infinity(); ///< mm or mm^3
    double           worst_constraint = 0.;
    /// |grad f + A lambda| / |grad f| over the active constraints and bounds.
    double           optimality = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::string> active; ///< the active constraints at the best layout
    unsigned int     evaluations = 0, solves = 0, newton_iterations = 0;
    double           seconds = 0.;
    std::vector<HistoryRow> history;
  };

  /// The deterministic starting layouts of the multistart.
  std::vector<Layout> starting_layouts(const OptimizationSettings &settings);

  /// The constraints c <= 0 of an evaluated layout (scaled: s2 by mu, E by
  /// E_max, widths by b/a - 1), their gradients (rows: constraints, columns:
  /// free variables) and a name for each.
  void constraints(const OptimizationSettings &settings, const Scene &base, const Layout &layout,
                   const LayoutEvaluation &evaluation, Eigen::VectorXd &c,
                   Eigen::MatrixXd &dc, std::vector<std::string> *names = nullptr);

  /// Optimise from @p start; @p on_evaluation is told about every evaluation.
  StartResult optimize_from(const Scene &base, const OptimizationSettings &settings,
                            LayoutEvaluator &evaluator, unsigned int index, const Layout &start,
                            const std::function<void(const HistoryRow &)> &on_evaluation = {});

  /// All starts of a run and the best of them.
  struct OptimizationRun
  {
    std::vector<StartResult> starts; ///< in start order
    unsigned int             best    = 0; ///< index into starts
    unsigned int             ranks   = 1;
    double                   seconds = 0.;
  };

  /// The best start: among the converged starts (else the feasible ones),
  /// those with the largest objective to a relative 1e-7, and of these the
  /// one with the smallest constraint violation (largest scaled constraint
  /// value, if positive), then the smallest
  /// first-order residual; if none is feasible, the least infeasible one.
  unsigned int best_start(const std::vector<StartResult> &starts);

  /// Every start of @p settings (under mpirun: dealt round-robin to the
  /// ranks, gathered on rank 0, where the best is chosen), told about every
  /// evaluation and every finished start of this rank. No output. After a
  /// stop request (StopOnSignals) only a rank's first start runs, and stops
  /// at its next evaluation with the best layout so far.
  OptimizationRun optimize_layouts(const Parameters &p, const Scene &base,
                                   const OptimizationSettings &settings,
                                   const std::function<void(const HistoryRow &)>  &on_evaluation = {},
                                   const std::function<void(const StartResult &)> &on_start = {});

  /// The product of the run (model/quantities_optimize.h): the optimum,
  /// /history, /starts and /optimum of doc/optimization.md, in SI.
  Product optimum_product(const OptimizationRun &run, const OptimizationSettings &settings,
                          const Scene &base, const std::string &parameter_text);

  /// <Base name>_optimum.prm: the parameters of @p input (its overrides
  /// included) with the layout as electrodes and a one-waypoint voltage path
  /// by load stepping, which `cdea run` replays to the optimum (its results
  /// go to <Base name>_optimum_run.h5). A finite @p max_field (V/m, the field
  /// limit) becomes its Breakdown field, so that the replay reports the
  /// largest field.
  void write_replay_parameters(const ParameterInput &input, const std::string &path,
                               const Layout &layout, const std::string &base_name,
                               double max_field);
} // namespace cdea
