// `cdea fit` with Calibration/Candidate models (commands/fit_material.cc
// hands it here): every candidate fitted to the material tests and once per
// file left out (design/model_selection.h), one line per fit, the table of
// models, per file the rms residuals (fitted on every file and held out),
// every model's constants with standard errors, and the verdict; then
// <Base name>_models.h5 with the recommended model's <Base name>_fit.h5 and
// _fit.prm, the three replaced together.

#include <cdea/base/format.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/fit_material.h>
#include <cdea/design/model_selection.h>
#include <cdea/input/parameters.h>
#include <cdea/model/quantities_model_selection.h>
#include <cdea/output/product_file.h>
#include <cdea/output/product_table.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <numeric>

namespace cdea
{
  namespace
  {
    namespace q = model_selection_quantity;

    std::vector<std::size_t> all_rows(const std::size_t n)
    {
      std::vector<std::size_t> rows(n);
      std::iota(rows.begin(), rows.end(), 0);
      return rows;
    }

    /// The table of models, then per file the rms of the fit on every file
    /// and the held-out one (relative), then every model's constants.
    void print_selection(const Product &product, const std::vector<MaterialTestData> &tests)
    {
      const ProductGroup &models = product.at("/models");
      const std::size_t   n      = models.at(q::model).size();
      std::cout << "\nfiles:";
      for (std::size_t i = 0; i < tests.size(); ++i)
        std::cout << "  " << i + 1 << " " << tests[i].name;
      std::cout << '\n';
      std::vector<TableColumn> columns{{&q::model, "model", 14, CellStyle::text, 14},
                                       {&q::constants, "k", 4, CellStyle::integer},
                                       {&q::rss, "RSS (kPa^2)", 13, CellStyle::number, 5},
                                       {&q::aic, "AIC", 10, CellStyle::fixed, 1},
                                       {&q::bic, "BIC", 10, CellStyle::fixed, 1},
                                       {&q::held_out_error, "held-out", 10, CellStyle::number, 3}};
      for (std::size_t i = 0; i < tests.size(); ++i)
        {
          const std::string f = std::to_string(i + 1);
          columns.push_back({&q::rms, "rms " + f + " (kPa)", 13, CellStyle::number, 3, "", i});
          columns.push_back({&q::relative_rms, "rel. " + f, 9, CellStyle::number, 3, "", i});
          columns.push_back({&q::held_out_relative_rms, "held-out " + f, 12, CellStyle::number,
                             3, "", i});
        }
      print_table(std::cout, models, columns, all_rows(n));
      const ProductGroup &constants = product.at("/constants");
      std::cout << "\nconstants (SI: Pa, s, 1):\n";
      print_table(std::cout, constants,
                  {{&q::constant_model, "model", 6, CellStyle::integer},
                   {&q::constant_name, "constant", 30, CellStyle::text, 30},
                   {&q::value, "value", 14, CellStyle::number, 6},
                   {&q::standard_error, "std. error", 14, CellStyle::number, 3}},
                  all_rows(constants.at(q::constant_name).size()));
      std::cout << "(model: the row of the table above, from 0)\n";
    }
  } // namespace

  int run_model_selection(Invocation &invocation, const std::vector<CandidateSetup> &setups,
                          const std::vector<MaterialTestData> &fitted,
                          const std::vector<double>           &weights,
                          const std::vector<MaterialTestData> &predicted,
                          const MaterialFitSettings           &settings)
  {
    const auto start = std::chrono::steady_clock::now();
    std::cout << "cdea " << CDEA_VERSION << " fit: " << setups.size() << " candidate models, "
              << fitted.size() << " material test(s), each fitted on every file and "
              << (fitted.size() > 1 ? "once per file left out" : "(one file) on it alone") << '\n';
    ModelSelection selection = select_model(
      setups, fitted, weights, settings,
      [](const std::string &model, const std::string &left_out, const FitResult &r) {
        std::cout << std::left << std::setw(14) << model << std::right
                  << (left_out.empty() ? std::string("every file") : "without " + left_out)
                  << ": " << (r.converged ? "converged" : "NOT converged") << ", rms "
                  << format_number(units::kPa.from_si(r.rms), 4) << " kPa, " << r.iterations
                  << " iterations" << std::endl;
      });
    const Product models = model_selection_product(selection, fitted);
    print_selection(models, fitted);
    for (const std::string &w : selection.warnings)
      std::cout << "WARNING: " << w << '\n';
    std::cout << "\nrecommended: " << selection.models[selection.recommended].setup.candidate.name()
              << (selection.decided ? "" : " (the data cannot decide)") << ": " << selection.verdict
              << '\n';
    const ModelAssessment &best = selection.models[selection.recommended];
    std::cout << "\n" << best.setup.candidate.name() << " on every file:\n";
    // Its _fit.prm is the prm made this candidate: its law, branches and free constants.
    for (const auto &entry : best.setup.overrides)
      invocation.input.overrides.push_back(entry);
    return finish_material_fit(invocation, best.setup.base, best.setup.fit, best.fit, fitted,
                               weights, predicted, start, &models);
  }
} // namespace cdea
