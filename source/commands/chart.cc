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
#include <cdea/output/hdf5_writer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>

namespace cdea
{
  namespace
  {
    constexpr double two_pi = 6.28318530717958647692;

    std::vector<double> in_kPa(const std::vector<double> &pascal)
    {
      std::vector<double> v;
      for (const double x : pascal)
        v.push_back(x * 1e-3);
      return v;
    }

    /// Indices of about eleven rows of a table of n points (first and last included).
    std::vector<std::size_t> table_rows(const std::size_t n)
    {
      std::vector<std::size_t> rows;
      const std::size_t        every = std::max<std::size_t>(1, (n - 1) / 10);
      for (std::size_t k = 0; k < n; k += every)
        rows.push_back(k);
      if (rows.back() != n - 1)
        rows.push_back(n - 1);
      return rows;
    }

    void write_curve(Hdf5Writer &w, const StressStretchCurve &c)
    {
      const std::string g = "/" + path_name(c.path);
      const std::size_t n = c.stretch.size();
      w.group(g);
      w.attribute(g, "locking_stretch", c.locking_stretch);
      w.dataset(g + "/stretch", {n}, c.stretch, "1", "stretch l1 along the load");
      w.dataset(g + "/transverse_stretch", {n}, c.transverse_stretch, "1",
                c.path == ChartPath::uniaxial ? "stretch l2 across the load (s2 = 0)" :
                                                "stretch l2 = l1");
      w.dataset(g + "/nominal_stress_kPa", {n}, in_kPa(c.nominal_stress), "kPa",
                "nominal stress s1 = dW/dl1 (force per undeformed area), relaxed");
      if (!c.instantaneous_stress.empty())
        {
          w.dataset(g + "/instantaneous_stress_kPa", {n}, in_kPa(c.instantaneous_stress), "kPa",
                    "nominal stress s1 with the internal variables at the undeformed state");
          w.dataset(g + "/instantaneous_transverse_stretch", {n},
                    c.instantaneous_transverse_stretch, "1", "l2 of the instantaneous curve");
        }
    }

    void write_dma(Hdf5Writer &w, const DmaChart &d)
    {
      const std::size_t n = d.frequency.size();
      w.group("/dma");
      w.attribute("/dma", "relaxed_modulus_kPa", d.moduli.relaxed * 1e-3);
      w.attribute("/dma", "instantaneous_modulus_kPa", d.moduli.instantaneous * 1e-3);
      w.attribute("/dma", "relaxation_time_s", d.moduli.relaxation_time);
      w.dataset("/dma/frequency_Hz", {n}, d.frequency, "Hz", "frequency f (w = 2 pi f)");
      w.dataset("/dma/storage_modulus_kPa", {n}, in_kPa(d.storage), "kPa",
                "storage modulus E' of small-strain uniaxial tension");
      w.dataset("/dma/loss_modulus_kPa", {n}, in_kPa(d.loss), "kPa",
                "loss modulus E'' of small-strain uniaxial tension");
      w.dataset("/dma/loss_factor", {n}, d.loss_factor, "1", "tan delta = E'' / E'");
    }

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
        const StressStretchCurve uniaxial =
          stress_stretch_curve(*law, ChartPath::uniaxial, settings);
        const StressStretchCurve equibiaxial =
          stress_stretch_curve(*law, ChartPath::equibiaxial, settings);
        std::optional<DmaChart> dma;
        if (law->n_internal_variables() > 0)
          dma = dma_chart(*law, settings);
        std::cout << "cdea " << CDEA_VERSION << " chart: Material/Model = " << model
                  << ", zero voltage\n";
        print_curve(uniaxial);
        print_curve(equibiaxial);
        if (dma)
          print_dma(*dma);
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
            Hdf5Writer w(path);
            w.attribute("/", "parameters", invocation.parameter_text);
            w.attribute("/", "code_version", std::string(CDEA_VERSION));
            w.attribute("/", "material_model", model);
            w.attribute("/", "voltage_V", 0.);
            w.attribute("/", "dma", std::string(dma ? "small-strain standard linear solid" :
                                                      "none: the law is elastic"));
            write_curve(w, uniaxial);
            write_curve(w, equibiaxial);
            if (dma)
              write_dma(w, *dma);
            w.commit();
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

