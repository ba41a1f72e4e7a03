// Benchmark: the uncertainty of a run's answers (doc/uncertainty.md). The
// scene of prm/default.prm with 3 % (one standard deviation, uncorrelated) on
// each of its film's constants (shear modulus, Jlim, permittivity), at its own
// 5 kV and driven on to 6 kV (the default path ends before the onset of
// wrinkling at 5.38 kV, so the onset voltage needs the longer path):
//
//   1. linear propagation against Monte-Carlo (SAMPLES runs, seed 1): the
//      standard deviations of the final displacement, stroke, volume change
//      and onset voltage; checked within 10 % for the displacement and the
//      onset voltage (the figure);
//   2. the cost of the linear propagation: the run with it against the run
//      without it, in-process (median CPU time of 20 RUNS interleaved pairs:
//      a run takes about 2 ms), and as whole `cdea run` processes with Mode =
//      linear and none (median wall time of RUNS each); checked at most 1.5
//      times in-process.
//
//   build/benchmarks/bench_uncertainty [SAMPLES] [RUNS]
//
// Smoke run (ctest): bench_uncertainty 40 2 (the Monte-Carlo check at 40
// samples within 35 %, the scatter of their standard deviation being 11 %).

#include <cdea/analysis/run_input.h>
#include <cdea/analysis/uncertainty_run.h>
#include <cdea/base/format.h>
#include <cdea/input/parameter_input.h>
#include <cdea/model/quantities_uncertainty.h>

#include "bench_common.h"

#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace cdea;

namespace
{
  namespace q = uncertainty_quantity;

  const std::string deviations = "shear modulus: 3%, Jlim: 3%, permittivity: 3%";

  RunInput input(const std::string &voltage_kV, const std::string &mode,
                 const unsigned int samples)
  {
    ParameterInput in = ParameterInput::file(std::string(CDEA_SOURCE_DIR) + "/prm/default.prm");
    in.overrides      = {{"Electrodes/Voltage path (kV)", voltage_kV},
                         {"Uncertainty/Mode", mode},
                         {"Uncertainty/Standard deviations", deviations},
                         {"Uncertainty/Samples", std::to_string(samples)}};
    std::string      text;
    const Parameters p = read_parameters(in, &text);
    return run_input(p, text, RunMethod::finite_elements, "run");
  }

  double value(const ProductGroup &rows, const Quantity &row)
  {
    return rows.at(row).value(0);
  }

  /// Linear against Monte-Carlo at @p voltage_kV; the largest relative
  /// difference of the displacement's and (if @p onset) the onset's sd.
  double compare(const std::string &voltage_kV, const unsigned int samples, const bool onset)
  {
    ProductGroup linear("/summary");
    quiet_run(input(voltage_kV, "linear", samples), input(voltage_kV, "linear", samples).scene,
              &linear);
    const RunInput     mc_input = input(voltage_kV, "monte carlo", samples);
    const double       t0       = cdea_bench::wall_seconds();
    const ProductGroup mc       = monte_carlo_run(mc_input, mc_input.uncertainty, false);
    const double       seconds  = cdea_bench::wall_seconds() - t0;
    std::cout << "default scene at " << voltage_kV << " kV, 3 % on mu, Jlim, eps; Monte-Carlo "
              << value(mc, q::samples) << " of " << samples << " samples completed ("
              << value(mc, q::onset_samples) << " with an onset), "
              << format_number(seconds, 3) << " s\n"
              << "  answer              linear sd    Monte-Carlo sd   MC/linear - 1\n";
    double worst = 0.;
    for (const auto &[name, row, checked] :
         std::vector<std::tuple<const char *, const Quantity *, bool>>{
           {"displacement (mm)  ", &q::displacement_std, true},
           {"stroke (mm)        ", &q::stroke_std, false},
           {"volume change (mm3)", &q::volume_change_std, false},
           {"onset voltage (kV) ", &q::onset_voltage_std, onset}})
      {
        const double l = value(linear, *row), m = value(mc, *row);
        std::cout << "  " << name << "  " << std::setw(11) << format_number(l, 5) << "  "
                  << std::setw(15) << format_number(m, 5) << "  " << std::setw(13)
                  << format_number(m / l - 1., 3) << '\n';
        if (checked)
          worst = std::max(worst, std::abs(m / l - 1.));
      }
    return worst;
  }

