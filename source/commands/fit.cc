// `cdea fit FILE.prm DATA.csv`: the calibration of subsection Calibration to
// the measured displacements (design/fit.h; DMA tables and creep curves in
// commands/fit_viscous.cc, material tests in commands/fit_material.cc),
// each iteration printed, the fitted values with their errors and
// correlations, the residuals, and the files <Base name>_fit.h5 and
// <Base name>_fit.prm. 0 converged, 2 not converged or interrupted (the
// values reached are written), 1 bad input.

#include <cdea/base/format.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/commands/fit_material.h>
#include <cdea/commands/fit_viscous.h>
#include <cdea/design/fit.h>
#include <cdea/input/validation.h>
#include <cdea/model/quantities_fit.h>
#include <cdea/output/product_table.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    /// A parameter in the units of its prm entry, with the unit.
    std::pair<double, std::string> shown(const SceneParameter &p, const double value)
    {
      switch (p.kind)
        {
          case ParameterKind::shear_modulus:
            return {units::kPa.from_si(value), units::kPa.name};
          case ParameterKind::mass:
            return {units::g.from_si(value), units::g.name};
          case ParameterKind::permittivity:
            return {value, units::F_per_m.name};
          default:
            return {value, ""};
        }
    }

    class Fit final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        const std::string &data_file = invocation.arguments.at(1);
        const Parameters  &p         = invocation.parameters;
        const std::string  prm_path = p.output.directory + "/" + p.output.base_name + "_fit.prm";
        if (const std::string why = refused_names(prm_path); !why.empty())
          throw InputError("cannot write '" + prm_path + "': " + why);
        if (material_test_files(invocation.arguments))
          {
            // Homogeneous material tests, one or several, fitted jointly.
            viscous = material_fit_job();
            viscous->check(invocation);
            return;
          }
        if (const FitDataKind kind = fit_data_kind(data_file);
            kind != FitDataKind::displacement_voltage)
          {
            // A DMA table or a creep curve: the viscoelastic film's fit.
            viscous = viscous_fit_job(kind);
            viscous->check(invocation);
            return;
          }
        base     = invocation.parameters.scene();
        settings = fit_settings(invocation.parameters);
        data     = read_calibration_data(data_file, base.n_rings(), voltage_ceiling(base));
        require_enough_points(data, settings, data_file);
      }

      std::string output_path(const Invocation &invocation) const override
      {
        return invocation.parameters.results_path("_fit");
      }

      int run(Invocation &invocation) override
      {
        if (viscous)
          return viscous->run(invocation);
        const auto start = std::chrono::steady_clock::now();
        print_banner(invocation.arguments.at(1));
        const Calibrated c =
          calibrate(invocation.parameters, base, data, settings,
                    [&](unsigned int k, double cost, const std::vector<double> &v) {
                      print_iteration(k, cost, v);
                    });
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!c.result.started) // nothing fitted: an older fit file stays as it was
          return fit_not_started(invocation, c.result.status,
                                 "change the start values in the parameter file or check that "
                                 "point; ");
        const Product product = fit_product(invocation.parameter_text, data, settings, c);
        print_values(c.result);
        print_residuals(c.result, product);
        for (const auto &w : c.result.warnings)
          std::cout << "WARNING: " << w << '\n';
        std::cout << c.result.iterations << " iterations, " << c.result.evaluations
                  << " evaluations, " << c.solves << " equilibrium solves (" << c.ramps
                  << " ramps), " << std::setprecision(3) << seconds << " s\n";
        return write_fit_files(invocation, base, settings.free, c.result, product);
      }

    private:
      Scene           base;
      FitSettings     settings;
      CalibrationData data;
      std::unique_ptr<ViscousFitJob> viscous; ///< a DMA, creep or material-test fit

      void print_banner(const std::string &data_file) const
      {
        std::cout << "cdea " << CDEA_VERSION << " fit: " << data.size() << " points of "
                  << data_file << ", " << base.n_rings() << " ring(s); free:";
        for (const auto &f : settings.free)
          std::cout << "  " << label(f);
        std::cout << "\n" << std::setw(5) << "iter" << std::setw(16) << "cost (mm^2)"
                  << "  parameters\n";
      }

      void print_iteration(const unsigned int k, const double cost,
                           const std::vector<double> &v) const
      {
        std::cout << std::setw(5) << k << std::setw(16) << format_number(cost, 8);
        for (std::size_t j = 0; j < v.size(); ++j)
          std::cout << "  " << format_number(shown(settings.free[j], v[j]).first, 8);
        std::cout << std::endl;
      }

      /// Start, fitted value, standard error per parameter; the correlations.
      void print_values(const FitResult &r) const
      {
        std::cout << "\n" << (r.converged ? "Converged" : "NOT converged") << ": " << r.status
                  << "\n" << std::left << std::setw(22) << "parameter" << std::right
                  << std::setw(16) << "start" << std::setw(16) << "fitted" << std::setw(16)
                  << "std. error" << std::setw(10) << "rel." << '\n';
        const std::size_t K = settings.free.size();
        for (std::size_t j = 0; j < K; ++j)
          {
            const auto [v0, unit] = shown(settings.free[j], r.initial[j]);
            const double v        = shown(settings.free[j], r.values[j]).first;
            const double e        = shown(settings.free[j], r.standard_errors[j]).first;
            std::cout << std::left << std::setw(22)
                      << label(settings.free[j]) + (unit.empty() ? "" : " (" + unit + ")")
                      << std::right << std::setw(16) << format_number(v0, 8) << std::setw(16)
                      << format_number(v, 8) << std::setw(16) << format_number(e, 3)
                      << std::setw(10) << format_number(e / std::abs(v), 2) << '\n';
          }
        print_correlation(settings.free, r, 16);
      }

      static void print_residuals(const FitResult &r, const Product &product)
      {
        using namespace fit_quantity;
        if (r.fitted.size() == 0)
          return;
        const ProductGroup &points = product.at("/data");
        std::vector<std::size_t> rows(points.at(displacement).size());
        for (std::size_t i = 0; i < rows.size(); ++i)
          rows[i] = i;
        std::cout << "residuals (model - measured):\n";
        print_table(std::cout, points,
                    {{nullptr, "point", 6, CellStyle::index},
                     {&voltage, "voltages (kV)", 24, CellStyle::list, 5},
                     {&displacement, "measured (mm)", 16, CellStyle::fixed, 6},
                     {&fitted, "model (mm)", 16, CellStyle::fixed, 6},
                     {&residual, "residual (mm)", 16, CellStyle::number, 3}},
                    rows);
        std::cout << "weighted rms residual "
                  << format_number(product.root().at(rms_residual).value(0), 4)
                  << " mm, condition number of the scaled Jacobian "
                  << format_number(r.condition, 3) << '\n';
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> fit_job()
  {
    return std::make_unique<Fit>();
  }
} // namespace cdea
