#pragma once
// Drives a TransientModel through time (doc/time.md):
//
//  1. pre-stretch and dead load quasi-statically (LoadStepper), with the
//     material's internal variables relaxed (network B carries nothing) -- or,
//     with a rest time, relaxed in the pre-stretched film and then held while
//     the weight is hung;
//  2. with a rest time, the weight held that long at zero voltage (creep);
//  3. the voltage waveform from t = 0 to its end in implicit steps of at most
//     `max_step`, landing on every breakpoint of the waveform: each step solves
//     equilibrium with the internal variables' update (backward Euler or the
//     trapezoidal rule) and, if on, the Newmark inertia of the disk (and the
//     pump's water column), halving the step where Newton fails and growing
//     it back after easy steps (StepController, numerics/step_control.h). A
//     converged step's internal variables are accepted and the disk's
//     velocity and acceleration updated:
//       a1 = (z1 - z_pred) / (beta dt^2),  v1 = v0 + dt ((1 - gamma) a0 + gamma a1).
//
// Every converged step goes through the same postprocessors as the
// quasi-static run, plus the time columns (time, disk velocity, energy
// budget), and to on_step. The first step in which the smallest hoop stress
// becomes negative is searched for the onset time (bracketed root in the
// step's fraction), reported as a step of its own.

#include <cdea/model/scene.h>
#include <cdea/numerics/step_control.h>
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
    TimeScheme   scheme       = TimeScheme::backward_euler;
    bool         inertia      = true;
    double       newmark_beta  = 0.25; ///< average acceleration: second order,
    double       newmark_gamma = 0.5;  ///< no numerical damping
    /// Time (s) the weight hangs at zero voltage before t = 0; infinity: the
    /// film starts relaxed.
    double rest_time = std::numeric_limits<double>::infinity();
    /// Fields wanted every this much time besides the breakpoints (0: not).
    double fields_interval = 0.;
    /// The pump's water column (transient_model.h); density 0: none.
    double water_density = 0.; ///< kg/m^3
    double water_volume  = 0.; ///< m^3
    double tube_area     = 1.; ///< m^2
  };

  /// The mechanical state of the disk (and the water column) between steps.
  struct InertiaState
  {
    double z = 0., v = 0., a = 0.;          ///< disk: m, m/s, m/s^2
    double V = 0., V_dot = 0., V_ddot = 0.; ///< enclosed volume and its rates
  };

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
    bool        take_step(StepController &control, double breakpoint, StepSummary &previous);
    SolveReport attempt_step(const ModelState &state0, const InertiaState &motion0, double h);
    /// One implicit step from the accepted state (model, motion) at t to
    /// t + dt; on success the new state is accepted and motion updated.
    SolveReport advance(double t, double dt, InertiaState &state);
    void        accept_step(double t_next);
    void        locate_onset(const StepEnds &ends, double h, double s2_start, double s2_end);
    std::string no_equilibrium_message(double t_next, unsigned int cutbacks,
                                       const std::string &why) const;
    double      water_column_mass(const InertiaState &m) const;
    double      kinetic_energy(double volume_mass) const;
    void        set_columns(double t, double volume_mass);
    void        report(const StepSummary &summary, unsigned int iterations);
    StepSummary evaluate(double t);
  };
} // namespace cdea
