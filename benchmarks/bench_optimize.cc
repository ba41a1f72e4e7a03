// Speed of `cdea optimize` and `cdea fit` as a user runs them (whole
// processes: loading the libraries, MPI start-up, input, work, files):
//
//   1. `cdea --help`: the start-up alone;
//   2. two rings, every edge and voltage free (Starts = STARTS);
//   3. RINGS rings (default 8), every edge and voltage free (Starts = STARTS);
//   4. a fit of shear modulus and Jlim to 20 points (two rings, synthetic data
//      at the paper's values with 0.02 mm of seeded noise).
//
// Each command runs RUNS times; printed: median and smallest wall time, the
// median CPU time of the process (user + system, far less affected by other
// jobs on a shared machine), and the work the program reports (evaluations or
// iterations, equilibrium solves, its own time).
//
// Every run's answer is checked (exit code 1 otherwise): the help names the
// commands; two rings reach the two-ring optimum of bench_partitioning
// (9.617312 mm, doc/optimization.md section 3) to 1e-5; RINGS rings lie
// between it and the straight cone (shooting/straight_cone.h), the limit of
// any partitioning; the fit recovers the synthetic data's mu = 25.1 kPa and
// Jlim = 270 within three of its own standard errors.
//
//   build/benchmarks/bench_optimize [RUNS [RINGS [STARTS]]]      (defaults 5 8 8)
//   build/benchmarks/bench_optimize --write-fit-data FILE.csv    (the example data)
//
// Files go to a temporary folder, removed at the end. Figures in
// doc/optimization.md.

#include <cdea/design/fit.h>
#include <cdea/design/sweep.h>
#include <cdea/base/mpi_session.h>
#include <cdea/shooting/straight_cone.h>

#include "bench_common.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <random>
#include <regex>
#include <sstream>

using namespace cdea;

namespace
{
  struct Timing
  {
    double wall = 0., cpu = 0.;
  };

