// Benchmark: a time-dependent run (doc/time.md, doc/performance.md), by
// default the pump scene prm/pump-time.prm (30 cycles of a 0.5 Hz square wave,
// viscoelastic film, disk inertia, water load, ESDIRK4 with error control:
// the parameter file's default time settings).
//
//  1. The run in one process without output, several times: median wall and
//     CPU time of a run, per time step and per Newton iteration.
//  2. Old against new (square waves): the old scheme of the scene, backward
//     Euler with fixed steps of 1.25 ms (the step doc/time.md's scene 3
//     needed), and the new default, each with its steps, CPU time and the
//     error of the last cycle's stroke against a converged reference. The
//     stroke is z(A)'s mean over the last tenth of the on half minus that
//     over the last tenth of the off half (the level drop's likewise), as
//     postprocess/plot_time.py reads the levels. The reference is ESDIRK4 at
//     relative and absolute tolerance 1e-9 (mm): stored for the unchanged
//     prm/pump-time.prm (made by `bench_time prm/pump-time.prm 0 0 0 0
//     --reference`), computed in-process otherwise.
//  3. The whole program (`cdea run FILE.prm`, output to a temporary folder)
//     as a user runs it: median wall time of a process, interleaved with
//     processes of the quasi-static default case (prm/default.prm), whose
//     time is almost all start-up.
//
//   build/benchmarks/bench_time [FILE.prm] [CYCLES] [RUNS] [PROCESS_RUNS] [OLD_RUNS] [--reference]
//
// CYCLES (if given and > 0) replaces Time/Cycles, for a quick smoke run:
//   build/benchmarks/bench_time "" 1 1 1 1
// OLD_RUNS (default 1; 0 leaves part 2 out) runs of the old scheme;
// --reference computes the reference in-process even where one is stored.
//
// Checked (exit code 1 otherwise): every timed run completes, reaches the
// waveform's end time (to 1e-9 s, as tests/test_python_time.py asks of the
// program) and reports the same steps and Newton iterations as the first (the
// runs time the same work); every process exits with 0.

#include <cdea/base/format.h>
#include <cdea/input/solver_settings.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameters.h>
#include <cdea/input/parameter_input.h>
#include <cdea/analysis/time_run.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/model/output_fields.h>
#include <cdea/solver/time_stepper.h>

#include "bench_common.h"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace cdea;

namespace
{
  /// The converged last-cycle stroke and level of prm/pump-time.prm as
  /// committed (ESDIRK4 at relative and absolute tolerance 1e-9).
  constexpr double stored_stroke_mm = 3.46788163;
  constexpr double stored_level_mm  = 38.93186983;

