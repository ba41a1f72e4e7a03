// Benchmark: the default case (prm/default.prm, or the file given) solved
// repeatedly in one process. Prints the median wall time of a whole run, per
// converged step and per Newton iteration, and the peak resident memory.
// Then it launches the whole program (`cdea run FILE.prm`, output to a
// temporary folder) several times and prints the median wall time of a process,
// which adds library loading, MPI initialisation, HDF5 output and printing.
//
//   build/benchmarks/bench_default [FILE.prm] [RUNS] [PROCESS_RUNS]

#include <cdea/app/commands.h>
#include <cdea/app/mpi_session.h>
#include <cdea/app/parameters.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/solver/load_stepper.h>

#include "bench_common.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
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
  using cdea_bench::median;

  /// A line of /proc/self/status in MiB ("VmRSS", "VmHWM").
  double status_mib(const std::string &key)
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind(key + ":", 0) == 0)
        return std::stod(line.substr(key.size() + 1)) / 1024.;
    return 0.;
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession  mpi(argc, argv);
  const std::string file = argc > 1 ? argv[1] : std::string(CDEA_SOURCE_DIR) + "/prm/default.prm";
  const int         runs = argc > 2 ? std::atoi(argv[2]) : 21;
  const int process_runs = argc > 3 ? std::atoi(argv[3]) : 7;
  const double baseline  = status_mib("VmRSS"); // libraries and MPI, before any model
  Parameters        p;
  try
    {
      p = read_parameters(file);
    }
  catch (const InputError &e)
    {
      std::cerr << "bench_default: " << e.what() << '\n';
      return 1;
    }
  const Scene scene = p.scene();

  std::vector<double> run_time, per_step, per_iteration;
  unsigned int        steps = 0, iterations = 0, dofs = 0;
  for (int k = 0; k < runs; ++k)
    {
      const auto    start = std::chrono::steady_clock::now();
      const auto    model_ptr = make_fe_model(p, scene);
      MembraneModel &model    = *model_ptr;
      LoadStepper   stepper(scene, model, stepping_settings(p));
      // Collect what a run reports (summary and fields), without file output.
      std::size_t samples = 0;
      stepper.on_step = [&](const StepSummary &) { samples += model.fields().R.size(); };
      const RunResult result = stepper.run();
      const double    t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!result.completed)
        {
          std::cerr << "bench_default: run did not complete: " << result.message << '\n';
          return 1;
        }
      steps      = result.steps;
      iterations = result.newton_iterations;
      dofs       = model.n_dofs();
      run_time.push_back(t);
      per_step.push_back(t / result.steps);
      per_iteration.push_back(t / std::max(1u, result.newton_iterations));
    }
  const double peak = status_mib("VmHWM");

  // Whole processes, as a user runs them.
  const std::filesystem::path out =
    std::filesystem::temp_directory_path() / ("cdea-bench-" + std::to_string(getpid()));
  const std::string prm = cdea_bench::prm_writing_to(file, out);
  std::vector<double> process_time;
  for (int k = 0; k < process_runs; ++k)
    {
      const auto start = std::chrono::steady_clock::now();
      const int  rc =
        std::system((std::string(CDEA_EXECUTABLE) + " run " + prm + " > /dev/null").c_str());
      process_time.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if (rc != 0)
        {
          std::cerr << "bench_default: cdea run failed\n";
          return 1;
        }
    }
  std::filesystem::remove_all(out);
  rusage children{};
  getrusage(RUSAGE_CHILDREN, &children);

  std::cout << std::setprecision(4) << "case: " << file << "\n"
            << "unknowns: " << dofs << ", converged steps: " << steps
            << ", Newton iterations: " << iterations << ", runs: " << runs << "\n"
            << "median time per run:              " << median(run_time) * 1e3 << " ms\n"
            << "median time per converged step:   " << median(per_step) * 1e6 << " us\n"
            << "median time per Newton iteration: " << median(per_iteration) * 1e6 << " us\n"
            << "resident memory before any model: " << baseline << " MiB (libraries, MPI)\n"
            << "peak resident memory (in-process): " << peak << " MiB\n"
            << "whole process `cdea run`, median of " << process_runs << ": "
            << median(process_time) * 1e3 << " ms, peak resident memory "
            << children.ru_maxrss / 1024. << " MiB\n";
  return 0;
}