  /// Median CPU seconds of the run without and with the linear propagation,
  /// in interleaved pairs.
  std::pair<double, double> cost(const std::string &voltage_kV, const int runs)
  {
    const RunInput      in = input(voltage_kV, "linear", 2);
    std::vector<double> without, with;
    for (int r = 0; r < runs; ++r)
      {
        double t0 = cdea_bench::cpu_seconds();
        cdea_bench::require(quiet_run(in, in.scene).completed, "the run completes");
        without.push_back(cdea_bench::cpu_seconds() - t0);
        ProductGroup rows("/summary");
        t0 = cdea_bench::cpu_seconds();
        quiet_run(in, in.scene, &rows);
        with.push_back(cdea_bench::cpu_seconds() - t0);
        cdea_bench::require_finite(value(rows, q::displacement_std), "the linear sd");
      }
    return {cdea_bench::median(without), cdea_bench::median(with)};
  }

  /// Median wall seconds of whole `cdea run` processes with Mode = @p mode.
  double process_time(const std::string &mode, const int runs)
  {
    const std::string prm =
      cdea_bench::prm_writing_to(std::string(CDEA_SOURCE_DIR) + "/prm/default.prm",
                                 std::filesystem::temp_directory_path() / "bench_uncertainty");
    const std::string command = std::string(CDEA_EXECUTABLE) + " run " + prm +
                                " --set 'Electrodes/Voltage path (kV)=6' --set "
                                "'Uncertainty/Mode=" + mode + "' --set "
                                "'Uncertainty/Standard deviations=" + deviations +
                                "' > /dev/null";
    std::vector<double> t;
    for (int r = 0; r < runs; ++r)
      {
        const cdea_bench::ProcessRun run = cdea_bench::time_process(command);
        cdea_bench::require(run.exit_code == 0, "cdea run exits 0");
        t.push_back(run.seconds);
      }
    return cdea_bench::median(t);
  }
} // namespace

int main(int argc, char **argv)
{
  const unsigned int samples = argc > 1 ? unsigned(std::max(2, std::atoi(argv[1]))) : 1000;
  const int          runs    = argc > 2 ? std::max(1, std::atoi(argv[2])) : 9;
  // Within 10 % at 1000 samples; a smoke run's few samples scatter more
  // (the sd of n normal samples by about 1/sqrt(2 n)).
  const double tolerance = std::max(0.10, 3. / std::sqrt(2. * samples));
  return cdea_bench::guarded("bench_uncertainty", [&] {
    const double at5 = compare("5", samples, false);
    const double at6 = compare("6", samples, true);
    std::cout << "\ncost of the linear propagation (3 constants):\n";
    for (const char *voltage : {"5", "6"})
      {
        const auto [without, with] = cost(voltage, 20 * runs);
        std::cout << "  in-process at " << voltage << " kV, CPU median of " << 20 * runs
                  << ": without "
                  << format_number(without, 4) << " s, with " << format_number(with, 4)
                  << " s, ratio " << format_number(with / without, 4) << '\n';
        cdea_bench::require(with / without <= 1.5, "the linear propagation costs at most 1.5 "
                                                   "times the run");
      }
    const double none = process_time("none", runs), linear = process_time("linear", runs);
    std::cout << "  cdea run at 6 kV, wall median of " << runs << ": Mode = none " << format_number(none, 4)
              << " s, linear " << format_number(linear, 4) << " s, ratio "
              << format_number(linear / none, 4) << '\n';
    std::cout << "largest |MC/linear - 1| of the displacement and onset voltage: "
              << format_number(std::max(at5, at6), 3) << " (tolerance "
              << format_number(tolerance, 3) << ")\n";
    cdea_bench::require(std::max(at5, at6) <= tolerance,
                        "linear and Monte-Carlo standard deviations agree");
    return 0;
  });
}
