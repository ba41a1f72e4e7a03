#pragma once
// Drives any EquilibriumModel through the three load stages:
//   0  pre-stretch: the unstretched film is stretched to lam_pre (homogeneous);
//   1  dead load:   the mass on the disk is ramped from 0 to m;
//   2  voltage:     the ring voltages follow the VoltagePath, t in [0, n_segments].
// Increments adapt: a failed Newton solve halves the increment (restarting from
// the last converged state), a fast one lets it grow back to its maximum. After
// every converged step of stages 1 and 2 the hoop stress is checked; the first
// load where s2 reaches zero anywhere is located by regula falsi (Illinois) on
// the stage parameter and reported as the wrinkling onset.

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
  };

  struct RunResult
  {
    bool         completed = false; ///< reached the end of the voltage path
    std::string  message;           ///< why the run stopped early (empty if completed)
    OnsetRecord  onset;
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
    void report(const StepSummary &summary_without_driver_fields, Stage stage, double t,
                unsigned int iterations);
    /// Locate s2 = 0 between a converged state at t0 (s2 >= 0) and one at t1
    /// (s2 < 0); leaves the model at the onset state.
    bool locate_onset(Stage stage, double t0, const std::vector<double> &state0, double f0,
                      double t1, double f1);
    double step_limit(Stage stage, double t) const;
  };

  /// Human-readable name of a stage ("pre-stretch", "dead load", "voltage").
  std::string stage_name(Stage stage);
} // namespace cdea
