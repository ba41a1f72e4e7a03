#pragma once
// The quasi-static run of `cdea run` and `cdea shoot`: the model along the
// load stages, every converged step printed as a table row and written to the
// results file as it comes (RunOutput), the onset, limit points and breakdown
// announced when found, the ParaView output if asked for, and the final state
// printed at the end.

#include <cdea/analysis/run_input.h>
#include <cdea/model/equilibrium_model.h>

namespace cdea
{
  /// Drives @p model (of @p method) through the load stages of @p input,
  /// printing and writing results_path(input.parameters, method). Returns
  /// the process exit code (ExitCode).
  int run_quasi_static(EquilibriumModel &model, const RunInput &input, RunMethod method);
} // namespace cdea
