#pragma once
// Drives any EquilibriumModel through the three load stages:
//   0  pre-stretch: the unstretched film is stretched to lam_pre (homogeneous);
//   1  dead load:   the mass on the disk is ramped from 0 to m;
//   2  voltage:     the ring voltages follow the VoltagePath, t in [0, n_segments].
// Increments adapt (StepController, numerics/step_control.h): a failed Newton
// solve halves the increment (restarting from the last converged state), a
// fast one lets it grow back to its maximum. The
// voltage stage can instead be followed by pseudo-arclength continuation
// (through folds, every limit point located) when the model offers it.
// After every converged step of stages 1 and 2 the registered postprocessors
// (postprocessors.h) fill its summary, and
//  - the first load where a crossing's margin changes sign is located by the
//    bracketed root finder on the stage parameter: the wrinkling onset
//    (s2_min = 0), and the breakdown field (E_max = E_b) when that check is on;
//  - a state outside the model's validity (StepSummary::validity_limit) ends
//    the run, after the boundary has been located by bisection.
// Every loop advances the stage parameter or stops with a message.

#include <cdea/model/scene.h>
#include <cdea/model/equilibrium_model.h>
#include <cdea/numerics/step_control.h>
#include <cdea/solver/postprocessors.h>

#include <functional>
#include <limits>
#include <memory>
#include <string>

namespace cdea
{
  struct SteppingSettings
  {
    unsigned int prestretch_steps      = 1;
    double       load_increment        = 0.25;   ///< fraction of m g
    double       voltage_increment     = 250.;   ///< V, largest ring voltage change per step
    double       min_voltage_increment = 1e-3;   ///< V
    unsigned int max_cutbacks          = 30;
    double       onset_tolerance       = 1e-3;   ///< V
    bool         extrapolate           = true;   ///< linear predictor from the last two steps
    bool         arc_length            = false;  ///< voltage stage by arc-length continuation
    unsigned int max_arc_length_steps  = 400;
    double       max_displacement      = 0.;     ///< m; arc length stops beyond it (0: none)
    bool         stability_check       = false;  ///< min_eigenvalue at every step (cdea run: on)
    /// Where the check computes the eigenvalue (Solver/Stability eigenvalue).
    StabilityEigenvalue stability_eigenvalue = StabilityEigenvalue::every_step;
    double       breakdown_field       = 0.;     ///< V/m (0: off)
    double       residual_tolerance    = 1e-10;  ///< of the arc-length corrector
    double       update_tolerance      = 1e-10;
  };

  /// What the postprocessors of a path with @p settings on @p scene are made
  /// from (the Reservoir's tube is the runs', run_setup.h).
  PostprocessorSetup postprocessor_setup(const Scene &scene, const SteppingSettings &settings);

  struct RunResult
  {
    bool         completed = false; ///< reached the end of the voltage path
    std::string  message;           ///< why the run stopped early (empty if completed)
    OnsetRecord  onset;
    OnsetRecord  breakdown;                ///< first exceedance of the breakdown field
    std::vector<LimitPoint> limit_points;  ///< in the order met (arc length)
    std::string  end;                      ///< how the voltage stage ended (arc length)
    unsigned int steps             = 0; ///< converged steps reported
    unsigned int newton_iterations = 0; ///< over all solves, the onset search included
    unsigned int solves            = 0; ///< equilibrium solves attempted
    /// Time runs: the accepted and rejected steps of the time integration
    /// (from t = 0, or from the rest), the sum of the local error estimates
    /// of the disk's position (m; NaN without an estimate: the fixed-step
    /// schemes) and a warning the run should print (a drive that never rose).
    unsigned int time_steps     = 0;
    unsigned int rejected_steps = 0;
    double       error_estimate = std::numeric_limits<double>::quiet_NaN();
    std::string  warning;
  };

  class LoadStepper
  {
  public:
    /// Registers the standard postprocessors (postprocessors.h) for @p settings.
    LoadStepper(const Scene &scene, EquilibriumModel &model, const SteppingSettings &settings);

    /// Register a further postprocessor, called after the standard ones.
    void add_postprocessor(std::unique_ptr<Postprocessor> postprocessor);

