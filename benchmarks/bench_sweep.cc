// Benchmark of `cdea sweep`: a full design map (prm/sweep-inner5.prm: 29 r_v/a
// x 61 outer voltages with both lines, or the file given).
//
// 1. In-process, one core: the map computed RUNS times by compute_sweep_map()
//    (no file output); median wall time, time per equilibrium solve and per
//    Newton iteration, and where the solves go (load stages up to the base
//    state, continuation, root finding of the lines, failed solves near folds).
// 2. Whole processes as a user runs them, each PROCESS_RUNS times:
//    `cdea sweep FILE` and `mpirun -np 2 cdea sweep FILE`; median wall times
//    and the speed-up on 2 ranks (start-up of the process included).
//
//   build/benchmarks/bench_sweep [FILE.prm] [RUNS] [PROCESS_RUNS] [RANKS]
//
// Figures in doc/design-maps.md come from this program.

#include <cdea/app/commands.h>
#include <cdea/app/mpi_session.h>
#include <cdea/app/parameters.h>
#include <cdea/app/sweep.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/solver/load_stepper.h>

#include "bench_common.h"

#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <regex>
#include <string>
#include <vector>

using namespace cdea;

namespace
{
  using cdea_bench::median;

  /// CPU time of this process (s): unlike wall time, hardly affected by
  /// other jobs on the machine.
  double cpu_seconds()
  {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }

  /// User + system CPU time of all waited-for children so far (s).
  double children_cpu_seconds()
  {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec +
           1e-6 * u.ru_stime.tv_usec;
  }

  struct CommandTimes
  {
    double wall = std::numeric_limits<double>::quiet_NaN(); ///< median, whole process
    double map  = std::numeric_limits<double>::quiet_NaN(); ///< median, as cdea reports it
    double cpu  = std::numeric_limits<double>::quiet_NaN(); ///< median CPU time, all processes
  };

  /// Medians over @p runs executions of a `cdea sweep` command line: the wall
  /// time of the process(es) and the map time the program prints ("... 0.5 s
  /// on 2 ranks": from reading the input to the gathered map, before the file
  /// is written). Output goes to @p log.
  CommandTimes time_command(const std::string &command, const std::string &log, const int runs)
  {
    std::vector<double> wall, map, cpu;
    for (int k = 0; k < runs; ++k)
      {
        const double cpu0  = children_cpu_seconds();
        const auto   start = std::chrono::steady_clock::now();
        const int    rc    = std::system((command + " > " + log + " 2>&1").c_str());
        wall.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        cpu.push_back(children_cpu_seconds() - cpu0);
        if (rc != 0)
          {
            std::cerr << "bench_sweep: command failed (" << rc << "): " << command << '\n';
            return {};
          }
        std::ifstream in(log);
        std::string   line;
        const std::regex pattern(R"(([0-9.eE+-]+) s on [0-9]+ ranks?)");
        std::smatch      match;
        while (std::getline(in, line))
          if (std::regex_search(line, match, pattern))
            map.push_back(std::stod(match[1]));
      }
    CommandTimes t;
    t.wall = median(wall);
    t.cpu  = median(cpu);
    if (map.size() == wall.size())
      t.map = median(map);
    return t;
  }

