#pragma once
// Drives a TransientModel through time (doc/time.md):
//
//  1. pre-stretch and dead load quasi-statically (LoadStepper), with the
//     material's internal variables relaxed (network B carries nothing) -- or,
//     with a rest time, relaxed in the pre-stretched film and then held while
//     the weight is hung;
//  2. with a rest time, the weight held that long at zero voltage (creep);
//  3. the voltage waveform from t = 0 to its end in implicit steps of at most
//     `max_step` (and, for a sine, 1/16 of its period), landing on every
//     breakpoint of the waveform. An ESDIRK method (esdirk_step.h, the
//     default) takes each step in stages and accepts it and sizes the next
//     from its error estimate (StepAcceptance with a PI controller, through
//     StepController's accept_with_factor and reject_with_factor), or takes
//     fixed steps. The fixed-step schemes of earlier versions solve each
//     step once with the internal variables' update (backward Euler or the
//     trapezoidal rule) and, if on, the Newmark inertia of the disk (and the
//     pump's water column):
//       a1 = (z1 - z_pred) / (beta dt^2),  v1 = v0 + dt ((1 - gamma) a0 + gamma a1).
//     Every scheme halves the step where Newton fails and, with fixed steps,
//     grows it back after easy steps (StepController, numerics/step_control.h).
//
// Every converged step goes through the same postprocessors as the
// quasi-static run, plus the time columns (time, disk velocity, energy
// budget), and to on_step. The first step in which the smallest hoop stress
// becomes negative is searched for the onset time (bracketed root in the
// step's fraction), reported as a step of its own.

#include <cdea/model/scene.h>
#include <cdea/numerics/esdirk.h>
#include <cdea/numerics/step_control.h>
#include <cdea/solver/esdirk_step.h>
#include <cdea/solver/load_stepper.h>
#include <cdea/solver/postprocessors.h>
#include <cdea/model/transient_model.h>
#include <cdea/model/waveform.h>

#include <functional>
#include <limits>
#include <memory>

namespace cdea
{
  struct TimeSettings
  {
    Waveform     waveform;
    double       max_step     = 0.01; ///< s
    double       min_step     = 1e-8; ///< s; a step cut below it ends the run
    unsigned int max_cutbacks = 30;
    /// A fixed-step scheme (backward Euler or trapezoidal) or an ESDIRK
    /// method with or without error control. The parameter file's default is
    /// ESDIRK4 with error control (time_settings() sets it); this struct's
    /// stays backward Euler for the C++ callers that build a fixed-step run.
    TimeMethod      method  = TimeMethod::backward_euler;
    TimeStepControl control = TimeStepControl::error;
    /// Error control: a step is accepted if every estimate e of its local
    /// error is below absolute + relative |value| (velocities: times the
    /// disk's angular frequency; the water volume: absolute times the tube's
    /// cross-section, i.e. the level in the tube).
    double relative_tolerance     = 1e-6;
    double displacement_tolerance = 1e-9; ///< m, absolute
    double internal_tolerance     = 1e-9; ///< absolute, on the evolving internal variables
    bool         inertia      = true;
    double       newmark_beta  = 0.25; ///< average acceleration: second order,
    double       newmark_gamma = 0.5;  ///< no numerical damping
    /// Time (s) the weight hangs at zero voltage before t = 0; infinity: the
    /// film starts relaxed.
    double rest_time = std::numeric_limits<double>::infinity();
    /// Fields wanted every this much time besides the breakpoints (0: not).
    double fields_interval = 0.;
    /// The liquid column on the enclosed volume whose inertia the steps
    /// carry with the disk's (the pump's water; transient_model.h); none:
    /// not present.
    LiquidColumn column;
  };

  /// An ESDIRK step of @p settings' method (an ESDIRK one) on @p model: the
  /// disk's mass with inertia, the liquid column, the tolerances, velocity
  /// errors weighed by the disk's angular frequency sqrt(k/m) at the model's
  /// state (1 rad/s without inertia), and the load on the pieces of @p
  /// waveform (zero voltage before t = 0). @p scene and @p waveform must
  /// outlive the step.
  std::unique_ptr<EsdirkStep> make_esdirk_step(TransientModel &model, const Scene &scene,
                                               const TimeSettings &settings,
                                               const Waveform     &waveform);

  class TimeStepper
  {
  public:
    TimeStepper(const Scene &scene, TransientModel &model, const SteppingSettings &quasi_static,
                const TimeSettings &settings);