    /// Called after each converged step, with the model in that state. The
    /// summary is complete (every postprocessor's part and the iterations).
    std::function<void(const StepSummary &)> on_step;
    /// Called once when the wrinkling onset has been located (before the
    /// on_step call that reports the onset state itself).
    std::function<void(const OnsetRecord &)> on_onset;
    /// Called when the breakdown field is first reached, and at each limit point.
    std::function<void(const OnsetRecord &)> on_breakdown;
    std::function<void(const LimitPoint &)>  on_limit_point;

    /// Fields of the step being reported (valid during on_step; computed
    /// once per step and shared with the postprocessors).
    const StepFields &step_fields();

    RunResult run();

    /// The load at parameter t of a stage.
    LoadState load(Stage stage, double t) const;

  private:
    /// A converged state with its summary and, if computed, its fields.
    struct Evaluated
    {
      StepSummary                       summary;
      std::shared_ptr<const StepFields> fields;
    };

    /// A quantity whose first sign change along the path is located.
    struct Crossing
    {
      std::function<double(const StepSummary &)> margin; ///< >= 0 before, < 0 after
      std::function<double(const StepSummary &)> radius; ///< where (reference R)
      OnsetRecord                               *record;
      std::function<void(const OnsetRecord &)>  *callback;
    };

    const Scene                                 scene;
    EquilibriumModel                           &model;
    SteppingSettings                            settings;
    std::vector<std::unique_ptr<Postprocessor>> postprocessors;
    std::vector<Crossing>                       crossings;

    RunResult                         result;
    std::shared_ptr<const StepFields> reported_fields;

    /// The arc-length path of the voltage stage (load_stepper.cc).
    struct ArcPath;
    /// How a step of the arc length left the path: open (go on), complete
    /// (followed as far as asked) or incomplete (the run ends early).
    enum class PathEnd
    {
      open,
      complete,
      incomplete
    };

    bool           run_stage(Stage stage, double t_end);
    StepController stage_controller(Stage stage, double t_end) const;
    void           set_min_increment(StepController &control, Stage stage, double t) const;
    /// A solve from the converged @p state0 at t to t_next, with the
    /// predictor through @p previous_state (at previous_t) if it is set.
    SolveReport    solve_step(Stage stage, double t, double t_next, const ModelState &state0,
                              const ModelState &previous_state, double previous_t);
    std::string    no_equilibrium_message(Stage stage, double t, double t_next,
                                          unsigned int cutbacks, const std::string &why) const;

    bool           run_arc_length(double t_end);
    StepController arc_length_controller() const;
    PathEnd        land_on_path_end(ArcPath &path, double t_end);
    PathEnd        advance_arc(ArcPath &path, double ds);
    void           report_limit_point(ArcPath &path, double ds);
    bool           stop_arc_length(const ArcPath &path, const std::string &why);

    Evaluated evaluate(Stage stage, double t);
    void      report(const Evaluated &state, unsigned int iterations);

    /// After a converged step from (t0, state0, e0) to t1 (the model's current
    /// state, e1): locate the crossings and the validity limit if they lie in
    /// between, report them, and leave the model at t1 again. Returns false if
    /// the run must end (a validity limit was met).
    bool check_crossings(Stage stage, double t0, const ModelState &state0, const Evaluated &e0,
                         double t1, const Evaluated &e1);
    /// Root of f(summary) on [t0, t1] with f(t0) >= 0 > f(t1); every evaluation
    /// is a solve from the nearest converged state on the f >= 0 side. Leaves
    /// the model at the root and returns its t.
    double locate_root(Stage stage, double t0, const ModelState &state0, double f0, double t1,
                       double f1, const std::function<double(const StepSummary &)> &f,
                       Evaluated &at_root, unsigned int &iterations);
    double step_limit(Stage stage, double t) const;
    double voltage_tolerance_in_t(Stage stage, double t) const;
    /// Count a solve in the result.
    SolveReport solve(const LoadState &load);
  };

  /// Human-readable name of a stage ("pre-stretch", "dead load", "voltage").
  std::string stage_name(Stage stage);
} // namespace cdea
