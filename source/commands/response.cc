// `cdea response FILE.prm`: the small-signal frequency response about the
// equilibrium at the end of the voltage path (analysis/frequency_response.h):
// the natural frequencies with their damping, a table of the transfer
// functions at a few frequencies, and <Base name>_response.h5 with all of
// them. 0 written, 1 bad input, 2 no equilibrium, interrupted (SIGINT,
// SIGTERM, SIGHUP: nothing written) or not written.

#include <cdea/analysis/frequency_response.h>
#include <cdea/base/format.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/model/quantities_response.h>
#include <cdea/output/product_file.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    class Response final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        input = run_input(invocation.parameters, invocation.parameter_text,
                          RunMethod::finite_elements, "response");
      }

      std::string output_path(const Invocation &invocation) const override
      {
        return invocation.parameters.results_path("_response");
      }

      int run(Invocation &invocation) override
      {
        const auto        start = std::chrono::steady_clock::now();
        FrequencyResponse r;
        try
          {
            r = frequency_response(input);
            if (const int signal = StopOnSignals::requested())
              throw RunInterrupted(signal);
          }
        catch (const RunInterrupted &e)
          {
            // Not divisible: no partial response is written.
            std::cerr << "cdea: " << e.what()
                      << " before the response was complete; nothing was written\n";
            invocation.output.give_up();
            return exit_not_complete;
          }
        catch (const std::runtime_error &e)
          {
            std::cerr << "cdea: " << e.what() << '\n';
            invocation.output.give_up();
            return exit_not_complete;
          }
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const Product product = response_product(invocation.parameter_text, r);
        print(r, product);
        try
          {
            write_product_file(product, invocation.output.path);
          }
        catch (const std::exception &e)
          {
            std::cerr << "cdea: the results cannot be written: " << e.what()
                      << " (an older file of this name stays as it was)\n";
            return exit_not_complete;
          }
        std::cout << r.frequency.size() << " frequencies in " << std::setprecision(3)
                  << units::ms.from_si(r.seconds) << " ms, " << seconds << " s in all\nwrote "
                  << invocation.output.path << '\n';
        return exit_success;
      }

    private:
      RunInput input;

      static void print(const FrequencyResponse &r, const Product &product)
      {
        using namespace response_quantity;
        const ProductGroup &root  = product.root();
        const ProductGroup &modes = product.at("/modes");
        std::cout << "Equilibrium at " << format_kV(r.bias) << ": displacement "
                  << format_number(root.at(displacement).value(0), 8) << " mm, enclosed volume "
                  << format_number(root.at(volume).value(0), 8) << " mm^3\nMass: disk "
                  << format_number(root.at(disk_mass).value(0)) << " g, membrane density "
                  << format_number(r.density) << " kg/m^3, water column "
                  << format_number(r.water_mass) << " kg/m^4\n";
        const std::size_t n_modes = modes.at(mode_frequency).size();
        if (n_modes == 0)
          std::cout << "no natural frequencies (no mass)\n";
        for (std::size_t k = 0; k < n_modes; ++k)
          std::cout << "mode " << k + 1 << ": natural frequency "
                    << format_number(modes.at(mode_frequency).value(k), 8) << " Hz, damping ratio "
                    << format_number(modes.at(mode_damping).value(k), 4) << '\n';
        const ProductGroup &transfer = product.at("/transfer");
        std::cout << std::setw(14) << "f (Hz)" << std::setw(18) << "disk (mm/kV)"
                  << std::setw(14) << "phase (deg)" << std::setw(20) << "volume (mm^3/kV)"
                  << '\n';
        const std::size_t n = r.frequency.size(), rows = std::min<std::size_t>(n, 11);
        for (std::size_t j = 0; j < rows; ++j)
          {
            const std::size_t i = rows > 1 ? j * (n - 1) / (rows - 1) : 0;
            std::cout << std::setw(14) << format_number(transfer.at(frequency).value(i), 5)
                      << std::setw(18) << format_number(transfer.at(amplitude).value(i), 6)
                      << std::setw(14) << format_fixed(transfer.at(phase).value(i), 2)
                      << std::setw(20)
                      << format_number(units::mm3_per_kV.from_si(std::abs(r.volume_drive[i])), 6)
                      << '\n';
          }
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> response_job()
  {
    return std::make_unique<Response>();
  }
} // namespace cdea
