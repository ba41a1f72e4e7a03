#pragma once
// In-process runs, for the Python module and other programs that drive cdea
// without a process per run: a run of `cdea run` (in time too) or `cdea
// shoot` whose results stay in memory (nothing is printed or written) and,
// on request, the results file the command writes (write_run()). The runs are
// the commands' own: the same input checks (run_input.h), model set-up and
// postprocessors (run_setup.h), so that a step kept here is the step the
// command writes.

#include <cdea/analysis/run_input.h>
#include <cdea/analysis/run_record.h>

namespace cdea
{
  /// The load stages of @p input with the model of @p method (a time run if
  /// Time/Enabled), every converged step kept; nothing is printed or written.
  RunRecord run_in_memory(const RunInput &input, RunMethod method);

  /// What main()'s MpiSession sets for the process, for a process without
  /// one (the Python interpreter): deal.II limited to one thread. MPI is left
  /// alone; a feature that needs it starts it (mpi::ensure_initialized()).
  void prepare_in_process_runs();
} // namespace cdea