  std::string load_average()
  {
    std::ifstream in("/proc/loadavg");
    std::string   a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession  mpi(argc, argv);
  const std::string file =
    argc > 1 ? argv[1] : std::string(CDEA_SOURCE_DIR) + "/prm/sweep-inner5.prm";
  const int runs         = argc > 2 ? std::atoi(argv[2]) : 7;
  const int process_runs = argc > 3 ? std::atoi(argv[3]) : 5;
  const int ranks        = argc > 4 ? std::atoi(argv[4]) : 2;

  Parameters    p;
  Scene         base;
  SweepSettings settings;
  try
    {
      p        = read_parameters(file);
      base     = p.scene();
      settings = sweep_settings(p, base);
    }
  catch (const InputError &e)
    {
      std::cerr << "bench_sweep: " << e.what() << '\n';
      return 1;
    }
  const std::size_t n = settings.ring_edge_values.size(), m = settings.outer_voltages.size();

  // 1. In-process, serial.
  std::vector<double> wall, cpu, per_solve, per_iteration, base_share, line_share, rows_share;
  SweepMap            map;
  for (int k = 0; k < runs; ++k)
    {
      const double cpu0  = cpu_seconds();
      const auto   start = std::chrono::steady_clock::now();
      map                = compute_sweep_map(p, base, settings);
      cpu.push_back(cpu_seconds() - cpu0);
      const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      unsigned long solves = 0, iterations = 0;
      double        base_t = 0., line_t = 0., rows_t = 0.;
      for (const SweepRow &r : map.rows)
        {
          solves += r.solves;
          iterations += r.newton_iterations;
          base_t += r.base_seconds;
          line_t += r.line_seconds;
          rows_t += r.seconds;
        }
      base_share.push_back(base_t / t);
      line_share.push_back(line_t / t);
      rows_share.push_back(rows_t / t);
      wall.push_back(t);
      per_solve.push_back(t / solves);
      per_iteration.push_back(t / iterations);
    }
  unsigned long solves = 0, iterations = 0, base_s = 0, base_i = 0, line_s = 0, line_i = 0,
                failed_s = 0, failed_i = 0, reached = 0;
  for (const SweepRow &r : map.rows)
    {
      solves += r.solves;
      iterations += r.newton_iterations;
      base_s += r.base_solves;
      base_i += r.base_iterations;
      line_s += r.line_solves;
      line_i += r.line_iterations;
      failed_s += r.failed_solves;
      failed_i += r.failed_iterations;
      for (const double d : r.displacement)
        reached += !std::isnan(d);
    }
  const unsigned long path_s = solves - base_s - line_s - failed_s;
  const unsigned long path_i = iterations - base_i - line_i - failed_i;

  std::cout << std::setprecision(4) << "case: " << file << "\n"
            << "load average at the start (1, 5, 15 min): " << load_average() << "\n"
            << "map: " << n << " r_v/a x " << m << " outer voltages = " << n * m
            << " points, " << reached << " reached; in-process runs: " << runs << "\n"
            << "equilibrium solves per map: " << solves << ", Newton iterations: " << iterations
            << "\n"
            << "  load stages to the base state:   " << std::setw(6) << base_s << " solves "
            << std::setw(6) << base_i << " iterations\n"
            << "  continuation (converged steps):  " << std::setw(6) << path_s << " solves "
            << std::setw(6) << path_i << " iterations\n"
            << "  root finding of the two lines:   " << std::setw(6) << line_s << " solves "
            << std::setw(6) << line_i << " iterations\n"
            << "  failed solves (cut-backs, folds):" << std::setw(6) << failed_s << " solves "
            << std::setw(6) << failed_i << " iterations\n"
            << "median wall time of a map, in-process, 1 core: " << median(wall) * 1e3
            << " ms (min " << *std::min_element(wall.begin(), wall.end()) * 1e3 << ", max "
            << *std::max_element(wall.begin(), wall.end()) * 1e3 << ")\n"
            << "median CPU time of a map, in-process:           " << median(cpu) * 1e3
            << " ms\n"
            << "median time per equilibrium solve:  " << median(per_solve) * 1e6 << " us\n"
            << "median time per Newton iteration:   " << median(per_iteration) * 1e6
            << " us\n"
            << "median time per map point:          " << median(wall) / (n * m) * 1e6
            << " us\n"
            << "share of the map time (medians): load stages to the base state "
            << 100. * median(base_share) << " %, continuation "
            << 100. * (median(rows_share) - median(base_share) - median(line_share))
            << " %, root finding " << 100. * median(line_share) << " %, outside the rows "
            << "(zero-voltage state, model set-up) " << 100. * (1. - median(rows_share))
            << " %\n"
            << std::flush;

  // Where the time goes: the pieces of a row, timed one by one on the
  // r_v/a = 1.7 layout (medians of repeated calls).
  {
    const Scene   scene = sweep_scene(base, 1.7, settings.inner_voltage);
    auto          time  = [](const std::function<void()> &f, const int repeat) {
      std::vector<double> t;
      for (int k = 0; k < repeat; ++k)
        {
          const auto start = std::chrono::steady_clock::now();
          f();
          t.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
      return median(t);
    };
    const double t_model = time(
      [&] { MembraneModel model(scene, fe_discretization(p), newton_settings(p)); }, 21);
    MembraneModel model(scene, fe_discretization(p), newton_settings(p));
    unsigned int  base_iterations = 0;
    const double  t_base          = time(
      [&] {
        LoadStepper stepper(scene, model, sweep_stepping_settings(p));
        base_iterations = stepper.run().newton_iterations;
      },
      11);
    unsigned int stable_iterations = 0;
    const double t_base_stable     = time(
      [&] {
        SteppingSettings with = sweep_stepping_settings(p);
        with.stability_check  = true;
        LoadStepper stepper(scene, model, with);
        stable_iterations = stepper.run().newton_iterations;
      },
      11);
    const double t_summary = time([&] { (void)model.summary(); }, 501);
    const ModelState x = model.state();
    const double t_state = time([&] { model.set_state(model.state()); }, 501);
    // One Newton iteration: solve from a slightly perturbed converged state.
    LoadState load;
    load.stage    = Stage::voltage;
    load.stretch  = scene.prestretch;
    load.mass     = scene.mass;
    load.force    = scene.dead_load();
    load.voltages = {settings.inner_voltage, settings.inner_voltage + 50.};
    model.solve(load);
    const ModelState converged = model.state();
    unsigned int              its       = 0;
    const double t_solve = time(
      [&] {
        model.set_state(converged);
        model.predict(x, -1.); // the previous step's state as the guess
        its = model.solve(load).iterations;
      },
      101);
    const double        t_iter = t_solve / std::max(1u, its);
    const double        est_newton  = iterations * t_iter;
    const double        est_summary = (solves - failed_s) * t_summary;
    const double        est_model   = n * t_model;
    const double        map_time    = median(wall);
    std::cout << "pieces (r_v/a = 1.7, medians of repeated calls):\n"
              << "  unknowns of a layout's FE model:              " << model.n_dofs() << " ("
              << model.n_elements() << " elements of degree " << p.discretization.polynomial_degree
              << ")\n"
              << "  build a MembraneModel (mesh, dofs, sparsity):  " << t_model * 1e6 << " us\n"
              << "  load stages to the base state (one row):      " << t_base * 1e3 << " ms, "
              << base_iterations << " Newton iterations\n"
              << "  the same with Solver/Stability check on:      " << t_base_stable * 1e3
              << " ms, " << stable_iterations << " Newton iterations\n"
              << "  a 50 V continuation step from the converged state: " << t_solve * 1e6
              << " us, " << its << " Newton iterations -> " << t_iter * 1e6
              << " us per iteration\n"
              << "  summary() (s2 at the ring edges):             " << t_summary * 1e6 << " us\n"
              << "  state() + set_state():                        " << t_state * 1e6 << " us\n"
              << "estimated share of the map time: Newton iterations "
              << 100. * est_newton / map_time << " %, summaries "
              << 100. * est_summary / map_time << " %, model set-up "
              << 100. * est_model / map_time << " %\n"
              << std::flush;
  }
  if (process_runs <= 0)
    return 0;

  // 2. Whole processes, serial and on `ranks` ranks.
  const std::filesystem::path out =
    std::filesystem::temp_directory_path() / ("cdea-bench-sweep-" + std::to_string(getpid()));
  const std::string prm = cdea_bench::prm_writing_to(file, out);
  // A child mpirun must not inherit this process's (singleton) MPI environment.
  const std::string clean_env =
    "env $(env | grep -E '^(OMPI_|PMIX_|OPAL_|HYDRA_|PMI_)' | cut -d= -f1 | sed 's/^/-u /') ";
  const std::string exe = CDEA_EXECUTABLE;
  const std::string log = (out / "log.txt").string();
  const CommandTimes serial =
    time_command(clean_env + exe + " sweep " + prm, log, process_runs);
  const std::string mpirun = "mpirun --oversubscribe" +
                             std::string(geteuid() == 0 ? " --allow-run-as-root" : "") +
                             " -np " + std::to_string(ranks) + " ";
  const CommandTimes parallel =
    time_command(clean_env + mpirun + exe + " sweep " + prm, log, process_runs);
  std::filesystem::remove_all(out);
  std::cout << "whole process `cdea sweep`, median of " << process_runs << ": "
            << serial.wall * 1e3 << " ms (map, as cdea reports it: " << serial.map * 1e3
            << " ms; CPU time " << serial.cpu * 1e3 << " ms)\n"
            << "whole process `mpirun -np " << ranks << " cdea sweep`, median of "
            << process_runs << ": " << parallel.wall * 1e3
            << " ms (map: " << parallel.map * 1e3 << " ms; CPU time of all processes "
            << parallel.cpu * 1e3 << " ms)\n"
            << "speed-up on " << ranks << " ranks: whole process " << serial.wall / parallel.wall
            << ", map " << serial.map / parallel.map << "\n"
            << "load average at the end: " << load_average() << '\n';
  return 0;
}
