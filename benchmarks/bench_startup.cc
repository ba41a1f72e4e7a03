// Benchmark: the start-up cost of a cdea process, side by side with its floor.
// Each round launches, in turn,
//   floor           startup_floor: an empty main() linked like cdea,
//   floor + MPI     startup_floor --mpi: the same with MPI_Init/MPI_Finalize
//                   (what every cdea process paid before MPI became optional),
//   cdea --version  the program doing nothing but print its version,
//   cdea run FILE   the default case, output to a temporary folder,
// and prints the median wall time of each over the rounds, and the differences
// to the floor. Interleaving the programs round by round lets a slow phase of
// the shared machine hit all of them alike.
//
//   build/benchmarks/bench_startup [ROUNDS] [FILE.prm]

#include "bench_common.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

extern char **environ;

namespace
{
  /// Wall time (s) of one run of @p args with stdout and stderr to
  /// /dev/null; negative if it did not exit with 0.
  double time_process(const std::vector<std::string> &args)
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
      return -1.;
    int status = 0;
    waitpid(pid, &status, 0);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? seconds : -1.;
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
    std::vector<double>      times;
  };
  std::vector<Program> programs = {
    {"floor (empty main linked like cdea)", {STARTUP_FLOOR}, {}},
    {"floor + MPI_Init/MPI_Finalize", {STARTUP_FLOOR, "--mpi"}, {}},
    {"cdea --version", {CDEA_EXECUTABLE, "--version"}, {}},
    {"cdea run " + std::filesystem::path(file).filename().string(),
     {CDEA_EXECUTABLE, "run", prm},
     {}}};
  for (int k = 0; k < rounds; ++k)
    for (Program &p : programs)
      {
        const double t = time_process(p.args);
        if (t < 0.)
          {
            std::cerr << "bench_startup: failed: " << p.args[0] << '\n';
            std::filesystem::remove_all(out);
            return 1;
          }
        p.times.push_back(t);
      }
  std::filesystem::remove_all(out);

  const double floor = cdea_bench::median(programs[0].times);
  std::cout << "process wall time, median of " << rounds << " interleaved rounds:\n";
  for (const Program &p : programs)
    {
      const double m = cdea_bench::median(p.times);
      std::cout << "  " << std::left << std::setw(38) << p.name << std::right << std::fixed
                << std::setprecision(1) << std::setw(8) << m * 1e3 << " ms   floor + "
                << std::setw(6) << (m - floor) * 1e3 << " ms\n";
    }
  const double run = cdea_bench::median(programs.back().times);
  std::cout << "cdea run over the floor: " << std::setprecision(1) << (run - floor) * 1e3
            << " ms (goal: at most 40 ms)\n";
  return 0;
}
