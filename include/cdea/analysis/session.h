#pragma once
// In-process runs, for the Python module and other programs that drive cdea
// without a process per run: the parameters from a file or from prm text with
// overrides, a run of `cdea run`, `cdea shoot` or `cdea sweep` whose results
// stay in memory (nothing is written), and on request the results file the
// command writes. The runs are the commands' own: the same input checks, model
// set-up, load stepper and postprocessors (add_run_postprocessors() is the one
// list of the run's own), so that a step kept here is the step the command
// writes.

#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/model/output_fields.h>
#include <cdea/model/records.h>
#include <cdea/model/scene.h>
#include <cdea/solver/load_stepper.h>
#include <cdea/solver/time_stepper.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  class ResultsFile;

  /// The model of a run: `cdea run` (finite elements) or `cdea shoot`.
  enum class RunMethod
  {
    finite_elements,
    shooting
  };

  /// The input of a run: validated parameters, their scene, and every
  /// parameter as text (for the results file).
  struct RunInput
  {
    Parameters  parameters;
    Scene       scene;
    std::string text;
  };

  /// The input as `cdea run` or `cdea shoot` reads it: parameters, scene and
  /// Reservoir checks; for the shooting model also the FE-only options
  /// refused and the voltage path followed by load stepping (@p note, if
  /// given, receives the line the command prints when that changes the
  /// Continuation). Throws InputError with the message the command prints.
  RunInput read_run_input(const ParameterInput &input, RunMethod method,
                          std::string *note = nullptr);

  /// Refuses the options only the FE model has (water load, relaxed law) for
  /// the command @p command ("shoot", "compare"): throws InputError.
  void require_shooting_options(const Parameters &p, const std::string &command);

  /// @p p with the voltage path followed by load stepping, as the shooting
  /// model does; @p note receives a line for the user if that changed the
  /// Continuation (else it is left empty).
  Parameters load_stepping_parameters(const Parameters &p, const std::string &command,
                                      std::string &note);

  /// The postprocessors of `cdea run` (quasi-static and in time) and `cdea
  /// shoot` beyond the steppers' standard ones: the enclosed volume (with the
  /// Reservoir's level tube) and the check for non-physical states.
  std::vector<TimeStepper::PostprocessorFactory> run_postprocessors(const Parameters &p,
                                                                    const Scene      &scene);

  /// Registers run_postprocessors() with @p stepper.
  void add_run_postprocessors(LoadStepper &stepper, const Parameters &p, const Scene &scene);
  void add_run_postprocessors(TimeStepper &stepper, const Parameters &p, const Scene &scene);

  /// Writes the /summary attributes @p attributes (doubles; rows == 0: 1D).
  void write_summary_attributes(ResultsFile &file, const std::vector<SummaryAttribute> &attributes);

  /// A run kept in memory.
  struct RunRecord
  {
    std::string method; ///< "finite elements", "shooting" or "finite elements in time"
    /// Root attributes of the results file besides method and parameters.
    std::vector<std::pair<std::string, std::string>> root_attributes;
    /// A time run: its file has no limit-point attributes, and /steps groups
    /// for some rows only (the others' fields are empty here).
    bool         time_run = false;
    std::string  parameters; ///< every parameter (root attribute)
    unsigned int n_rings = 0;
    std::string  results_path; ///< where the command would write the results
    std::vector<StepSummary>   steps;  ///< one per converged step
    std::vector<StepFields>    fields; ///< the fields of each step
    /// Completed or why not, onset, limit points, breakdown, counts. A run
    /// that stopped on an error says so here ("error: ...").
    RunResult                result;
    std::vector<std::string> notes;       ///< what the command prints besides (e.g. load stepping)
    double                   seconds = 0.; ///< wall time of the load stages
  };

  /// The load stages of @p input with the model of @p method (a time run if
  /// Time/Enabled), every converged step kept; nothing is printed or written.
  RunRecord run_in_memory(const RunInput &input, RunMethod method);

  /// Runs @p run (a stepper whose on_step fills @p record) into
  /// record.result and record.seconds; an error ends the run as incomplete
  /// with its message, and the steps so far stay.
  void run_keeping_steps(RunRecord &record, const std::function<RunResult()> &run);

  /// Writes @p record through ResultsFile as the command writes it: root
  /// attributes, /summary with every column and attribute, /steps. Throws
  /// std::runtime_error naming the path if the file cannot be written.
  void write_run(const RunRecord &record, const std::string &path);


  /// What main()'s MpiSession sets for the process, for a process without
  /// one (the Python interpreter): deal.II limited to one thread. MPI is left
  /// alone; a feature that needs it starts it (mpi::ensure_initialized()).
  void prepare_in_process_runs();
} // namespace cdea