  /// CPU time (user + system) of this process or of its finished children (s).
  double cpu_seconds(const int who)
  {
    rusage u{};
    getrusage(who, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }

  /// Time means of a piecewise-linear signal over fixed windows [a, b].
  struct WindowMeans
  {
    std::vector<std::pair<double, double>> windows;
    std::vector<double>                    integral;
    double                                 t0 = std::nan(""), y0 = 0.;

    explicit WindowMeans(std::vector<std::pair<double, double>> w)
      : windows(std::move(w))
      , integral(windows.size(), 0.)
    {}

    void add(const double t1, const double y1)
    {
      if (!std::isnan(t0) && t1 > t0)
        for (std::size_t k = 0; k < windows.size(); ++k)
          {
            const double a = std::max(windows[k].first, t0), b = std::min(windows[k].second, t1);
            if (b <= a)
              continue;
            const auto y = [&](const double t) { return y0 + (y1 - y0) * (t - t0) / (t1 - t0); };
            integral[k] += 0.5 * (y(a) + y(b)) * (b - a);
          }
      t0 = t1;
      y0 = y1;
    }

    double mean(const std::size_t k) const
    {
      return integral[k] / (windows[k].second - windows[k].first);
    }
  };

  struct Measured
  {
    unsigned int steps = 0, rejected = 0; ///< the time integration's
    unsigned int rows = 0, iterations = 0; ///< steps reported, Newton iterations
    double       wall = 0., cpu = 0.;
    double       stroke_mm = std::nan(""), level_mm = std::nan("");
    bool         completed = false;
  };

  /// One in-process run of @p p (nothing written); with a square wave the
  /// last cycle's stroke and level drop (B - A, means over the last tenth of
  /// each half).
  Measured measure(const Parameters &p, const Scene &scene)
  {
    const auto   start     = std::chrono::steady_clock::now();
    const double cpu_start = cpu_seconds(RUSAGE_SELF);
    TimeRunSetup run       = set_up_time_run(p, scene);
    const double end = run.settings.waveform.end_time(), f = run.settings.waveform.frequency();
    const double period = f > 0. ? 1. / f : 0.;
    const std::vector<std::pair<double, double>> windows = {
      {end - 0.6 * period, end - 0.5 * period}, {end - 0.1 * period, end}};
    WindowMeans z(windows), level(windows);
    run.stepper->on_step = [&](const StepSummary &s) {
      const double t = s.columns.in_file_units(summary_column::waveform_time);
      if (std::isnan(t))
        return;
      z.add(t, s.displacement * 1e3);
      level.add(t, s.columns.in_file_units(summary_column::level_drop));
    };
    const RunResult result = run.stepper->run();
    Measured        m;
    m.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m.cpu  = cpu_seconds(RUSAGE_SELF) - cpu_start;
    m.completed = result.completed;
    m.steps     = result.time_steps > 0 ? result.time_steps : result.steps;
    m.rejected  = result.rejected_steps;
    m.rows       = result.steps;
    m.iterations = result.newton_iterations;
    if (!m.completed)
      std::cerr << "bench_time: run did not complete: " << result.message << '\n';
    else if (std::abs(run.stepper->time() - end) > 1e-9)
      {
        std::cerr << "bench_time: check failed: the run ended at t = " << run.stepper->time()
                  << " s, the waveform ends at " << end << " s\n";
        m.completed = false;
      }
    if (p.time.waveform == WaveformKind::square)
      {
        m.stroke_mm = z.mean(0) - z.mean(1);
        m.level_mm  = level.mean(0) - level.mean(1);
      }
    return m;
  }

  /// Part 2: the old scheme and the new default against the reference.
  bool old_against_new(const Parameters &p, const Scene &scene, const int old_runs,
                       const bool stored, const Measured &fresh)
  {
    Parameters old = p;
    old.time.scheme      = TimeMethod::backward_euler;
    old.time.step_control = TimeStepControl::fixed;
    old.time.time_step_s = 0.00125;
    std::vector<Measured> before;
    std::vector<double>   before_cpu;
    for (int k = 0; k < old_runs; ++k)
      {
        before.push_back(measure(old, scene));
        before_cpu.push_back(before.back().cpu);
        if (!before.back().completed)
          return false;
      }
    double reference = stored_stroke_mm, reference_level = stored_level_mm;
    if (!stored)
      {
        Parameters tight = p;
        tight.time.scheme                = TimeMethod::esdirk4;
        tight.time.step_control          = TimeStepControl::error;
        tight.time.relative_tolerance    = 1e-9;
        tight.time.absolute_tolerance_mm = 1e-9;
        const Measured r = measure(tight, scene);
        if (!r.completed)
          return false;
        reference       = r.stroke_mm;
        reference_level = r.level_mm;
      }
    const auto line = [&](const std::string &name, const Measured &m, const double cpu) {
      std::cout << std::left << std::setw(34) << name << std::right << std::setw(7) << m.steps
                << " steps " << std::setw(9) << std::setprecision(4) << cpu * 1e3
                << " ms CPU   stroke " << std::setprecision(9) << m.stroke_mm << " mm, error "
                << std::setprecision(2) << std::abs(m.stroke_mm / reference - 1.)
                << "; level " << std::setprecision(9) << m.level_mm << " mm, error "
                << std::setprecision(2) << std::abs(m.level_mm / reference_level - 1.) << '\n';
    };
    std::cout << "old against new (last cycle; reference " << std::setprecision(9) << reference
              << " mm stroke, " << reference_level << " mm level, "
              << (stored ? "stored" : "computed: ESDIRK4 at 1e-9") << "):\n";
    line("old: backward Euler, fixed 1.25 ms", before.front(), cdea_bench::median(before_cpu));
    line("new: " + to_string(p.time.scheme) + ", error control at " +
           format_number(p.time.relative_tolerance),
         fresh, fresh.cpu);
    std::cout << std::setprecision(4) << "steps new / old: "
              << double(fresh.steps) / before.front().steps
              << ", CPU new / old: " << fresh.cpu / cdea_bench::median(before_cpu) << '\n';
    return true;
  }
  /// Part 1: @p runs in-process runs of @p p; the first one's measurement.
  Measured time_in_process(const Parameters &p, const Scene &scene, const int runs,
                           const std::string &title)
  {
    std::vector<double> run_time, run_cpu, per_step, per_iteration;
    Measured            first;
    for (int k = 0; k < runs; ++k)
      {
        const Measured m = measure(p, scene);
        if (!m.completed)
          return m;
        if (k == 0)
          first = m;
        else if (m.rows != first.rows || m.iterations != first.iterations)
          {
            std::cerr << "bench_time: check failed: run " << k << " took " << m.rows
                      << " steps and " << m.iterations << " Newton iterations, the first "
                      << first.rows << " and " << first.iterations << '\n';
            Measured failed = m;
            failed.completed = false;
            return failed;
          }
        run_time.push_back(m.wall);
        run_cpu.push_back(m.cpu);
        per_step.push_back(m.wall / m.rows);
        per_iteration.push_back(m.wall / std::max(1u, m.iterations));
      }
    const TimeSettings settings = time_settings(p, scene);
    const bool         sized = esdirk_tableau(p.time.scheme) && p.time.step_control == TimeStepControl::error;
    using cdea_bench::median;
    std::cout << std::setprecision(4) << "case: " << title << "\n"
              << "simulated time: " << settings.waveform.end_time() << " s, "
              << to_string(p.time.scheme) << (sized ? ", time steps up to " : ", time step ")
              << settings.max_step << " s, steps reported: " << first.rows
              << ", Newton iterations: " << first.iterations << ", runs: " << runs << "\n"
              << "median time per run (no output):  " << median(run_time) * 1e3 << " ms (CPU "
              << median(run_cpu) * 1e3 << " ms)\n"
              << "median time per step:             " << median(per_step) * 1e6 << " us\n"
              << "median time per Newton iteration: " << median(per_iteration) * 1e6 << " us\n";
    first.completed = runs > 0;
    return first;
  }

  /// Part 3: whole processes of @p prm, interleaved with the quasi-static
  /// default case (its process is almost all start-up: the reference for
  /// what the time run adds), writing into @p out.
  bool time_processes(const std::string &prm, const std::filesystem::path &out, const int runs)
  {
    const std::string reference = cdea_bench::prm_writing_to(
      std::string(CDEA_SOURCE_DIR) + "/prm/default.prm", out / "default");
    std::vector<double> process_time, process_cpu, reference_time;
    for (int k = 0; k < runs; ++k)
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
              return false;
            }
          if (run == &prm)
            {
              process_time.push_back(wall);
              process_cpu.push_back(cpu_seconds(RUSAGE_CHILDREN) - cpu_start);
            }
          else
            reference_time.push_back(wall);
        }
    using cdea_bench::median;
    if (runs > 0)
      std::cout << std::setprecision(4) << "whole process `cdea run`, median of " << runs << ": "
                << median(process_time) * 1e3 << " ms (CPU " << median(process_cpu) * 1e3
                << " ms); the quasi-static default case, interleaved: "
                << median(reference_time) * 1e3 << " ms\n";
    return true;
  }

  /// The three parts on the copy @p prm of @p file.
  bool bench(const std::string &file, const std::string &prm, const std::filesystem::path &out,
             const std::vector<int> &counts, const bool stored)
  {
    const int  cycles = counts[0], runs = counts[1], process_runs = counts[2], old_runs = counts[3];
    Parameters p;
    try
      {
        p = read_parameters(prm);
      }
    catch (const InputError &e)
      {
        std::cerr << "bench_time: " << e.what() << '\n';
        return false;
      }
    if (!p.time.enabled)
      {
        std::cerr << "bench_time: " << file << " is not a time run (Time/Enabled = false)\n";
        return false;
      }
    const Scene    scene = p.scene();
    const Measured fresh = time_in_process(
      p, scene, std::max(runs, 1),
      file + (cycles > 0 ? " with " + std::to_string(cycles) + " cycles" : std::string()));
    if (!fresh.completed)
      return false;
    if (old_runs > 0 && p.time.waveform == WaveformKind::square &&
        !old_against_new(p, scene, old_runs, stored, fresh))
      return false;
    return time_processes(prm, out, process_runs);
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession         mpi(argc, argv);
  bool                     compute_reference = false;
  std::vector<std::string> args;
  for (int k = 1; k < argc; ++k)
    if (std::strcmp(argv[k], "--reference") == 0)
      compute_reference = true;
    else
      args.emplace_back(argv[k]);
  const std::string pump = std::string(CDEA_SOURCE_DIR) + "/prm/pump-time.prm";
  const std::string file = !args.empty() && !args[0].empty() ? args[0] : pump;
  std::vector<int>  counts = {0, 5, 5, 1}; // cycles, runs, processes, old runs
  for (std::size_t k = 1; k < args.size() && k <= counts.size(); ++k)
    counts[k - 1] = std::atoi(args[k].c_str());

  // A copy of the file writing into a temporary folder, with the cycles.
  const std::filesystem::path out =
    std::filesystem::temp_directory_path() / ("cdea-bench-time-" + std::to_string(getpid()));
  const std::string prm = cdea_bench::prm_writing_to(file, out);
  if (counts[0] > 0)
    std::ofstream(prm, std::ios::app) << "subsection Time\n  set Cycles = " << counts[0] << "\nend\n";
  const bool stored = !compute_reference && counts[0] <= 0 && std::filesystem::exists(file) &&
                      std::filesystem::equivalent(file, pump);
  const bool ok = bench(file, prm, out, counts, stored);
  std::filesystem::remove_all(out);
  return ok ? 0 : 1;
}
