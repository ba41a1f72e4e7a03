#pragma once
// Drives any EquilibriumModel through the three load stages:
//   0  pre-stretch: the unstretched film is stretched to lam_pre (homogeneous);
//   1  dead load:   the mass on the disk is ramped from 0 to m;
//   2  voltage:     the ring voltages follow the VoltagePath, t in [0, n_segments].
// Increments adapt: a failed Newton solve halves the increment (restarting from
// the last converged state), a fast one lets it grow back to its maximum. The
// voltage stage can instead be followed by pseudo-arclength continuation
// (through folds, every limit point located) when the model offers it.
// After every converged step of stages 1 and 2:
//  - the first load where the hoop stress reaches zero anywhere is located by
//    regula falsi (Illinois) on the stage parameter: the wrinkling onset;
//  - likewise the first load where the true field reaches the breakdown field;
//  - a state outside the model's validity (StepSummary::validity_limit) ends
//    the run, after the boundary has been located by bisection.

#include <cdea/scene.h>
#include <cdea/solver/equilibrium_model.h>

#include <functional>
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
    double       breakdown_field       = 0.;     ///< V/m (0: off)
    double       residual_tolerance    = 1e-10;  ///< of the arc-length corrector
    double       update_tolerance      = 1e-10;
  };

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
  };

  class LoadStepper
  {
  public:
    LoadStepper(const Scene &scene, EquilibriumModel &model, const SteppingSettings &settings);

    /// Called after each converged step, with the model in that state. The
    /// summary is complete (stage, load factor, stroke, wrinkled filled in).
    std::function<void(const StepSummary &)> on_step;
    /// Called once when the wrinkling onset has been located (before the
    /// on_step call that reports the onset state itself).
    std::function<void(const OnsetRecord &)> on_onset;
    /// Called when the breakdown field is first reached, and at each limit point.
    std::function<void(const OnsetRecord &)> on_breakdown;
    std::function<void(const LimitPoint &)>  on_limit_point;

    RunResult run();

    /// The load at parameter t of a stage.
    LoadState load(Stage stage, double t) const;

  private:
    const Scene        scene;
    EquilibriumModel  &model;
    SteppingSettings   settings;

    RunResult result;
    double    reference_displacement = 0.; ///< at the end of the dead-load stage
    bool      have_reference         = false;

    bool run_stage(Stage stage, double t_end);
    bool run_arc_length(double t_end);
    void report(const StepSummary &summary_without_driver_fields, Stage stage, double t,
                unsigned int iterations);
    /// The model's summary with the driver's checks added (stability, field).
    StepSummary current_summary() const;

    /// After a converged step from (t0, state0, summary0) to t1 (the model's
    /// current state, summary1): locate the onset, breakdown and validity limit if they lie in
    /// between, report them, and leave the model at t1 again. Returns false if
    /// the run must end (a validity limit was met).
    bool check_crossings(Stage stage, double t0, const std::vector<double> &state0,
                         const StepSummary &summary0, double t1, const StepSummary &summary1);
    /// Root of f(summary) on [t0, t1] with f(t0) >= 0 > f(t1), by Illinois
    /// steps each solved from the converged side; leaves the model at the
    /// root and returns its t.
    double locate_root(Stage stage, double t0, std::vector<double> state0, double f0,
                       double t1, double f1, const std::function<double(const StepSummary &)> &f,
                       StepSummary &at_root, unsigned int &iterations);
    double step_limit(Stage stage, double t) const;
    double voltage_tolerance_in_t(Stage stage, double t) const;
  };

  /// Human-readable name of a stage ("pre-stretch", "dead load", "voltage").
  std::string stage_name(Stage stage);
} // namespace cdea
