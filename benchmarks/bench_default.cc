// Benchmark: the default case (prm/default.prm, or the file given) solved
// repeatedly in one process. Prints the median wall time of a whole run, per
// converged step and per Newton iteration, and the peak resident memory.
// Process start-up (library loading, MPI initialisation) is timed separately
// by the caller (see doc/performance.md); it does not belong to the solver.
//
//   build/benchmarks/bench_default [FILE.prm] [RUNS]

#include <cdea/app/commands.h>
#include <cdea/app/mpi_session.h>
#include <cdea/app/parameters.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/solver/load_stepper.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace cdea;

namespace
{
  double median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession  mpi(argc, argv);
  const std::string file = argc > 1 ? argv[1] : std::string(CDEA_SOURCE_DIR) + "/prm/default.prm";
  const int         runs = argc > 2 ? std::atoi(argv[2]) : 21;
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
      MembraneModel model(scene, fe_discretization(p), newton_settings(p));
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
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::cout << std::setprecision(4) << "case: " << file << "\n"
            << "unknowns: " << dofs << ", converged steps: " << steps
            << ", Newton iterations: " << iterations << ", runs: " << runs << "\n"
            << "median time per run:              " << median(run_time) * 1e3 << " ms\n"
            << "median time per converged step:   " << median(per_step) * 1e6 << " us\n"
            << "median time per Newton iteration: " << median(per_iteration) * 1e6 << " us\n"
            << "peak resident memory:             " << usage.ru_maxrss / 1024. << " MiB\n";
  return 0;
}