  /// Run @p args (argv[0] the program) with stdout and stderr into @p log;
  /// its wall time and its own CPU time from wait4().
  Timing run_process(const std::vector<std::string> &args, const std::string &log, int &status)
  {
    std::cout.flush();
    std::fflush(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid  = fork();
    if (pid == 0)
      {
        if (!std::freopen(log.c_str(), "w", stdout) || dup2(fileno(stdout), 2) < 0)
          _exit(127);
        std::vector<char *> argv;
        for (const auto &a : args)
          argv.push_back(const_cast<char *>(a.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
      }
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    Timing t;
    t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.cpu  = usage.ru_utime.tv_sec + 1e-6 * usage.ru_utime.tv_usec + usage.ru_stime.tv_sec +
            1e-6 * usage.ru_stime.tv_usec;
    status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return t;
  }

  std::string slurp(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /// The counts the program prints on its last lines.
  std::string work_of(const std::string &output)
  {
    std::smatch m;
    static const std::regex optimize(R"((\d+) evaluations, (\d+) equilibrium solves, (\d+) Newton iterations, ([0-9.e-]+) s)");
    static const std::regex fit(R"((\d+) iterations, (\d+) evaluations, (\d+) equilibrium solves \((\d+) ramps\), ([0-9.e-]+) s)");
    if (std::regex_search(output, m, optimize))
      return m[1].str() + " evaluations, " + m[2].str() + " solves, in-process " + m[4].str() + " s";
    if (std::regex_search(output, m, fit))
      return m[1].str() + " iterations, " + m[2].str() + " evaluations, " + m[3].str() +
             " solves, in-process " + m[5].str() + " s";
    return "";
  }

  /// The benchmark's temporary folder (removed by main and on failure).
  std::filesystem::path output_folder;

  /// What a run's output must say; throws cdea_bench::Broken otherwise.
  using OutputCheck = std::function<void(const std::string &)>;

  void time_command(const std::string &what, const std::vector<std::string> &args,
                    const std::string &log, const int runs, const OutputCheck &check)
  {
    std::vector<double> wall, cpu;
    std::string         work;
    for (int k = 0; k < runs; ++k)
      {
        int          status = 0;
        const Timing t      = run_process(args, log, status);
        // 2: the optimizer stopped unconverged; still a measurement.
        if (status != 0 && status != 2)
          {
            std::cerr << "bench_optimize: '" << what << "' exited with " << status
                      << "; its output:\n"
                      << slurp(log);
            std::filesystem::remove_all(output_folder);
            std::exit(1);
          }
        const std::string output = slurp(log);
        try
          {
            check(output);
          }
        catch (const cdea_bench::Broken &e)
          {
            std::cerr << "bench_optimize: check failed: " << e.what() << "; the output:\n"
                      << output;
            std::filesystem::remove_all(output_folder);
            std::exit(1);
          }
        wall.push_back(t.wall);
        cpu.push_back(t.cpu);
        work = work_of(output) + (status == 2 ? " (NOT converged)" : "");
      }
    std::cout << std::left << std::setw(44) << what << std::right << std::fixed
              << std::setprecision(3) << std::setw(9) << cdea_bench::median(wall) << std::setw(9)
              << *std::min_element(wall.begin(), wall.end()) << std::setw(9)
              << cdea_bench::median(cpu) << "   " << work << std::endl;
  }

  /// 20 points of the paper's actuator with rings 1-1.7-3: both rings to
  /// 5 kV in 10 steps, then the outer one to 6.5 kV in 10 steps;
  /// displacements of the model at mu = 25.1 kPa, Jlim = 270 plus Gaussian
  /// noise of 0.02 mm (seed 2025).
  void write_fit_data(const std::string &file)
  {
    CalibrationData d;
    for (int k = 1; k <= 10; ++k)
      d.voltages.push_back({500. * k, 500. * k});
    for (int k = 1; k <= 10; ++k)
      d.voltages.push_back({5e3, 5e3 + 150. * k});
    d.weight.assign(20, 1.);
    d.displacement.assign(20, 0.);
    const Scene                       scene = paper_scene({1., 1.7, 3.}, {{5., 5.}});
    const std::vector<SceneParameter> free{{ParameterKind::shear_modulus, 0},
                                           {ParameterKind::jlim, 0}};
    DisplacementModel model(scene, d, free, FeDiscretization(), NewtonSettings(), SteppingSettings());
    Eigen::VectorXd   x;
    model.evaluate({25.1e3, 270.}, x, nullptr);
    std::mt19937                     generator(2025);
    std::normal_distribution<double> noise(0., 0.02);
    std::ofstream                    out(file);
    out << "# Synthetic measurement: cdea's model of the paper's actuator (rings 1, 1.7, 3;\n"
           "# mu = 25.1 kPa, Jlim = 270) plus Gaussian noise of 0.02 mm (seed 2025).\n"
           "# Written by: build/benchmarks/bench_optimize --write-fit-data FILE\n"
           "V1_kV, V2_kV, displacement_mm\n";
    for (std::size_t i = 0; i < d.voltages.size(); ++i)
      {
        char line[128];
        std::snprintf(line, sizeof line, "%.2f, %.2f, %.4f\n", d.voltages[i][0] * 1e-3,
                      d.voltages[i][1] * 1e-3, x[i] * 1e3 + noise(generator));
        out << line;
      }
  }

  /// The number after @p label in @p output (NaN if absent).
  double number_after(const std::string &output, const std::string &label)
  {
    const std::size_t at = output.find(label);
    return at == std::string::npos ? std::nan("") :
                                     std::strtod(output.c_str() + at + label.size(), nullptr);
  }

  /// The optimum's stroke (mm) as `cdea optimize` prints it.
  double optimum_stroke(const std::string &output)
  {
    const std::size_t at = output.find("Optimum (start");
    return at == std::string::npos ? std::nan("") : number_after(output.substr(at), "stroke ");
  }

  /// The fitted value and standard error of @p parameter, as `cdea fit`
  /// prints them: "name  start  fitted  std.error  rel.".
  std::pair<double, double> fitted(const std::string &output, const std::string &parameter)
  {
    std::smatch       m;
    const std::regex  row("\\n" + parameter + R"(\s+\S+\s+(\S+)\s+(\S+)\s+\S+)");
    cdea_bench::require(std::regex_search(output, m, row), "fit: no row for " + parameter);
    return {std::stod(m[1].str()), std::stod(m[2].str())};
  }

  void check_fit(const std::string &output, const std::string &parameter, const double truth)
  {
    const auto [value, error] = fitted(output, parameter);
    cdea_bench::require(std::abs(value - truth) <= 3. * error && error < 0.1 * truth,
                        "fit: " + parameter + " " + std::to_string(value) + " +- " +
                          std::to_string(error) + ", synthetic value " + std::to_string(truth));
  }

  void write_file(const std::filesystem::path &path, const std::string &text)
  {
    std::ofstream(path) << text;
  }

  std::string optimize_prm(const unsigned int rings, const unsigned int starts,
                           const std::string &dir, const std::string &base)
  {
    std::ostringstream o;
    o << "subsection Optimization\n  set Rings = " << rings
      << "\n  set Edge bounds (r/a) = 1, 3\n  set Starts = " << starts
      << "\nend\nsubsection Output\n  set Directory = " << dir << "\n  set Base name = " << base
      << "\nend\n";
    return o.str();
  }
} // namespace

int main(int argc, char **argv)
{
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 2 && args[0] == "--write-fit-data")
    {
      const MpiSession mpi(argc, argv);
      write_fit_data(args[1]);
      std::cout << "wrote " << args[1] << '\n';
      return 0;
    }
  const int          runs   = args.size() > 0 ? std::stoi(args[0]) : 5;
  const unsigned int rings  = args.size() > 1 ? std::stoi(args[1]) : 8;
  const unsigned int starts = args.size() > 2 ? std::stoi(args[2]) : 8;
  const std::filesystem::path out =
    std::filesystem::temp_directory_path() / ("cdea-bench-optimize-" + std::to_string(getpid()));
  output_folder = out;
  std::filesystem::create_directories(out);
  // The bounds of the answers: the two-ring optimum and the straight cone.
  constexpr double two_ring_stroke = 9.617312; // mm, bench_partitioning part 1
  double           cone_stroke     = 0.;
  {
    const MpiSession mpi(argc, argv);
    write_fit_data((out / "fit.csv").string());
    const Scene scene;
    cone_stroke = (shooting::straight_cone(scene).displacement -
                   zero_voltage_displacement(scene, FeDiscretization(), NewtonSettings(),
                                             SteppingSettings())) *
                  1e3;
  }
  write_file(out / "two.prm", optimize_prm(2, starts, out.string(), "two"));
  write_file(out / "many.prm", optimize_prm(rings, starts, out.string(), "many"));
  write_file(out / "fit.prm", "subsection Electrodes\n  set Ring edges (r/a) = 1, 1.7, 3\n"
                              "  set Voltage path (kV) = 5, 5\nend\n"
                              "subsection Material\n  set Shear modulus (kPa) = 20\n"
                              "  set Jlim = 150\nend\n"
                              "subsection Calibration\n  set Free parameters = shear modulus, Jlim\n"
                              "end\nsubsection Output\n  set Directory = " +
                                out.string() + "\n  set Base name = fit\nend\n");

  const std::string exe = CDEA_EXECUTABLE;
  const auto help_check = [](const std::string &output) {
    cdea_bench::require(output.find("cdea optimize") != std::string::npos &&
                          output.find("cdea fit") != std::string::npos,
                        "cdea --help names neither optimize nor fit");
  };
  const auto two_check = [&](const std::string &output) {
    const double stroke = optimum_stroke(output);
    cdea_bench::require(std::abs(stroke / two_ring_stroke - 1.) < 1e-5,
                        "optimize, two rings: stroke " + std::to_string(stroke) +
                          " mm, not the two-ring optimum " + std::to_string(two_ring_stroke));
  };
  const auto many_check = [&](const std::string &output) {
    const double stroke = optimum_stroke(output);
    cdea_bench::require(stroke > two_ring_stroke && stroke < cone_stroke,
                        "optimize, " + std::to_string(rings) + " rings: stroke " +
                          std::to_string(stroke) + " mm, not between two rings (" +
                          std::to_string(two_ring_stroke) + ") and the straight cone (" +
                          std::to_string(cone_stroke) + ")");
  };
  const auto fit_check = [](const std::string &output) {
    check_fit(output, "shear modulus \\(kPa\\)", 25.1);
    check_fit(output, "Jlim", 270.);
  };
  std::cout << "bench_optimize: " << runs << " run(s) of each command; wall and CPU times in s\n"
            << std::left << std::setw(44) << "command" << std::right << std::setw(9) << "median"
            << std::setw(9) << "min" << std::setw(9) << "CPU" << "   work reported\n";
  time_command("cdea --help (start-up only)", {exe, "--help"}, (out / "help.log").string(), runs,
               help_check);
  time_command("optimize: 2 rings all free, " + std::to_string(starts) + " starts",
               {exe, "optimize", (out / "two.prm").string()}, (out / "two.log").string(), runs,
               two_check);
  if (rings > 2) // (the smoke run of ctest skips it)
    time_command("optimize: " + std::to_string(rings) + " rings all free, " +
                   std::to_string(starts) + " starts",
                 {exe, "optimize", (out / "many.prm").string()}, (out / "many.log").string(),
                 runs, many_check);
  time_command("fit: mu and Jlim to 20 points", {exe, "fit", (out / "fit.prm").string(),
                                                 (out / "fit.csv").string()},
               (out / "fit.log").string(), runs, fit_check);
  std::cout << "checked: the two-ring optimum, the bounds of " << rings
            << " rings, the fitted mu and Jlim\n";
  std::filesystem::remove_all(out);
  return 0;
}
