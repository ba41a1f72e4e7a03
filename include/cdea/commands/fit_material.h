#pragma once
// `cdea fit FILE.prm A.csv [B.csv ...] [--predict C.csv ...]` with material
// tests (design/material_test_data.h): the part of the fit command
// (commands/fit.cc) for homogeneous test histories, fitted jointly
// (design/material_fit.h), with files evaluated but not fitted after
// --predict.

#include <cdea/commands/fit_viscous.h>

#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  /// Whether the data files among @p arguments (those after FILE.prm, but
  /// the word --predict) are material tests: true if all are, false for one
  /// file of another kind without --predict (the fits of one file); an
  /// InputError for a mix, or for several files or --predict with data of
  /// another kind.
  bool material_test_files(const std::vector<std::string> &arguments);

  /// The job of a material-test fit: check() reads the settings and every
  /// file, run() fits, prints and writes as the other fits do.
  std::unique_ptr<ViscousFitJob> material_fit_job();
} // namespace cdea
