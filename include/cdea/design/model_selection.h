#pragma once
// Model selection for material tests (doc/materials.md, "Choosing a
// model"): every candidate of Calibration/Candidate models (a law without
// internal variables and a number of viscous branches) fitted to the tests
// jointly as the single fit does (material_fit.h: data-driven start, several
// starts), with its information criteria for Gaussian residuals,
//   AIC = n ln(RSS / n) + 2 k,   BIC = n ln(RSS / n) + k ln n,
// (n samples, k free constants, RSS = sum w r^2 in kPa^2), and its
// leave-one-file-out error: fitted to all files but one, that one predicted.
// The recommended model has the lowest mean held-out relative rms; where
// the second best is within the spread (the sampling error of the two
// held-out errors, an rms of n Gaussian residuals varying by rms / sqrt(2 n),
// or the standard error over the files of their paired differences if
// larger), or there is one file, the data cannot decide, and the verdict
// says so (and names the lowest BIC).

#include <cdea/design/material_fit.h>
#include <cdea/input/parameter_input.h>

#include <functional>
#include <utility>
#include <string>
#include <vector>

namespace cdea
{
  /// One candidate: a law of Material/Model without internal variables
  /// and the number of branches of network B beside it (0: the elastic law
  /// alone; from 1, Material/Model = viscoelastic with network A's Gent law).
  struct CandidateModel
  {
    std::string  law;
    unsigned int branches = 0;
    std::string  name() const { return law + " " + std::to_string(branches); }
  };

  /// Calibration/Candidate models: "LAW N, LAW N, ..." (empty: none).
  /// InputError naming the entry, the item and what is allowed (the laws
  /// without internal variables, branches 0 to 20, and branches only with
  /// 'elastic'); a model given twice is refused.
  std::vector<CandidateModel> candidate_models(const std::string &text);

  /// A candidate ready to fit: its scene and free constants (the law's own:
  /// shear modulus, Jlim where the law has it, the law's constants; every
  /// branch's modulus and relaxation time).
  struct CandidateSetup
  {
    CandidateModel candidate;
    Scene          base;
    FitSettings    fit;
    /// The entries that make the prm this candidate ("Material/Model",
    /// the branch lists, "Calibration/Free parameters", ...), in order: the
    /// recommended model's _fit.prm is written with them.
    std::vector<std::pair<std::string, std::string>> overrides;
  };

  /// @p input with the candidate's law and branches set (Material/Model,
  /// the branch lists, Calibration/Free parameters), read as every command
  /// reads its parameters.
  CandidateSetup candidate_setup(const ParameterInput &input, const CandidateModel &candidate);

  /// One candidate's fit and its measures.
  struct ModelAssessment
  {
    CandidateSetup            setup;
    MaterialFitResult         fit;      ///< on every file
    double                    rss = 0.; ///< sum w r^2 (Pa^2)
    std::size_t               samples = 0;
    double                    aic = 0., bic = 0.;
    /// Per file: fitted to the others, this one predicted (rms NaN: not
    /// computed, with one file, too few samples, or a fit that failed).
    std::vector<TestMeasures> held_out;
    double                    held_out_error = 0.; ///< mean relative held-out rms (NaN: none)
  };

  struct ModelSelection
  {
    std::vector<ModelAssessment> models;
    std::size_t                  recommended = 0;
    /// false: one file, or the second best within the spread.
    bool        decided = false;
    double      spread  = 0.; ///< of the two best's held-out errors (NaN: one file)
    std::string verdict;      ///< the recommendation in words
    std::vector<std::string> warnings;
  };

  /// Fits every candidate of @p setups to @p tests (with @p weights, empty:
  /// 1 each), then once per file without it, and recommends. @p settings
  /// gives the starts and time steps (its free parameters are the
  /// candidates'). @p progress is told of each fit: model, the file held
  /// out ("" for the fit on all) and its cost.
  ModelSelection select_model(
    const std::vector<CandidateSetup> &setups, const std::vector<MaterialTestData> &tests,
    const std::vector<double> &weights, const MaterialFitSettings &settings,
    const std::function<void(const std::string &, const std::string &, const FitResult &)>
      &progress = {});

  /// The recommendation from the assessed models (select_model()'s last step).
  void recommend(ModelSelection &selection);

  /// The product of a model selection (model/quantities_model_selection.h),
  /// in SI; written to <Base name>_models.h5.
  Product model_selection_product(const ModelSelection                &selection,
                                  const std::vector<MaterialTestData> &tests);
} // namespace cdea
