// Benchmark of `cdea sweep`: a full design map (prm/sweep-inner5.prm: 29 r_v/a
// x 61 outer voltages with both lines, or the file given).
//
// 1. In-process, one core: the map computed RUNS times by compute_sweep_map()
//    (no file output); median wall and CPU time, time per equilibrium solve
//    and per Newton iteration, and where the solves go (load stages up to the
//    base state, continuation, root finding of the lines, failed solves near
//    folds, as the rows count them). Then the pieces of a row, timed one by
//    one on the r_v/a = 1.7 layout; among them the load stages to the base
//    state (CPU medians) without the stability check, with it and the
//    eigenvalue at every step, and with it near folds (Solver/Stability
//    eigenvalue), with their ratios to the first.
// 2. Whole processes as a user runs them, each PROCESS_RUNS times (0: none):
//    `cdea sweep FILE` and `mpirun -np RANKS cdea sweep FILE`; median wall
//    times and the speed-up on RANKS ranks (start-up of the process included).
//
//   build/benchmarks/bench_sweep [FILE.prm] [RUNS] [PROCESS_RUNS] [RANKS]
//
// Fails (exit code 1) if a row does not reach its base state, a row has no
// red line, a figure is not finite, the three load-stage runs end in
// different states (final displacement, bit for bit), or the stable columns
// of the two checks differ (or an eigenvalue near folds differs from every
// step's by more than 1e-10 relative); ctest runs it with 1 0 (label
// bench-smoke). doc/design-maps.md ("Speed") quotes it.

#include <cdea/input/solver_settings.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/design/sweep.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/model/output_fields.h>
#include <cdea/solver/load_stepper.h>

#include "bench_common.h"

#include <sys/resource.h>

#include <iomanip>
#include <regex>
#include <sstream>

using namespace cdea;
using namespace cdea_bench;

