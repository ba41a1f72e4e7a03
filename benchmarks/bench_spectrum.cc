// Benchmark: the cost of a relaxation spectrum (doc/materials.md, "The
// relaxation spectrum"). The pump cycle of prm/pump-time.prm (by default)
// run in one process without output, three ways, interleaved:
//   1. as the file has it: network B as one branch of the old entries;
//   2. the same branch given as the lists Branch shear moduli (kPa) etc.;
//   3. three branches, 25, 15 and 5 kPa (the same 45 kPa in all) at 0.2, 2
//      and 20 s.
// It checks the answer: 1 and 2 end with the same disk position to 1e-12
// (relative), and 3 ends elsewhere (the spectrum is not the one branch). It
// prints the median wall and CPU time of each and the ratio of 3 to 1.
//
//   build/benchmarks/bench_spectrum [FILE.prm] [CYCLES] [RUNS]
//
// CYCLES (if given and > 0) replaces Time/Cycles: build/benchmarks/bench_spectrum "" 1 1

#include <cdea/analysis/time_run.h>
#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/solver/time_stepper.h>

#include "bench_common.h"

#include <sys/resource.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace cdea;

namespace
{
  double cpu_seconds()
  {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }

  struct Timing
  {
    std::vector<double> wall, cpu;
    double              disk_position = 0.;
    unsigned int        steps = 0, iterations = 0;
  };

  /// One run of @p p in memory; false if it did not complete.
  bool run_once(const Parameters &p, Timing &t)
  {
    const auto   start     = std::chrono::steady_clock::now();
    const double cpu_start = cpu_seconds();
    const Scene        scene  = p.scene();
    const TimeRunSetup run    = set_up_time_run(p, scene);
    const RunResult    result = run.stepper->run();
    t.wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    t.cpu.push_back(cpu_seconds() - cpu_start);
    t.disk_position = run.model->disk_position();
    t.steps         = result.steps;
    t.iterations    = result.newton_iterations;
    if (!result.completed)
      std::cerr << "bench_spectrum: run did not complete: " << result.message << '\n';
    return result.completed;
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession  mpi(argc, argv);
  const std::string file =
    argc > 1 && argv[1][0] != '\0' ? argv[1] : std::string(CDEA_SOURCE_DIR) + "/prm/pump-time.prm";
  const int cycles = argc > 2 ? std::atoi(argv[2]) : 0;
  const int runs   = argc > 3 ? std::atoi(argv[3]) : 3;

  const std::filesystem::path out =
    std::filesystem::temp_directory_path() / ("cdea-bench-spectrum-" + std::to_string(getpid()));
  const std::string base = cdea_bench::prm_writing_to(file, out);
  if (cycles > 0)
    std::ofstream(base, std::ios::app) << "subsection Time\n  set Cycles = " << cycles << "\nend\n";
  const std::array<std::string, 3> names{{"one branch (Network B entries)",
                                           "one branch (Branch lists)", "three branches"}};
  const std::array<std::string, 3> material{
    {"", "  set Branch shear moduli (kPa) = 45\n  set Branch relaxation times (s) = 2\n",
     "  set Branch shear moduli (kPa) = 25, 15, 5\n"
     "  set Branch relaxation times (s) = 0.2, 2, 20\n"}};
  std::array<Parameters, 3> p;
  try
    {
      for (std::size_t k = 0; k < 3; ++k)
        {
          const std::string prm = out / ("case" + std::to_string(k) + ".prm");
          std::filesystem::copy_file(base, prm, std::filesystem::copy_options::overwrite_existing);
          std::ofstream(prm, std::ios::app) << "subsection Material\n" << material[k] << "end\n";
          p[k] = read_parameters(prm);
        }
    }
  catch (const std::exception &e)
    {
      std::cerr << "bench_spectrum: " << e.what() << '\n';
      std::filesystem::remove_all(out);
      return 1;
    }
  std::array<Timing, 3> t;
  bool                  ok = true;
  for (int r = 0; r < runs && ok; ++r)
    for (std::size_t k = 0; k < 3 && ok; ++k)
      ok = run_once(p[k], t[k]);
  std::filesystem::remove_all(out);
  if (!ok)
    return 1;

  using cdea_bench::median;
  std::cout << std::setprecision(4) << "case: " << file
            << (cycles > 0 ? " with " + std::to_string(cycles) + " cycles" : std::string())
            << ", runs: " << runs << " each, interleaved\n";
  for (std::size_t k = 0; k < 3; ++k)
    std::cout << names[k] << ": median " << median(t[k].wall) * 1e3 << " ms wall, "
              << median(t[k].cpu) * 1e3 << " ms CPU; steps " << t[k].steps
              << ", Newton iterations " << t[k].iterations << ", final disk position "
              << std::setprecision(12) << t[k].disk_position * 1e3 << " mm"
              << std::setprecision(4) << '\n';
  std::cout << "three branches / one branch: wall " << median(t[2].wall) / median(t[0].wall)
            << ", CPU " << median(t[2].cpu) / median(t[0].cpu) << '\n';

  const double same = std::abs(t[1].disk_position - t[0].disk_position) /
                      std::abs(t[0].disk_position);
  const double apart = std::abs(t[2].disk_position - t[0].disk_position) /
                       std::abs(t[0].disk_position);
  if (!(same <= 1e-12) || !(apart > 1e-6))
    {
      std::cerr << "bench_spectrum: wrong answer: the list entries' one branch differs by "
                << same << " (at most 1e-12 allowed), the three branches by " << apart
                << " (more than 1e-6 expected)\n";
      return 1;
    }
  return 0;
}
