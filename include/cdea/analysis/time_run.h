#pragma once
// Time runs (Time/Enabled = true, doc/time.md): the FE model through the
// quasi-static pre-stretch and weight, then in time through the voltage
// waveform. One set-up for `cdea run FILE.prm` (run_time(), which prints and
// writes as it goes) and for the in-process run (time_run_in_memory(), which
// keeps every step as the results file holds it).

#include <cdea/analysis/run_input.h>
#include <cdea/analysis/run_record.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/solver/time_stepper.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  /// The model and stepper of a time run, with every postprocessor of the
  /// run registered, and the root attributes of its results file.
  struct TimeRunSetup
  {
    TimeSettings                                     settings;
    std::unique_ptr<MembraneModel>                   model;
    std::unique_ptr<TimeStepper>                     stepper;
    std::vector<std::pair<std::string, std::string>> root_attributes;
  };

  TimeRunSetup set_up_time_run(const Parameters &p, const Scene &scene);

  /// `cdea run` of a time run: prints the steps and writes the results file.
  /// Returns the process exit code (ExitCode).
  int run_time(const RunInput &input);

  /// The same run kept in memory (nothing printed or written): one row per
  /// /summary row, with the fields of the rows the file gives a /steps group
  /// (empty StepFields for the others).
  RunRecord time_run_in_memory(const RunInput &input);
} // namespace cdea
