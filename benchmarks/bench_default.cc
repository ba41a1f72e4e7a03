// Benchmark: the default case (prm/default.prm, or the file given) solved
// RUNS times in one process as `cdea run` solves it (model from the
// parameters, all load stages with the file's Solver settings, the stability
// eigenvalue at every step when the file asks for it, the fields of every
// step; no file output). Prints the median wall time of a run, per converged
// step and per Newton iteration, and the memory. Then it runs the whole
// program (`cdea run`, output to a temporary folder) PROCESS_RUNS times and
// prints the median wall time of a process, which adds library loading (and MPI
// start-up only under a launcher), HDF5 output and printing (0: no processes).
//
//   build/benchmarks/bench_default [FILE.prm] [RUNS] [PROCESS_RUNS]
//
// Fails (exit code 1) if a run does not complete or a figure is not finite;
// ctest runs it with 3 1 (label bench-smoke). doc/performance.md quotes it.

#include <cdea/analysis/run_setup.h>
#include <cdea/input/solver_settings.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>

#include "bench_common.h"

#include <sys/resource.h>

#include <iomanip>

using namespace cdea;
using namespace cdea_bench;

namespace
{
  int benchmark(const std::string &file, const int runs, const int process_runs)
  {
    const double     baseline = status_mib("VmRSS"); // the libraries, before any model
    const Parameters p        = read_parameters(file);
    const Scene      scene    = p.scene();

    std::vector<double> run_time, per_step, per_iteration;
    unsigned int        steps = 0, iterations = 0, dofs = 0;
    for (int k = 0; k < runs; ++k)
      {
        const double start = wall_seconds();
        const auto   model = make_fe_model(p, scene);
        LoadStepper  stepper(scene, *model, stepping_settings(p));
        // What a run reports besides the summary: the fields of every step.
        std::size_t samples = 0;
        stepper.on_step     = [&](const StepSummary &) { samples += stepper.step_fields().R.size(); };
        const RunResult result = stepper.run();
        const double    t      = wall_seconds() - start;
        require(result.completed, "the run did not complete: " + result.message);
        require(samples > 0, "no fields were evaluated");
        require(k == 0 || (result.steps == steps && result.newton_iterations == iterations),
                "runs of the same case differ in their steps or iterations");
        steps      = result.steps;
        iterations = result.newton_iterations;
        dofs       = model->n_dofs();
        run_time.push_back(t);
        per_step.push_back(t / result.steps);
        per_iteration.push_back(t / std::max(1u, result.newton_iterations));
      }
    const double peak = status_mib("VmHWM");
    require_finite(median(run_time), "the median time per run", true);

    std::cout << std::setprecision(4) << "case: " << file << "\n"
              << "unknowns: " << dofs << ", converged steps: " << steps
              << ", Newton iterations: " << iterations << ", runs: " << runs << "\n"
              << "median time per run:              " << median(run_time) * 1e3 << " ms\n"
              << "median time per converged step:   " << median(per_step) * 1e6 << " us\n"
              << "median time per Newton iteration: " << median(per_iteration) * 1e6 << " us\n"
              << "resident memory before any model: " << baseline << " MiB (the libraries)\n"
              << "peak resident memory (in-process): " << peak << " MiB\n";
    if (process_runs <= 0)
      return 0;

    // Whole processes, as a user runs them.
    const OutputFolder  out("", true);
    const std::string   prm = prm_writing_to(file, out.path());
    std::vector<double> process_time;
    for (int k = 0; k < process_runs; ++k)
      {
        const ProcessRun r =
          time_process(std::string(CDEA_EXECUTABLE) + " run " + prm + " > /dev/null");
        require(r.exit_code == 0, "cdea run failed (status " + std::to_string(r.exit_code) + ")");
        process_time.push_back(r.seconds);
      }
    const std::string results = (out / (p.output.base_name + ".h5")).string();
    require(std::filesystem::exists(results), "cdea run wrote no " + results);
    rusage children{};
    getrusage(RUSAGE_CHILDREN, &children);
    std::cout << "whole process `cdea run`, median of " << process_runs << ": "
              << median(process_time) * 1e3 << " ms, peak resident memory "
              << children.ru_maxrss / 1024. << " MiB\n";
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  return guarded("bench_default", [&] {
    const std::string file =
      argc > 1 ? argv[1] : std::string(CDEA_SOURCE_DIR) + "/prm/default.prm";
    const int runs         = argc > 2 ? std::atoi(argv[2]) : 21;
    const int process_runs = argc > 3 ? std::atoi(argv[3]) : 7;
    require(runs > 0, "RUNS must be a positive number");
    return benchmark(file, runs, process_runs);
  });
}
