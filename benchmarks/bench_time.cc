// Benchmark: a time-dependent run (doc/time.md, doc/performance.md), by
// default the pump scene prm/pump-time.prm (30 cycles of a 0.5 Hz square wave
// in 10 ms steps, viscoelastic film, disk inertia, water load). First the run
// in one process without output, several times: median wall time of a run,
// per time step and per Newton iteration. Then the whole program
// (`cdea run FILE.prm`, output to a temporary folder) as a user runs it:
// median wall time of a process, which adds library loading, MPI start-up,
// printing and the HDF5 file, interleaved with processes of the quasi-static
// default case (prm/default.prm), whose time is almost all start-up.
//
//   build/benchmarks/bench_time [FILE.prm] [CYCLES] [RUNS] [PROCESS_RUNS]
//
// CYCLES (if given and > 0) replaces Time/Cycles, for a quick smoke run:
//   build/benchmarks/bench_time "" 1 1 1
//
// Checked (exit code 1 otherwise): every timed run completes, reaches the
// waveform's end time (to 1e-9 s, as tests/test_python_time.py asks of the
// program) and reports the same steps and Newton iterations as the first (the
// runs time the same work); every process exits with 0.

#include <cdea/input/solver_settings.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameters.h>
#include <cdea/input/parameter_input.h>
#include <cdea/analysis/time_run.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/solver/time_stepper.h>

#include "bench_common.h"

#include <sys/resource.h>
#include <unistd.h>

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
  /// CPU time (user + system) of this process or of its finished children (s).
  double cpu_seconds(const int who)
  {
    rusage u{};
    getrusage(who, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession  mpi(argc, argv);
  const std::string file =
    argc > 1 && argv[1][0] != '\0' ? argv[1] : std::string(CDEA_SOURCE_DIR) + "/prm/pump-time.prm";
  const int cycles       = argc > 2 ? std::atoi(argv[2]) : 0;
  const int runs         = argc > 3 ? std::atoi(argv[3]) : 5;
  const int process_runs = argc > 4 ? std::atoi(argv[4]) : 5;

  // A copy of the file writing into a temporary folder, with the cycles.
  const std::filesystem::path out =
    std::filesystem::temp_directory_path() / ("cdea-bench-time-" + std::to_string(getpid()));
  const std::string prm = cdea_bench::prm_writing_to(file, out);
  if (cycles > 0)
    std::ofstream(prm, std::ios::app) << "subsection Time\n  set Cycles = " << cycles << "\nend\n";

  Parameters p;
  try
    {
      p = read_parameters(prm);
    }
  catch (const InputError &e)
    {
      std::cerr << "bench_time: " << e.what() << '\n';
      std::filesystem::remove_all(out);
      return 1;
    }
  if (!p.time.enabled)
    {
      std::cerr << "bench_time: " << file << " is not a time run (Time/Enabled = false)\n";
      std::filesystem::remove_all(out);
      return 1;
    }
  const Scene        scene    = p.scene();
  const TimeSettings settings = time_settings(p, scene);

  std::vector<double> run_time, run_cpu, per_step, per_iteration;
  unsigned int        steps = 0, iterations = 0;
  for (int k = 0; k < runs; ++k)
    {
      const auto   start     = std::chrono::steady_clock::now();
      const double cpu_start = cpu_seconds(RUSAGE_SELF);
      // The model, stepper and postprocessors of `cdea run`.
      const TimeRunSetup run    = set_up_time_run(p, scene);
      const RunResult    result = run.stepper->run();
      const double    t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!result.completed)
        {
          std::cerr << "bench_time: run did not complete: " << result.message << '\n';
          std::filesystem::remove_all(out);
          return 1;
        }
      const double end_time = settings.waveform.end_time();
      if (std::abs(run.stepper->time() - end_time) > 1e-9 ||
          (k > 0 && (result.steps != steps || result.newton_iterations != iterations)))
        {
          std::cerr << "bench_time: check failed: run " << k << " ended at t = "
                    << run.stepper->time() << " s (the waveform ends at " << end_time
                    << " s) after " << result.steps << " steps and " << result.newton_iterations
                    << " Newton iterations (the first run: " << steps << ", " << iterations
                    << ")\n";
          std::filesystem::remove_all(out);
          return 1;
        }
      steps      = result.steps;
      iterations = result.newton_iterations;
      run_time.push_back(t);
      run_cpu.push_back(cpu_seconds(RUSAGE_SELF) - cpu_start);
      per_step.push_back(t / steps);
      per_iteration.push_back(t / std::max(1u, iterations));
    }

  // Whole processes, interleaved with the quasi-static default case (its
  // process is almost all start-up: the reference for what the time run adds).
  const std::string reference =
    cdea_bench::prm_writing_to(std::string(CDEA_SOURCE_DIR) + "/prm/default.prm", out / "default");
  std::vector<double> process_time, process_cpu, reference_time;
  for (int k = 0; k < process_runs; ++k)
    for (const std::string *run : {&prm, &reference})
      {
        const auto   start     = std::chrono::steady_clock::now();
        const double cpu_start = cpu_seconds(RUSAGE_CHILDREN);
        const int    rc        = std::system(
          (std::string(CDEA_EXECUTABLE) + " run " + *run + " > /dev/null").c_str());
        const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (rc != 0)
          {
            std::cerr << "bench_time: cdea run " << *run << " failed\n";
            std::filesystem::remove_all(out);
            return 1;
          }
        if (run == &prm)
          {
            process_time.push_back(wall);
            process_cpu.push_back(cpu_seconds(RUSAGE_CHILDREN) - cpu_start);
          }
        else
          reference_time.push_back(wall);
      }
  std::filesystem::remove_all(out);

  using cdea_bench::median;
  std::cout << std::setprecision(4) << "case: " << file
            << (cycles > 0 ? " with " + std::to_string(cycles) + " cycles" : std::string()) << "\n"
            << "simulated time: " << settings.waveform.end_time() << " s, time step "
            << settings.max_step << " s, steps reported: " << steps
            << ", Newton iterations: " << iterations << ", runs: " << runs << "\n"
            << "median time per run (no output):  " << median(run_time) * 1e3 << " ms (CPU "
            << median(run_cpu) * 1e3 << " ms)\n"
            << "median time per step:             " << median(per_step) * 1e6 << " us\n"
            << "median time per Newton iteration: " << median(per_iteration) * 1e6 << " us\n";
  if (process_runs > 0)
    std::cout << "whole process `cdea run`, median of " << process_runs << ": "
              << median(process_time) * 1e3 << " ms (CPU " << median(process_cpu) * 1e3
              << " ms); the quasi-static default case, interleaved: "
              << median(reference_time) * 1e3 << " ms\n";
  return 0;
}
