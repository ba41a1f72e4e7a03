// The error estimate of `cdea run` (doc/accuracy.md): on the twelve
// validation scenes (tests/validation_scenes.h) at coarse discretizations,
// each key output's estimated error against its true error (the difference
// from a run with p = 8 and 8 elements per ring, the onset located to 1e-7
// V): the effectivity estimate / true error, where the true error is well
// above the reference's own (1e-9 relative); and the cost of the estimate
// against the run's (wall clock, median of ROUNDS rounds).
//
//   build/benchmarks/bench_error_estimate [ROUNDS] [--smoke]
//
// With --smoke (ctest, label bench-smoke): two scenes at p = 2 with 2
// elements per ring, one round; it fails unless every effectivity there
// lies between 0.5 and 3.

#include "bench_common.h"

#include "../tests/error_estimate_runs.h"
#include "../tests/validation_scenes.h"

#include <iomanip>

using namespace cdea;
using namespace cdea_bench;
using namespace cdea_test;

namespace
{
  /// The true errors below this (relative) are not compared: the
  /// reference's own error and round-off.
  constexpr double resolved = 1e-8;

  struct Tally
  {
    double lowest = INFINITY, highest = 0.;
    int    compared = 0, outside = 0;
    void   add(const double effectivity)
    {
      lowest  = std::min(lowest, effectivity);
      highest = std::max(highest, effectivity);
      ++compared;
      outside += effectivity < 0.5 || effectivity > 3.;
    }
  };

  /// One scene at one discretization: a line per key output.
  void compare(const Case &c, const FeDiscretization &d, const EstimatedRun &reference,
               std::vector<Tally> &tallies, std::vector<double> &cost, const int rounds)
  {
    std::vector<double> run_t, estimate_t;
    EstimatedRun        run;
    for (int k = 0; k < rounds; ++k)
      {
        run = estimated_run(c.scene, d, 1e-7);
        run_t.push_back(run.run_seconds);
        estimate_t.push_back(run.estimate_seconds);
      }
    require(run.result.completed, c.name + ": the coarse run completes");
    cost.push_back(median(estimate_t) / median(run_t));
    std::cout << "  p " << d.degree << ", " << d.elements_per_ring << "/ring: run "
              << std::setprecision(3) << 1e3 * median(run_t) << " ms, estimate "
              << 1e3 * median(estimate_t) << " ms\n";
    const std::vector<double> value = key_values(run), truth = key_values(reference),
                              estimate = estimated_errors(run);
    for (std::size_t k = 0; k < value.size() && k < truth.size(); ++k)
      {
        const double error = std::abs(value[k] - truth[k]);
        // Relative to the output (s2_min to mu; a zero stroke or volume change to the
        // displacement and the volume).
        const double scale = k == 3           ? c.scene.material.shear_modulus :
                             truth[k] != 0.   ? std::abs(truth[k]) :
                                                std::abs(truth[0]);
        std::cout << "    " << std::setw(14) << key_name(k) << "  true " << std::setw(9)
                  << std::setprecision(2) << error / scale << "  estimated " << std::setw(9)
                  << estimate[k] / scale;
        if (error > resolved * scale && std::isfinite(estimate[k]))
          {
            const double effectivity = estimate[k] / error;
            tallies[std::min<std::size_t>(k, 4)].add(effectivity);
            std::cout << "  effectivity " << std::setprecision(3) << effectivity;
          }
        std::cout << '\n';
      }
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  return guarded("bench_error_estimate", [&] {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool               smoke  = take_flag(args, "--smoke");
    const int                rounds = args.empty() ? 5 : std::stoi(args.front());
    std::vector<FeDiscretization> discretizations;
    for (const auto &[p, e] : smoke ? std::vector<std::pair<int, int>>{{2, 2}} :
                                      std::vector<std::pair<int, int>>{{1, 3}, {2, 2}, {3, 1}, {4, 4}})
      {
        FeDiscretization d;
        d.degree            = p;
        d.elements_per_ring = e;
        discretizations.push_back(d);
      }
    std::vector<Case> scenes = cases();
    if (smoke)
      scenes = {scenes[1], scenes[10]};
    std::vector<Tally>  tallies(5);
    std::vector<double> cost;
    std::cout << "relative errors (s2_min over mu), effectivity = estimated / true where the "
                 "true error exceeds "
              << resolved << ":\n";
    for (const Case &c : scenes)
      {
        std::cout << c.name << '\n';
        const EstimatedRun reference = reference_run(c.scene);
        require(reference.result.completed, c.name + ": the reference run completes");
        for (const FeDiscretization &d : discretizations)
          compare(c, d, reference, tallies, cost, smoke ? 1 : rounds);
      }
    std::cout << "\neffectivity over the scenes and discretizations (in 0.5..3 / compared, "
                 "lowest, highest):\n";
    for (std::size_t k = 0; k < tallies.size(); ++k)
      std::cout << "  " << std::setw(14) << key_name(k) << "  " << tallies[k].compared - tallies[k].outside
                << " / " << tallies[k].compared << "  " << std::setprecision(3)
                << tallies[k].lowest << "  " << tallies[k].highest << '\n';
    std::cout << "cost of the estimate over the run's (median over the runs): "
              << median(cost) << ", largest " << *std::max_element(cost.begin(), cost.end())
              << '\n';
    if (smoke)
      for (std::size_t k = 0; k < tallies.size(); ++k)
        require(tallies[k].outside == 0, std::string(key_name(k)) + ": an effectivity outside 0.5..3");
    return 0;
  });
}
