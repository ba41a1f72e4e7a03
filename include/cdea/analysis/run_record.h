#pragma once
// A run kept in memory (the in-process runs of the Python module), how a run
// ended as its file says it, and the writing of a kept run as the command
// writes it.

#include <cdea/analysis/run_input.h>
#include <cdea/model/records.h>
#include <cdea/model/output_fields.h>
#include <cdea/model/run_stream.h>
#include <cdea/solver/load_stepper.h>

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  class ResultsFile;

  /// How a run (or a design map) ended: the start of the root attribute
  /// run_status of its file.
  enum class RunStatus
  {
    complete,
    stopped
  };

  /// "complete", "stopped".
  std::string to_string(RunStatus status);

  /// The root attribute run_status of a run's results file: "complete", or
  /// "stopped after step N: <why>" (N the last of @p n_steps steps kept).
  std::string run_status(const RunResult &result, std::size_t n_steps);


  /// A run kept in memory: a sink of its product stream (model/run_stream.h).
  struct RunRecord : RunSink
  {
    RunMethod method = RunMethod::finite_elements; ///< the root attribute `method`
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
    ProductGroup attributes{"/summary"}; ///< the /summary attributes as streamed
    /// Completed or why not, onset, limit points, breakdown, counts. A run
    /// that stopped on an error says so here ("error: ...").
    RunResult                result;
    std::vector<std::string> notes;       ///< what the command prints besides (e.g. load stepping)
    double                   seconds = 0.; ///< wall time of the load stages

    void append(const StepSummary &summary, const StepFields &step_fields) override;
    void set_summary_attributes(const ProductGroup &values) override;
  };

  /// Runs @p run (a stepper whose on_step fills @p record) into
  /// record.result and record.seconds; an error ends the run as incomplete
  /// with its message, and the steps so far stay.
  void run_keeping_steps(RunRecord &record, const std::function<RunResult()> &run);

  /// Writes @p record through ResultsFile as the command writes it: root
  /// attributes, /summary with every column and attribute, /steps (the
  /// record's stream again, into the file). Throws std::runtime_error naming
  /// the path if the file cannot be written.
  void write_run(const RunRecord &record, const std::string &path);
} // namespace cdea