namespace
{
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
    double wall, map, cpu; ///< medians: whole process, map as cdea reports it, CPU of all
  };

  /// Medians over @p runs executions of a `cdea sweep` command line; the map
  /// time is what the program prints ("... 0.5 s on 2 ranks": from reading
  /// the input to the gathered map). Output goes to @p log.
  CommandTimes time_command(const std::string &command, const std::string &log, const int runs)
  {
    std::vector<double> wall, map, cpu;
    const std::regex    pattern(R"(([0-9.eE+-]+) s on [0-9]+ ranks?)");
    for (int k = 0; k < runs; ++k)
      {
        const double     cpu0 = children_cpu_seconds();
        const ProcessRun r    = time_process(command + " > " + log + " 2>&1");
        require(r.exit_code == 0, "command failed (" + std::to_string(r.exit_code) + "): " +
                                    command);
        wall.push_back(r.seconds);
        cpu.push_back(children_cpu_seconds() - cpu0);
        std::ifstream in(log);
        std::string   line;
        std::smatch   match;
        while (std::getline(in, line))
          if (std::regex_search(line, match, pattern))
            map.push_back(std::stod(match[1]));
      }
    return {median(wall), map.size() == wall.size() ? median(map) : std::nan(""), median(cpu)};
  }

  std::string load_average()
  {
    std::ifstream in("/proc/loadavg");
    std::string   a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
  }

  /// Totals of a map's rows.
  struct Counts
  {
    unsigned long solves = 0, iterations = 0, base_s = 0, base_i = 0, line_s = 0, line_i = 0,
                  failed_s = 0, failed_i = 0, reached = 0;
    double        base_t = 0., line_t = 0., rows_t = 0.;
  };

  Counts count(const SweepMap &map)
  {
    Counts c;
    for (const SweepRow &r : map.rows)
      {
        c.solves += r.solves;
        c.iterations += r.newton_iterations;
        c.base_s += r.base_solves;
        c.base_i += r.base_iterations;
        c.line_s += r.line_solves;
        c.line_i += r.line_iterations;
        c.failed_s += r.failed_solves;
        c.failed_i += r.failed_iterations;
        c.base_t += r.base_seconds;
        c.line_t += r.line_seconds;
        c.rows_t += r.seconds;
        for (const double d : r.displacement)
          c.reached += !std::isnan(d);
        require(r.base_reached, "row r_v/a = " + std::to_string(r.rv_over_a) +
                                  " did not reach its base state: " + r.message);
        require_finite(r.red.outer_voltage, "the red line of r_v/a = " + std::to_string(r.rv_over_a));
      }
    return c;
  }

  /// The load stages to the base state of one row, as a LoadStepper runs them.
  struct StageRun
  {
    double              seconds    = 0.; ///< CPU median of 11
    unsigned int        iterations = 0;  ///< Newton iterations
    double              displacement = 0.; ///< of the final state
    std::vector<double> stable, eigenvalue;  ///< the columns, at every step
  };

  StageRun load_stages(const Scene &scene, MembraneModel &model, const SteppingSettings &settings)
  {
    StageRun r;
    r.seconds = median_time(
      [&] {
        r.stable.clear();
        r.eigenvalue.clear();
        LoadStepper stepper(scene, model, settings);
        stepper.on_step = [&](const StepSummary &s) {
          r.stable.push_back(s.columns.get(summary_column::stable));
          r.eigenvalue.push_back(s.columns.get(summary_column::min_eigenvalue));
        };
        r.iterations   = stepper.run().newton_iterations;
        r.displacement = model.displacement();
      },
      11, cpu_seconds);
    return r;
  }

  /// The load stages without the stability check, with it (the eigenvalue at
  /// every step) and with it near folds; fails unless the three reach the
  /// same state (bitwise) and the two checks give the same stable column.
  void time_load_stages(const Scene &scene, MembraneModel &model, const SteppingSettings &off)
  {
    SteppingSettings every = off;
    every.stability_check  = true;
    SteppingSettings near  = every;
    near.stability_eigenvalue = StabilityEigenvalue::near_folds;
    const StageRun a = load_stages(scene, model, off);
    const StageRun b = load_stages(scene, model, every);
    const StageRun c = load_stages(scene, model, near);
    require(a.displacement == b.displacement && a.displacement == c.displacement,
            "the load stages reach different states with and without the stability check");
    require(b.stable == c.stable && !b.stable.empty(),
            "the stable column near folds differs from that of the eigenvalue at every step");
    unsigned int computed = 0;
    for (std::size_t i = 0; i < c.eigenvalue.size(); ++i)
      if (!std::isnan(c.eigenvalue[i]))
        {
          ++computed;
          require(rel(c.eigenvalue[i], b.eigenvalue[i]) <= 1e-10,
                  "an eigenvalue near folds differs from that at every step");
        }
    std::cout << "  load stages to the base state (one row):      " << a.seconds * 1e3 << " ms, "
              << a.iterations << " Newton iterations (CPU medians of 11)\n"
              << "  with the check, eigenvalue at every step:     " << b.seconds * 1e3 << " ms ("
              << b.seconds / a.seconds << "x), " << b.iterations << " Newton iterations\n"
              << "  with the check, eigenvalue near folds:        " << c.seconds * 1e3 << " ms ("
              << c.seconds / a.seconds << "x), the eigenvalue at " << computed << " of "
              << c.eigenvalue.size() << " steps\n";
  }

  /// The pieces of a row on the r_v/a = 1.7 layout, one by one (medians of
  /// repeated calls), and the share of the map time they explain.
  void time_pieces(const Parameters &p, const Scene &base, const SweepSettings &settings,
                     const Counts &c, const std::size_t n_rows, const double map_time)
  {
    const Scene  scene   = sweep_scene(base, 1.7, settings.inner_voltage);
    const double t_model = median_time(
      [&] { MembraneModel model(scene, fe_discretization(p), newton_settings(p)); }, 21,
      wall_seconds);
    MembraneModel model(scene, fe_discretization(p), newton_settings(p));
    std::cout << "pieces (r_v/a = 1.7, medians of repeated calls):\n"
              << "  unknowns of a layout's FE model:              " << model.n_dofs() << " ("
              << model.n_elements() << " elements of degree "
              << p.discretization.polynomial_degree << ")\n"
              << "  build a MembraneModel (mesh, dofs, shapes):    " << t_model * 1e6 << " us\n";
    time_load_stages(scene, model, sweep_stepping_settings(p));
    const double     t_summary = median_time([&] { (void)model.summary(); }, 501, wall_seconds);
    const ModelState x         = model.state();
    const double     t_state =
      median_time([&] { model.set_state(model.state()); }, 501, wall_seconds);
    // One continuation step: 50 V up from the converged base state, from the
    // previous state's linear extrapolation.
    LoadState load = model.load();
    load.voltages  = {settings.inner_voltage, settings.inner_voltage + 50.};
    require(model.solve(load).converged, "a 50 V continuation step did not converge");
    const ModelState converged = model.state();
    unsigned int     its       = 0;
    const double     t_solve   = median_time(
      [&] {
        model.set_state(converged);
        model.predict(x, -1.); // the previous step's state as the guess
        its = model.solve(load).iterations;
      },
      101, wall_seconds);
    const double t_iter = t_solve / std::max(1u, its);
    require_finite(t_iter, "the time of a Newton iteration", true);
    std::cout << "  a 50 V continuation step from the converged state: " << t_solve * 1e6
              << " us, " << its << " Newton iterations -> " << t_iter * 1e6
              << " us per iteration\n"
              << "  summary() (s2 at the ring edges):             " << t_summary * 1e6 << " us\n"
              << "  state() + set_state():                        " << t_state * 1e6 << " us\n"
              << "estimated share of the map time: Newton iterations "
              << 100. * c.iterations * t_iter / map_time << " %, summaries "
              << 100. * (c.solves - c.failed_s) * t_summary / map_time << " %, model set-up "
              << 100. * n_rows * t_model / map_time << " %\n"
              << std::flush;
  }

  int benchmark(const std::string &file, const int runs, const int process_runs, const int ranks)
  {
    const Parameters    p        = read_parameters(file);
    const Scene         base     = p.scene();
    const SweepSettings settings = sweep_settings(p, base);
    const std::size_t   n = settings.ring_edge_values.size(), m = settings.outer_voltages.size();
    std::cout << std::setprecision(4) << "case: " << file << "\n"
              << "load average at the start (1, 5, 15 min): " << load_average() << "\n";

    // 1. In-process, serial.
    std::vector<double> wall, cpu, per_solve, per_iteration, base_share, line_share, rows_share;
    SweepMap            map;
    Counts              c;
    for (int k = 0; k < runs; ++k)
      {
        const double cpu0 = cpu_seconds(), start = wall_seconds();
        map               = compute_sweep_map(p, base, settings);
        cpu.push_back(cpu_seconds() - cpu0);
        const double t = wall_seconds() - start;
        c              = count(map);
        base_share.push_back(c.base_t / t);
        line_share.push_back(c.line_t / t);
        rows_share.push_back(c.rows_t / t);
        wall.push_back(t);
        per_solve.push_back(t / c.solves);
        per_iteration.push_back(t / c.iterations);
      }
    require(c.reached > 0, "no point of the map was reached");
    const unsigned long path_s = c.solves - c.base_s - c.line_s - c.failed_s;
    const unsigned long path_i = c.iterations - c.base_i - c.line_i - c.failed_i;
    const auto row = [](const unsigned long s, const unsigned long i) {
      std::ostringstream o;
      o << std::setw(6) << s << " solves " << std::setw(6) << i << " iterations\n";
      return o.str();
    };
    std::cout << "map: " << n << " r_v/a x " << m << " outer voltages = " << n * m
              << " points, " << c.reached << " reached; in-process runs: " << runs << "\n"
              << "equilibrium solves per map: " << c.solves
              << ", Newton iterations: " << c.iterations << "\n"
              << "  load stages to the base state:   " << row(c.base_s, c.base_i)
              << "  continuation (converged steps):  " << row(path_s, path_i)
              << "  root finding of the two lines:   " << row(c.line_s, c.line_i)
              << "  failed solves (cut-backs, folds):" << row(c.failed_s, c.failed_i)
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
    time_pieces(p, base, settings, c, n, median(wall));
    if (process_runs <= 0)
      return 0;

    // 2. Whole processes, serial and on `ranks` ranks.
    const OutputFolder out("", true);
    const std::string  prm = prm_writing_to(file, out.path());
    // A child mpirun must not inherit this process's (singleton) MPI environment.
    const std::string clean_env =
      "env $(env | grep -E '^(OMPI_|PMIX_|OPAL_|HYDRA_|PMI_)' | cut -d= -f1 | sed 's/^/-u /') ";
    const std::string  exe    = CDEA_EXECUTABLE;
    const std::string  log    = (out / "log.txt").string();
    const CommandTimes serial = time_command(clean_env + exe + " sweep " + prm, log, process_runs);
    const std::string  mpirun = "mpirun --oversubscribe" +
                               std::string(geteuid() == 0 ? " --allow-run-as-root" : "") +
                               " -np " + std::to_string(ranks) + " ";
    const CommandTimes parallel =
      time_command(clean_env + mpirun + exe + " sweep " + prm, log, process_runs);
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
} // namespace

int main(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  return guarded("bench_sweep", [&] {
    const std::string file =
      argc > 1 ? argv[1] : std::string(CDEA_SOURCE_DIR) + "/prm/sweep-inner5.prm";
    const int runs         = argc > 2 ? std::atoi(argv[2]) : 7;
    const int process_runs = argc > 3 ? std::atoi(argv[3]) : 5;
    const int ranks        = argc > 4 ? std::atoi(argv[4]) : 2;
    require(runs > 0 && ranks > 0, "RUNS and RANKS must be positive numbers");
    return benchmark(file, runs, process_runs, ranks);
  });
}
