#pragma once
// The model and the postprocessors of a run, set up as the parameters say: one
// set-up for the commands (`cdea run`, `shoot`, `compare`), the time run and
// the in-process runs, so that a step kept in memory is the step a command
// writes.

#include <cdea/analysis/run_input.h>
#include <cdea/fe/error_estimate.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/solver/load_stepper.h>
#include <cdea/solver/time_stepper.h>

#include <memory>
#include <vector>

namespace cdea
{
  /// An FE model of @p scene set up as the parameters say (discretization,
  /// Newton, linear solver, the law of Material/Model, relaxed law, the load
  /// terms the parameters switch on).
  std::unique_ptr<MembraneModel> make_fe_model(const Parameters &p, const Scene &scene);
  /// The same on @p discretization in place of the parameters' (the error
  /// estimate's richer model).
  std::unique_ptr<MembraneModel> make_fe_model(const Parameters &p, const Scene &scene,
                                               const FeDiscretization &discretization);

  /// The error estimate of a quasi-static run of @p method (finite elements
  /// with Discretization/Error estimate on), on models set up as the run's;
  /// null otherwise.
  std::unique_ptr<RunErrorEstimate> make_error_estimate(const Parameters &p, const Scene &scene,
                                                        RunMethod method);

  /// The model of a quasi-static run of @p method (finite elements or
  /// shooting) for @p input.
  std::unique_ptr<EquilibriumModel> make_model(const RunInput &input, RunMethod method);

  /// The postprocessors of `cdea run` (quasi-static and in time) and `cdea
  /// shoot` beyond the steppers' own: those registered to run on_runs
  /// (solver/postprocessors.h; the enclosed volume with the Reservoir's level
  /// tube, the check for non-physical states).
  std::vector<TimeStepper::PostprocessorFactory> run_postprocessors(const Parameters &p,
                                                                    const Scene      &scene);

  /// Registers run_postprocessors() with @p stepper.
  void add_run_postprocessors(LoadStepper &stepper, const Parameters &p, const Scene &scene);
  void add_run_postprocessors(TimeStepper &stepper, const Parameters &p, const Scene &scene);
} // namespace cdea
