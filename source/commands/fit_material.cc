// The material-test fits of `cdea fit` (commands/fit.cc hands them here when
// every data file is a material test): the files before --predict fitted
// jointly, each with the weight of its '# weight' line, those after it
// evaluated at the fitted values; each iteration printed, the fitted values
// with their standard errors and correlations, per file its kind, samples
// and rms residual (kPa and relative to its largest |stress|),
// <Base name>_fit.h5 and <Base name>_fit.prm. Exit codes as every fit.

#include <cdea/base/format.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/fit_material.h>
#include <cdea/design/fit_data.h>
#include <cdea/design/material_fit.h>
#include <cdea/design/model_selection.h>
#include <cdea/input/parameters.h>
#include <cdea/output/safe_files.h>
#include <cdea/input/validation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    const std::string predict_option = "--predict";

    /// The data files of the arguments (after FILE.prm): those to fit and
    /// those after --predict; InputError for a misplaced --predict.
    std::pair<std::vector<std::string>, std::vector<std::string>>
    fit_and_predict_files(const std::vector<std::string> &arguments)
    {
      std::vector<std::string> fit, predict;
      bool                     predicting = false;
      for (std::size_t i = 1; i < arguments.size(); ++i)
        if (arguments[i] == predict_option)
          {
            if (predicting)
              throw InputError("--predict is given twice: list every file to predict after one "
                               "--predict");
            predicting = true;
          }
        else
          (predicting ? predict : fit).push_back(arguments[i]);
      if (fit.empty())
        throw InputError("no data file to fit before --predict: cdea fit FILE.prm A.csv "
                         "[B.csv ...] [--predict C.csv ...]");
      if (predicting && predict.empty())
        throw InputError("--predict needs at least one data file after it");
      return {fit, predict};
    }

    class MaterialFit final : public ViscousFitJob
    {
    public:
      void check(Invocation &invocation) override
      {
        const Parameters &p      = invocation.parameters;
        const auto [fit, predict] = fit_and_predict_files(invocation.arguments);
        base                      = p.scene();
        for (const CandidateModel &c : candidate_models(p.calibration.candidate_models_text))
          candidates.push_back(candidate_setup(invocation.input, c));
        if (candidates.empty())
          settings.fit = free_parameter_settings(p);
        else if (const std::string models = p.results_path("_models");
                 !refused_names(models).empty())
          throw InputError("cannot write '" + models + "': " + refused_names(models));
        const TestSpecimen specimen = test_specimen(p);
        for (const std::string &file : fit)
          {
            fitted.push_back(read_material_test(file, specimen));
            settings.test_weights.push_back(material_test_weight(file));
          }
        for (const std::string &file : predict)
          predicted.push_back(read_material_test(file, specimen));
        std::size_t samples = 0;
        for (const MaterialTestData &t : fitted)
          samples += t.size();
        for (const CandidateSetup &c : candidates)
          if (samples < c.fit.free.size())
            throw InputError(std::to_string(samples) + " samples in the files to fit for the " +
                             std::to_string(c.fit.free.size()) + " constants of candidate '" +
                             c.candidate.name() + "' (Calibration/Candidate models)");
        if (samples < settings.fit.free.size())
          throw InputError(std::to_string(samples) + " samples in the files to fit for " +
                           std::to_string(settings.fit.free.size()) +
                           " free parameters (Calibration/Free parameters)");
        // Refuses a free parameter the tests do not depend on (mass, ...).
        MaterialTestModel(base, fitted, settings.fit.free, settings.point);
      }

      int run(Invocation &invocation) override
      {
        if (!candidates.empty())
          return run_model_selection(invocation, candidates, fitted, settings.test_weights,
                                     predicted, settings);
        const auto start = std::chrono::steady_clock::now();
        print_banner();
        const MaterialFitResult r = fit_material_tests(
          base, fitted, settings, [&](unsigned int k, double cost, const std::vector<double> &v) {
            std::cout << std::setw(5) << k << std::setw(16) << format_number(cost, 8);
            for (const double x : v)
              std::cout << "  " << format_number(x, 8);
            std::cout << std::endl;
          });
        return finish_material_fit(invocation, base, settings.fit, r, fitted,
                                   settings.test_weights, predicted, start);
      }

    private:
      Scene                         base;
      MaterialFitSettings           settings;
      std::vector<CandidateSetup>   candidates; ///< Calibration/Candidate models
      std::vector<MaterialTestData> fitted, predicted;

      void print_banner() const
      {
        std::size_t samples = 0;
        for (const MaterialTestData &t : fitted)
          samples += t.size();
        std::cout << "cdea " << CDEA_VERSION << " fit: " << fitted.size() << " material test(s), "
                  << samples << " samples";
        if (!predicted.empty())
          std::cout << ", " << predicted.size() << " more to predict";
        std::cout << "; free:";
        for (const auto &f : settings.fit.free)
          std::cout << "  " << label(f);
        std::cout << "\n" << std::setw(5) << "iter" << std::setw(16) << "cost (kPa^2)"
                  << "  parameters (SI)\n";
      }
    };

    /// Per file: fitted or predicted, weight, samples, rms (kPa), largest
    /// |stress| (kPa), rms relative to it, and the kind.
  void print_files(const std::vector<MaterialTestOutcome> &outcomes)
    {
      std::size_t width = 4;
      for (const MaterialTestOutcome &o : outcomes)
        width = std::max(width, o.data->name.size());
      std::cout << std::left << std::setw(int(width) + 2) << "file" << std::setw(9) << "role"
                << std::right << std::setw(8) << "weight" << std::setw(9) << "samples"
                << std::setw(14) << "rms (kPa)" << std::setw(16) << "largest (kPa)"
                << std::setw(11) << "relative" << "  kind\n";
      for (const MaterialTestOutcome &o : outcomes)
        {
          const TestMeasures &m = o.measures;
          std::cout << std::left << std::setw(int(width) + 2) << o.data->name << std::setw(9)
                    << (o.fitted ? "fitted" : "predicted") << std::right << std::setw(8)
                    << format_number(o.weight, 4) << std::setw(9) << m.samples << std::setw(14)
                    << format_number(units::kPa.from_si(m.rms), 4) << std::setw(16)
                    << format_number(units::kPa.from_si(m.largest), 5) << std::setw(11)
                    << format_number(m.relative, 3) << "  "
                    << test_kind_name(o.data->history.kind) << '\n';
        }
    }

    /// What a data file holds, in words, for the refusal of a mix.
    std::string kind_words(const std::string &file)
    {
      if (is_material_test(file))
        return "a material test";
      switch (fit_data_kind(file))
        {
          case FitDataKind::dma:
            return "a DMA table";
          case FitDataKind::creep:
            return "a creep curve";
          default:
            return "displacement-voltage points";
        }
    }
  } // namespace

  bool material_test_files(const std::vector<std::string> &arguments)
  {
    std::vector<std::string> files;
    for (std::size_t i = 1; i < arguments.size(); ++i)
      if (arguments[i] != predict_option)
        files.push_back(arguments[i]);
    const bool  predicting = files.size() + 1 < arguments.size();
    if (files.empty())
      throw InputError("no data file: cdea fit FILE.prm A.csv [B.csv ...] [--predict C.csv ...]");
    std::size_t material   = 0;
    for (const std::string &file : files)
      material += is_material_test(file) ? 1 : 0;
    if (material == files.size() && !files.empty())
      return true;
    if (material == 0 && files.size() == 1 && !predicting)
      return false;
    for (const std::string &file : files)
      if (!is_material_test(file))
        throw InputError(file + " holds " + kind_words(file) +
                         (material > 0 ? ", the other files material tests: a fit of material "
                                         "tests together with data of another kind is not "
                                         "supported yet" :
                                         ": several data files and --predict are for material "
                                         "tests (uniaxial_stretch, equibiaxial_stretch, "
                                         "pure_shear_stretch or force_N columns); fit "
                                         "displacement points, creep curves and DMA tables one "
                                         "file at a time"));
    return false;
  }

  int finish_material_fit(Invocation &invocation, const Scene &base, const FitSettings &settings,
                          const MaterialFitResult &r, const std::vector<MaterialTestData> &fitted,
                          const std::vector<double>                            &weights,
                          const std::vector<MaterialTestData>                  &predicted,
                          const std::chrono::steady_clock::time_point          &start,
                          const Product                                        *models)
  {
    if (!r.fit.started)
      return fit_not_started(invocation, r.fit.status,
                             "change the start values in the parameter file; ");
    std::vector<std::string>               warnings = r.fit.warnings;
    const std::vector<MaterialTestOutcome> outcomes =
      material_test_outcomes(base, settings.free, r, fitted, weights, predicted, warnings);
    print_fitted_values(settings.free, r.fit);
    print_files(outcomes);
    std::cout << "weighted rms residual of the fitted files "
              << format_number(units::kPa.from_si(r.fit.rms), 4)
              << " kPa, condition number of the scaled Jacobian "
              << format_number(r.fit.condition, 3) << '\n';
    for (const auto &w : warnings)
      std::cout << "WARNING: " << w << '\n';
    std::cout << r.fit.iterations << " iterations of the best of " << r.starts.size()
              << " start(s), " << r.evaluations << " evaluations, " << std::setprecision(3)
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s\n";
    const Product product = material_fit_product(invocation.parameter_text, settings, r, outcomes);
    if (!models)
      return write_fit_files(invocation, base, settings.free, r.fit, product);
    return write_fit_files(invocation, base, settings.free, r.fit, product,
                           {{models, invocation.parameters.results_path("_models")}});
  }

  std::unique_ptr<ViscousFitJob> material_fit_job()
  {
    return std::make_unique<MaterialFit>();
  }
} // namespace cdea