    /// A postprocessor for both parts of the run (made once for each).
    using PostprocessorFactory = std::function<std::unique_ptr<Postprocessor>()>;
    void add_postprocessor(const PostprocessorFactory &make);

    std::function<void(const StepSummary &)> on_step;
    std::function<void(const OnsetRecord &)> on_onset;
    /// Whether the step being reported should be written with its fields:
    /// the quasi-static steps, the start, the onset, every breakpoint of the
    /// waveform and the end, and every fields_interval of time.
    bool fields_wanted() const;
    /// Fields of the step being reported (valid during on_step).
    const StepFields &step_fields();

    RunResult run();

    /// After run(): the time reached and the disk's state there.
    double              time() const { return t_now; }
    const InertiaState &inertia_state() const { return motion; }

    /// The largest step for the waveform: max_step, and for a sine under an
    /// ESDIRK method at most 1/16 of its period (s).
    static double largest_step(const TimeSettings &settings);

  private:
    const Scene                       scene;
    TransientModel                   &model;
    SteppingSettings                  quasi_static;
    TimeSettings                      settings;
    std::vector<PostprocessorFactory> factories;
    std::vector<std::unique_ptr<Postprocessor>> postprocessors;
    class TimeColumns;
    TimeColumns *time_columns = nullptr;

    /// The energy budget since the start of the time integration.
    struct EnergyAccount
    {
      EnergyBudget last;              ///< at the last accepted step
      double       stored_start = 0.; ///< stored energy at the start
      double       work = 0., dissipated = 0.;
    };
    /// The unknowns of the last two accepted steps' starts, for the predictor.
    struct History
    {
      ModelState older, oldest;
      double     dt_older = 0., dt_oldest = 0.;
    };
    /// A step's accepted start and end.
    struct StepEnds
    {
      ModelState   state0, state1;
      InertiaState motion0, motion1;
    };

    /// The ESDIRK path: its step, the state at t_now (with the rates the
    /// next step starts from) and the acceptance of its steps by their
    /// error estimate (with the PI controller's memory).
    std::unique_ptr<EsdirkStep>     esdirk;
    TimePoint                       point;
    std::unique_ptr<StepAcceptance> acceptance;
    double                          largest_voltage = 0.;

    LoadStepper                      *quasi_static_stepper = nullptr;
    std::shared_ptr<const StepFields> reported_fields;
    RunResult                         result;
    bool                              wants_fields = false;
    double                            t_now = 0.;
    double                            next_fields_time = 0.;
    InertiaState                      motion;
    EnergyAccount                     energy;
    History                           history;

    /// The static stability eigenvalue in the time stage: without inertia only.
    bool time_stage_stability() const { return quasi_static.stability_check && !settings.inertia; }
    LoadState           load_at(double t) const;
    std::vector<double> voltages_at(double t) const;
    bool                run_quasi_static();
    StepSummary         start_time_stage();
    StepControlSettings step_control() const;
    bool        next_step(StepController &control, double breakpoint, double &t_next, double &h);
    bool        take_step(StepController &control, double breakpoint, StepSummary &previous);
    double      initial_step() const;
    void        start_esdirk();
    bool        take_esdirk_step(StepController &control, double breakpoint,
                                 StepSummary &previous);
    bool        reject_esdirk_step(StepController &control, double h, const SolveReport &solved);
    void        accept_esdirk_step(double h);
    /// After an accepted step of length h from ends.state0: the columns, the
    /// rows and the onset search (with @p step_from_start, which leaves the
    /// model and motion at a fraction of the step), common to both paths.
    void        finish_step(StepEnds &ends, double h, double t_next, double breakpoint,
                            double volume_mass, unsigned int iterations,
                            const std::function<bool(double)> &step_from_start,
                            StepSummary &previous);
    void        finish_run();
    SolveReport attempt_step(const ModelState &state0, const InertiaState &motion0, double h);
    /// One implicit step from the accepted state (model, motion) at t to
    /// t + dt; on success the new state is accepted and motion updated.
    SolveReport advance(double t, double dt, InertiaState &state);
    void        accept_step(double t_next);
    void        locate_onset(const StepEnds &ends, double h, double s2_start, double s2_end,
                             const std::function<bool(double)> &step_from_start);
    std::string no_equilibrium_message(double t_next, unsigned int cutbacks,
                                       const std::string &why) const;
    double      water_column_mass(const InertiaState &m) const;
    double      kinetic_energy(double volume_mass) const;
    void        set_columns(double t, double volume_mass);
    void        report(const StepSummary &summary, unsigned int iterations);
    StepSummary evaluate(double t);
  };
} // namespace cdea
