// The DMA and creep fits of `cdea fit` (commands/fit.cc hands them here by
// the data file's header): each iteration printed, the fitted values with
// their standard errors and correlations, the residuals, <Base name>_fit.h5
// and <Base name>_fit.prm. Exit codes as the fit of displacement points.

#include <cdea/base/format.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/fit_viscous.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/input/validation.h>
#include <cdea/model/quantities_fit.h>
#include <cdea/output/product_file.h>
#include <cdea/output/product_table.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    /// A parameter in the unit of the table (kPa for network A's modulus).
    double shown(const SceneParameter &p, const double value)
    {
      return p.kind == ParameterKind::shear_modulus ? units::kPa.from_si(value) : value;
    }

    std::string shown_label(const SceneParameter &p)
    {
      return p.kind == ParameterKind::shear_modulus ? "shear modulus (kPa)" : label(p);
    }

    class ViscousFit final : public ViscousFitJob
    {
    public:
      explicit ViscousFit(const FitDataKind kind)
        : kind(kind)
      {}

      void check(Invocation &invocation) override
      {
        const Parameters  &p    = invocation.parameters;
        const std::string &file = invocation.arguments.at(1);
        settings                = viscous_fit_settings(p, kind);
        std::size_t rows        = 0;
        if (kind == FitDataKind::dma)
          rows = 2 * (dma = read_dma_data(file)).size();
        else
          {
            const Scene scene = p.scene();
            creep = read_creep_data(file, scene.n_rings(), voltage_ceiling(scene));
            require_waveform_match(p, creep, file);
            rows = creep.size();
          }
        if (rows < settings.free.size())
          throw InputError(file + ": " + std::to_string(rows) + " observations for " +
                           std::to_string(settings.free.size()) +
                           " free parameters (Calibration/Free parameters)");
      }

      int run(Invocation &invocation) override
      {
        const Parameters &p     = invocation.parameters;
        const auto        start = std::chrono::steady_clock::now();
        print_banner(invocation.arguments.at(1));
        const auto progress = [&](unsigned int k, double cost, const std::vector<double> &v) {
          std::cout << std::setw(5) << k << std::setw(16) << format_number(cost, 8);
          for (std::size_t j = 0; j < v.size(); ++j)
            std::cout << "  " << format_number(shown(settings.free[j], v[j]), 8);
          std::cout << std::endl;
        };
        const FitResult r = kind == FitDataKind::dma ? fit_dma(p.scene(), dma, settings, progress) :
                                                       fit_creep(p, creep, settings, progress);
        if (!r.started)
          return fit_not_started(invocation, r.status, "");
        const Product product =
          kind == FitDataKind::dma ? dma_fit_product(invocation.parameter_text, dma, settings, r) :
                                     creep_fit_product(invocation.parameter_text, creep, settings, r);
        print_values(r);
        print_residuals(r, product);
        for (const auto &w : r.warnings)
          std::cout << "WARNING: " << w << '\n';
        std::cout << r.iterations << " iterations, " << r.evaluations << " evaluations, "
                  << std::setprecision(3)
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
                  << " s\n";
        return write_and_report(invocation, r, product);
      }

    private:
      const FitDataKind kind;
      FitSettings       settings;
      DmaData           dma;
      CreepData         creep;

      void print_banner(const std::string &file) const
      {
        std::cout << "cdea " << CDEA_VERSION << " fit: "
                  << (kind == FitDataKind::dma ? std::to_string(dma.size()) + " DMA rows" :
                                                 std::to_string(creep.size()) + " creep samples")
                  << " of " << file << "; free:";
        for (const auto &f : settings.free)
          std::cout << "  " << label(f);
        std::cout << "\n" << std::setw(5) << "iter" << std::setw(16)
                  << (kind == FitDataKind::dma ? "cost (kPa^2)" : "cost (mm^2)") << "  parameters\n";
      }

      void print_values(const FitResult &r) const { print_fitted_values(settings.free, r); }

      void print_residuals(const FitResult &r, const Product &product) const
      {
        using namespace fit_quantity;
        if (r.fitted.size() == 0)
          return;
        const bool          is_dma = kind == FitDataKind::dma;
        const ProductGroup &data   = product.at("/data");
        std::vector<std::size_t> rows(is_dma ? dma.size() : creep.size());
        for (std::size_t i = 0; i < rows.size(); ++i)
          rows[i] = i;
        std::cout << "residuals (model - measured):\n";
        if (is_dma)
          print_table(std::cout, data,
                      {{&dma_frequency, "frequency (Hz)", 16, CellStyle::number, 4},
                       {&dma_storage, "storage (kPa)", 16, CellStyle::fixed, 4},
                       {&dma_fitted_storage, "model", 11, CellStyle::fixed, 4},
                       {&dma_loss, "loss (kPa)", 13, CellStyle::fixed, 4},
                       {&dma_fitted_loss, "model", 11, CellStyle::fixed, 4}},
                      rows);
        else
          print_table(std::cout, data,
                      {{&creep_time, "time (s)", 14, CellStyle::number, 6},
                       {&creep_displacement, "measured (mm)", 16, CellStyle::fixed, 6},
                       {&creep_fitted, "model (mm)", 15, CellStyle::fixed, 6},
                       {&creep_residual, "residual (mm)", 15, CellStyle::number, 3}},
                      rows);
        const ProductEntry &rms = product.root().at(is_dma ? rms_residual_kPa : rms_residual);
        std::cout << "weighted rms residual " << format_number(rms.value(0), 4) << " "
                  << rms.quantity->unit.name << ", condition number of the scaled Jacobian "
                  << format_number(r.condition, 3) << '\n';
      }

      int write_and_report(const Invocation &invocation, const FitResult &r,
                           const Product &product) const
      {
        return write_fit_files(invocation, invocation.parameters.scene(), settings.free, r,
                               product);
      }
    };
  } // namespace

  std::unique_ptr<ViscousFitJob> viscous_fit_job(const FitDataKind kind)
  {
    return std::make_unique<ViscousFit>(kind);
  }

  int write_fit_files(const Invocation &invocation, const Scene &base,
                      const std::vector<SceneParameter> &free, const FitResult &r,
                      const Product &product, const std::vector<ProductPath> &more)
  {
    const Parameters  &p        = invocation.parameters;
    const std::string &h5_path  = invocation.output.path;
    const std::string  prm_path = p.output.directory + "/" + p.output.base_name + "_fit.prm";
    std::vector<std::string> paths{h5_path, prm_path};
    for (const ProductPath &m : more)
      paths.push_back(m.path);
    const auto write = [&] {
      write_product_file(product, h5_path);
      if (r.fitted.size() > 0)
        {
          std::vector<ParameterChange> entries = fitted_entries(base, free, r.values);
          for (ParameterChange &u : uncertainty_entries(free, r))
            entries.push_back(std::move(u));
          write_changed_parameters(invocation.input, prm_path, entries,
                                   "# Written by cdea fit: the parameter file with the fitted "
                                   "values; subsection Uncertainty holds their covariance\n"
                                   "# (Uncertainty/Mode = linear carries it into cdea run).\n");
        }
      for (const ProductPath &m : more)
        write_product_file(*m.product, m.path);
    };
    return finish_fit(write, paths, r);
  }

  int finish_fit(const std::function<void()> &write_results, const std::vector<std::string> &paths,
                 const FitResult &r)
  {
    const std::string &h5_path = paths.front();
    const int                signal = StopOnSignals::requested();
    std::vector<std::string> wrote;
    try
      {
        ReplaceTogether pair(paths);
        write_results();
        wrote = pair.commit(signal != 0);
      }
    catch (const std::exception &e)
      {
        std::cerr << "cdea: the results cannot be written: " << e.what()
                  << " (older files of this name stay as they were)\n";
        return exit_not_complete;
      }
    std::string list;
    for (const std::string &w : wrote)
      if (!w.empty())
        list += (list.empty() ? "" : w == wrote.back() ? " and " : ", ") + w;
    std::cout << "wrote " << list << '\n';
    if (signal)
      {
        std::cerr << "cdea: interrupted by " << signal_name(signal)
                  << "; the values reached are in " << wrote[0]
                  << (wrote[0] != h5_path ? " (the older " + h5_path + " is kept as it was)" : "")
                  << '\n';
        return exit_not_complete;
      }
    if (!r.converged)
      {
        std::cerr << "cdea: the fit did not converge (" << r.status
                  << "); the last values are in " << h5_path << '\n';
        return exit_not_complete;
      }
    return exit_success;
  }

  int fit_not_started(Invocation &invocation, const std::string &status, const std::string &hint)
  {
    invocation.output.give_up();
    if (const int signal = StopOnSignals::requested())
      {
        std::cerr << "cdea: interrupted by " << signal_name(signal)
                  << " during the evaluation of the start values; nothing was written\n";
        return exit_not_complete;
      }
    std::cerr << "cdea: " << status << " (" << hint << "nothing was written)\n";
    return exit_input_error;
  }

  void print_fitted_values(const std::vector<SceneParameter> &free, const FitResult &r)
  {
    std::cout << "\n" << (r.converged ? "Converged" : "NOT converged") << ": " << r.status
              << "\n" << std::left << std::setw(30) << "parameter" << std::right << std::setw(16)
              << "start" << std::setw(16) << "fitted" << std::setw(16) << "std. error"
              << std::setw(10) << "rel." << '\n';
    for (std::size_t j = 0; j < free.size(); ++j)
      {
        const SceneParameter &f = free[j];
        const double          e = shown(f, r.standard_errors[j]), v = shown(f, r.values[j]);
        std::cout << std::left << std::setw(30) << shown_label(f) << std::right << std::setw(16)
                  << format_number(shown(f, r.initial[j]), 8) << std::setw(16)
                  << format_number(v, 8) << std::setw(16) << format_number(e, 3) << std::setw(10)
                  << format_number(e / std::abs(v), 2) << '\n';
      }
    print_correlation(free, r, 28);
  }

  void print_correlation(const std::vector<SceneParameter> &free, const FitResult &r,
                         const int label_width)
  {
    const std::size_t K = free.size();
    if (K < 2)
      return;
    std::cout << "correlation:\n";
    for (std::size_t i = 0; i < K; ++i)
      {
        std::cout << "  " << std::left << std::setw(label_width) << label(free[i]) << std::right;
        for (std::size_t j = 0; j < K; ++j)
          std::cout << std::setw(9) << format_fixed(r.correlation(i, j), 4);
        std::cout << '\n';
      }
  }
} // namespace cdea
