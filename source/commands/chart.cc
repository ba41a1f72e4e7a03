// `cdea chart FILE.prm`: the material charts of the law of Material/Model at
// zero voltage (material/material_chart.h): uniaxial and equibiaxial nominal
// stress against stretch and, for a law with internal variables, the
// small-strain DMA chart (storage and loss modulus, loss factor against
// frequency); a summary printed, everything in <Base name>_chart.h5
// (doc/materials.md, "Material charts"). 0 written, 1 bad input, 2 not written
// (a SIGINT, SIGTERM or SIGHUP before the file: nothing written).

#include <cdea/base/format.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/material/material_chart.h>
#include <cdea/material/membrane_law.h>
#include <cdea/model/chart_product.h>
#include <cdea/model/quantities_chart.h>
#include <cdea/output/product_file.h>
#include <cdea/output/product_table.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    constexpr double two_pi = 6.28318530717958647692;

    class Chart final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        law = invocation.parameters.scene().law();
      }

      std::string output_path(const Invocation &invocation) const override
      {
        return invocation.parameters.results_path("_chart");
      }

      int run(Invocation &invocation) override
      {
        const std::string model = invocation.parameters.material_law.model;
        const Product     product =
          chart_product(*law, settings, invocation.parameter_text, model);
        const bool dma = product.find("/dma") != nullptr;
        std::cout << "cdea " << CDEA_VERSION << " chart: Material/Model = " << model
                  << ", zero voltage\n";
        print_curve(product.at("/uniaxial"));
        print_curve(product.at("/equibiaxial"));
        if (dma)
          print_dma(product.at("/dma"));
        else
          std::cout << "DMA chart: none (Material/Model = " << model
                    << " is elastic: no internal variables, no loss)\n";
        const std::string &path = invocation.output.path;
        if (const int signal = StopOnSignals::requested())
          {
            std::cerr << "cdea: interrupted by " << signal_name(signal)
                      << " before the chart was written; nothing was written\n";
            invocation.output.give_up();
            return exit_not_complete;
          }
        try
          {
            write_product_file(product, path);
          }
        catch (const std::exception &e)
          {
            std::cerr << "cdea: the chart cannot be written: " << e.what()
                      << " (an older file of this name stays as it was)\n";
            return exit_not_complete;
          }
        std::cout << "wrote " << path << '\n';
        return exit_success;
      }

    private:
      std::shared_ptr<const MembraneLaw> law;
      ChartSettings                      settings;

      static void print_curve(const ProductGroup &c)
      {
        using namespace chart_quantity;
        const bool   viscous = c.find(instantaneous_stress) != nullptr;
        const auto  &L       = c.at(stretch).values;
        const double locking = c.at(locking_stretch).values[0];
        std::cout << "\n" << c.name().substr(1) << " tension: stretch 1 to "
                  << format_number(L.back(), 6) << " ("
                  << (std::isfinite(locking) ?
                        "99 % of the way to the locking stretch " + format_number(locking, 6) :
                        std::string("no locking below it"))
                  << ")\n";
        const Quantity &transverse = c.name() == "/uniaxial" ? uniaxial_transverse_stretch :
                                                               equibiaxial_transverse_stretch;
        std::vector<TableColumn> columns = {
          {&stretch, "stretch", 10, CellStyle::fixed, 4},
          {&transverse, "transverse", 14, CellStyle::fixed, 6},
          {&nominal_stress, viscous ? "relaxed s1 (kPa)" : "nominal s1 (kPa)", 20}};
        if (viscous)
          columns.push_back({&instantaneous_stress, "instantaneous s1 (kPa)", 24});
        print_table(std::cout, c, columns, sampled_rows(L.size()));
      }

      static void print_dma(const ProductGroup &d)
      {
        using namespace chart_quantity;
        const double E_A = d.at(relaxed_modulus).values[0], E = d.at(instantaneous_modulus).values[0];
        const double tau = d.at(relaxation_time).values[0];
        const std::string moduli = format_number(d.at(relaxed_modulus).value(0), 6);
        const std::string glassy = format_number(d.at(instantaneous_modulus).value(0), 6);
        if (tau > 0.)
          {
            // tan delta = E_B x / (E_A + E x^2), x = w tau, is largest at x = sqrt(E_A / E).
            const double x_peak = std::sqrt(E_A / E);
            std::cout << "\nDMA chart (small-strain uniaxial tension, standard linear solid):\n"
                      << "  relaxed modulus E_A " << moduli << " kPa, instantaneous E_A + E_B "
                      << glassy << " kPa, relaxation time " << format_number(tau, 6)
                      << " s\n  largest loss factor "
                      << format_number((E - E_A) / (2. * std::sqrt(E_A * E)), 6) << " at "
                      << format_number(x_peak / (two_pi * tau), 6) << " Hz\n";
          }
        else
          {
            const auto &tan_delta = d.at(loss_factor).values;
            const auto  peak      = std::max_element(tan_delta.begin(), tan_delta.end());
            const auto  k         = std::size_t(peak - tan_delta.begin());
            std::cout << "\nDMA chart (small-strain uniaxial tension, relaxation spectrum):\n"
                      << "  relaxed modulus " << moduli << " kPa, instantaneous " << glassy
                      << " kPa\n  largest loss factor of the table " << format_number(*peak, 6)
                      << " at " << format_number(d.at(frequency).values[k], 6) << " Hz\n";
          }
        print_table(std::cout, d,
                    {{&frequency, "frequency (Hz)", 14, CellStyle::number, 4},
                     {&storage_modulus, "E' (kPa)", 16},
                     {&loss_modulus, "E'' (kPa)", 16},
                     {&loss_factor, "tan delta", 14, CellStyle::number, 4}},
                    sampled_rows(d.at(frequency).size()));
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> chart_job()
  {
    return std::make_unique<Chart>();
  }
} // namespace cdea