      static void print_curve(const StressStretchCurve &c)
      {
        const bool viscous = !c.instantaneous_stress.empty();
        std::cout << "\n" << path_name(c.path) << " tension: stretch 1 to "
                  << format_number(c.stretch.back(), 6) << " ("
                  << (std::isfinite(c.locking_stretch) ?
                        "99 % of the way to the locking stretch " +
                          format_number(c.locking_stretch, 6) :
                        std::string("no locking below it"))
                  << ")\n"
                  << std::setw(10) << "stretch" << std::setw(14) << "transverse" << std::setw(20)
                  << (viscous ? "relaxed s1 (kPa)" : "nominal s1 (kPa)");
        if (viscous)
          std::cout << std::setw(24) << "instantaneous s1 (kPa)";
        std::cout << '\n';
        for (const std::size_t k : table_rows(c.stretch.size()))
          {
            std::cout << std::setw(10) << format_fixed(c.stretch[k], 4) << std::setw(14)
                      << format_fixed(c.transverse_stretch[k], 6) << std::setw(20)
                      << format_number(c.nominal_stress[k] * 1e-3, 6);
            if (viscous)
              std::cout << std::setw(24) << format_number(c.instantaneous_stress[k] * 1e-3, 6);
            std::cout << '\n';
          }
      }

      static void print_dma(const DmaChart &d)
      {
        const SmallStrainModuli &m = d.moduli;
        const double E_A = m.relaxed, E = m.instantaneous;
        if (m.relaxation_time > 0.)
          {
            // tan delta = E_B x / (E_A + E x^2), x = w tau, is largest at x = sqrt(E_A / E).
            const double x_peak = std::sqrt(E_A / E);
            std::cout << "\nDMA chart (small-strain uniaxial tension, standard linear solid):\n"
                      << "  relaxed modulus E_A " << format_number(E_A * 1e-3, 6)
                      << " kPa, instantaneous E_A + E_B " << format_number(E * 1e-3, 6)
                      << " kPa, relaxation time " << format_number(m.relaxation_time, 6)
                      << " s\n  largest loss factor "
                      << format_number((E - E_A) / (2. * std::sqrt(E_A * E)), 6) << " at "
                      << format_number(x_peak / (two_pi * m.relaxation_time), 6) << " Hz\n";
          }
        else
          {
            const auto peak = std::max_element(d.loss_factor.begin(), d.loss_factor.end());
            const auto k    = std::size_t(peak - d.loss_factor.begin());
            std::cout << "\nDMA chart (small-strain uniaxial tension, relaxation spectrum):\n"
                      << "  relaxed modulus " << format_number(E_A * 1e-3, 6)
                      << " kPa, instantaneous " << format_number(E * 1e-3, 6)
                      << " kPa\n  largest loss factor of the table " << format_number(*peak, 6)
                      << " at " << format_number(d.frequency[k], 6) << " Hz\n";
          }
        std::cout << std::setw(14) << "frequency (Hz)" << std::setw(16) << "E' (kPa)"
                  << std::setw(16) << "E'' (kPa)" << std::setw(14) << "tan delta" << '\n';
        for (const std::size_t k : table_rows(d.frequency.size()))
          std::cout << std::setw(14) << format_number(d.frequency[k], 4) << std::setw(16)
                    << format_number(d.storage[k] * 1e-3, 6) << std::setw(16)
                    << format_number(d.loss[k] * 1e-3, 6) << std::setw(14)
                    << format_number(d.loss_factor[k], 4) << '\n';
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> chart_job()
  {
    return std::make_unique<Chart>();
  }
} // namespace cdea
