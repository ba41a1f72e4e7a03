// Benchmark: the start-up cost of a cdea process, side by side with its floor.
// Each round launches, in turn,
//   floor           startup_floor: an empty main() linked like cdea,
//   floor + MPI     startup_floor --mpi: the same with MPI_Init/MPI_Finalize
//                   (what every cdea process paid before MPI became optional),
//   cdea --version  the program doing nothing but print its version,
//   cdea run FILE   the default case, output to a temporary folder,
// and prints the median wall time of each over the rounds, and the differences
// to the floor; and the same for the CPU time (user + system) of each process,
// which other jobs on a shared machine disturb much less than the wall time.
// Interleaving the programs round by round lets a slow phase of the machine hit
// all of them alike. Exits with 1 if a process fails or the run leaves no
// results file.
//
//   build/benchmarks/bench_startup [ROUNDS] [FILE.prm]

#include "bench_common.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

extern char **environ;

namespace
{
  struct Times
  {
    double wall = -1., cpu = -1.; ///< s; negative: the process failed
  };

  /// Wall and CPU time of one run of @p args with stdout and stderr to
  /// /dev/null.
  Times time_process(const std::vector<std::string> &args)
  {
    std::vector<char *> argv;
    for (const std::string &a : args)
      argv.push_back(const_cast<char *>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    const auto start = std::chrono::steady_clock::now();
    pid_t      pid   = 0;
    const int  error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0)
      return {};
    int    status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      return {};
    const auto as_seconds = [](const timeval &t) { return t.tv_sec + 1e-6 * t.tv_usec; };
    return {seconds, as_seconds(usage.ru_utime) + as_seconds(usage.ru_stime)};
  }

  /// Whether @p folder holds a non-empty finished results file (*.h5).
  bool results_written(const std::filesystem::path &folder)
  {
    std::error_code ec;
    for (const auto &entry : std::filesystem::directory_iterator(folder, ec))
      if (entry.path().extension() == ".h5" && entry.path().stem().extension().empty() &&
          entry.file_size(ec) > 0)
        return true;
    return false;
  }
} // namespace

int main(int argc, char **argv)
{
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 21;
  const std::string file =
    argc > 2 ? argv[2] : std::string(CDEA_SOURCE_DIR) + "/prm/default.prm";
  if (rounds < 1)
    {
      std::cerr << "bench_startup: ROUNDS must be at least 1\n";
      return 1;
    }
  const std::filesystem::path out =
    std::filesystem::temp_directory_path() / ("cdea-bench-startup-" + std::to_string(getpid()));
  const std::string prm = cdea_bench::prm_writing_to(file, out);

  struct Program
  {
    std::string              name;
    std::vector<std::string> args;
    std::vector<double>      wall, cpu;
  };
  std::vector<Program> programs = {
    {"floor (empty main linked like cdea)", {STARTUP_FLOOR}, {}, {}},
    {"floor + MPI_Init/MPI_Finalize", {STARTUP_FLOOR, "--mpi"}, {}, {}},
    {"cdea --version", {CDEA_EXECUTABLE, "--version"}, {}, {}},
    {"cdea run " + std::filesystem::path(file).filename().string(),
     {CDEA_EXECUTABLE, "run", prm},
     {},
     {}}};
  for (int k = 0; k < rounds; ++k)
    for (Program &p : programs)
      {
        const Times t = time_process(p.args);
        if (t.wall < 0.)
          {
            std::cerr << "bench_startup: failed: " << p.args[0] << '\n';
            std::filesystem::remove_all(out);
            return 1;
          }
        p.wall.push_back(t.wall);
        p.cpu.push_back(t.cpu);
      }
  // What the timed run computes: beside its exit code (checked above), the
  // finished results file (not a partial, journal or checkpoint).
  const bool written = results_written(out);
  std::filesystem::remove_all(out);
  if (!written)
    {
      std::cerr << "bench_startup: cdea run wrote no results file into " << out << '\n';
      return 1;
    }

  std::cout << "medians of " << rounds << " interleaved rounds (load average at the end: ";
  {
    std::ifstream load("/proc/loadavg");
    std::string   a, b, c;
    load >> a >> b >> c;
    std::cout << a << ' ' << b << ' ' << c << ")\n";
  }
  std::cout << std::left << std::setw(40) << "" << std::right << std::setw(10) << "wall"
            << std::setw(14) << "over floor" << std::setw(10) << "CPU" << std::setw(14)
            << "over floor" << "\n";
  const double floor_wall = cdea_bench::median(programs[0].wall);
  const double floor_cpu  = cdea_bench::median(programs[0].cpu);
  for (const Program &p : programs)
    {
      const double w = cdea_bench::median(p.wall), c = cdea_bench::median(p.cpu);
      std::cout << "  " << std::left << std::setw(38) << p.name << std::right << std::fixed
                << std::setprecision(1) << std::setw(7) << w * 1e3 << " ms" << std::setw(11)
                << (w - floor_wall) * 1e3 << " ms" << std::setw(7) << c * 1e3 << " ms"
                << std::setw(11) << (c - floor_cpu) * 1e3 << " ms\n";
    }
  std::cout << "cdea run over the floor: " << std::setprecision(1)
            << (cdea_bench::median(programs.back().wall) - floor_wall) * 1e3 << " ms wall, "
            << (cdea_bench::median(programs.back().cpu) - floor_cpu) * 1e3
            << " ms CPU (goal: at most 40 ms)\n";
  return 0;
}
