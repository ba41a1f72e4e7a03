#pragma once
// `cdea fit FILE.prm A.csv [B.csv ...] [--predict C.csv ...]` with material
// tests (design/material_test_data.h): the part of the fit command
// (commands/fit.cc) for homogeneous test histories, fitted jointly
// (design/material_fit.h), with files evaluated but not fitted after
// --predict.

#include <cdea/commands/fit_viscous.h>

#include <chrono>
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

  struct CandidateSetup;
  struct FitSettings;
  struct MaterialFitResult;
  struct MaterialFitSettings;
  struct MaterialTestData;
  struct Scene;
  class Product;

  /// How a material-test fit ends (from @p start): the fitted values, per
  /// file (@p fitted with @p weights, then @p predicted evaluated) its rms,
  /// and <Base name>_fit.h5 and _fit.prm written, with <Base name>_models.h5
  /// (@p models, a model selection's) if given, replaced together.
  int finish_material_fit(Invocation &invocation, const Scene &base, const FitSettings &settings,
                          const MaterialFitResult &r, const std::vector<MaterialTestData> &fitted,
                          const std::vector<double>                   &weights,
                          const std::vector<MaterialTestData>         &predicted,
                          const std::chrono::steady_clock::time_point &start,
                          const Product                               *models = nullptr);

  /// `cdea fit` with Calibration/Candidate models (commands/
  /// fit_material_models.cc): every candidate of @p setups fitted and
  /// compared (design/model_selection.h), the table printed, the
  /// recommended model's fit ended as finish_material_fit() with the
  /// selection's product.
  int run_model_selection(Invocation &invocation, const std::vector<CandidateSetup> &setups,
                          const std::vector<MaterialTestData> &fitted,
                          const std::vector<double>           &weights,
                          const std::vector<MaterialTestData> &predicted,
                          const MaterialFitSettings           &settings);
} // namespace cdea
