#pragma once
// The sub-commands of the cdea program. Each returns the process exit code.

#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/options.h>
#include <cdea/solver/load_stepper.h>

#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  struct Parameters;

  /// Settings of the solver pieces, from the parsed parameters.
  SteppingSettings stepping_settings(const Parameters &p);
  FeDiscretization fe_discretization(const Parameters &p);
  NewtonSettings   newton_settings(const Parameters &p);
  shooting::ShootingOptions shooting_options(const Parameters &p);

  /// An FE model of @p scene set up as the parameters say (discretization,
  /// Newton, linear solver, relaxed law, water load).
  std::unique_ptr<MembraneModel> make_fe_model(const Parameters &p, const Scene &scene);

  /// Exit codes: 0 success, 1 bad input or unwritable output (nothing is
  /// written), 2 the run stopped before the end of its voltage path or could
  /// not write all of its results (signal, full disk, vanished directory;
  /// the messages say where the converged steps are).
  enum ExitCode : int
  {
    exit_success      = 0,
    exit_input_error  = 1,
    exit_not_complete = 2
  };

  /// `cdea run FILE.prm`: the FE model along the load stages.
  int run_fe(const std::string &prm_file);

  /// `cdea shoot FILE.prm`: the shooting model along the same load stages.
  int run_shooting(const std::string &prm_file);

  /// `cdea compare FILE.prm`: both models, and their differences.
  int compare(const std::string &prm_file);

  /// `cdea recover FILE.h5`: the results of a killed run that was writing
  /// FILE.h5, rebuilt from its journal into FILE.h5 (or, if that exists,
  /// FILE.recovered.h5). 0 done, 1 nothing to recover or the run still
  /// going, 2 the file cannot be written.
  int recover(const std::string &results_file);

  std::string usage();
} // namespace cdea
