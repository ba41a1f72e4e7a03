#pragma once
// What the benchmark programs share: clocks and medians, whole-process runs,
// a run of any model through the load stages, the folder the CSV files go to,
// and the checks that make a smoke run (ctest label bench-smoke, `--smoke` or
// small arguments) fail when the library breaks what a benchmark measures.
// A benchmark is a driver of the library's public interfaces; nothing here
// solves anything itself.

#include <cdea/base/mpi_session.h>
#include <cdea/model/scene.h>
#include <cdea/model/equilibrium_model.h>
#include <cdea/solver/load_stepper.h>

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <regex>
#include <string>
#include <vector>

namespace cdea_bench
{
  /// A line of /proc/self/status in MiB ("VmRSS", "VmHWM").
  inline double status_mib(const std::string &key)
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind(key + ":", 0) == 0)
        return std::stod(line.substr(key.size() + 1)) / 1024.;
    return 0.;
  }

  /// Median of the samples (the mean of the two middle ones for an even
  /// count); NaN for none.
  inline double median(std::vector<double> v)
  {
    if (v.empty())
      return std::nan("");
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }

  /// CPU time of this process (s): hardly affected by other jobs on the machine.
  inline double cpu_seconds()
  {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }

  /// Wall-clock time (s) from an arbitrary origin.
  inline double wall_seconds()
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
  }

  /// Median time (s) of @p repeat calls of @p f, by @p clock.
  inline double median_time(const std::function<void()> &f, const int repeat,
                            double (*clock)() = cpu_seconds)
  {
    std::vector<double> t;
    for (int k = 0; k < repeat; ++k)
      {
        const double t0 = clock();
        f();
        t.push_back(clock() - t0);
      }
    return median(t);
  }

  /// |a - b| / |b|.
  inline double rel(const double a, const double b) { return std::abs(a - b) / std::abs(b); }

  /// Wall time (s) of a shell command and its exit status.
  struct ProcessRun
  {
    double seconds   = 0.;
    int    exit_code = 0;
  };

  inline ProcessRun time_process(const std::string &command)
  {
    const double start = wall_seconds();
    const int    rc    = std::system(command.c_str());
    return {wall_seconds() - start, rc};
  }

  /// Copy the parameter file @p file into the folder @p out (created) as
  /// bench.prm with its Output/Directory pointing there, so that benchmark
  /// runs of the program write nothing into the working directory.
  inline std::string prm_writing_to(const std::string &file, const std::filesystem::path &out)
  {
    std::filesystem::create_directories(out);
    const std::string prm = (out / "bench.prm").string();
    std::ifstream     in(file);
    std::ofstream     copy(prm);
    // The file's own Directory entry is left out (an entry set twice draws a warning).
    const std::regex directory(R"(^\s*set\s+Directory\s*=.*)");
    std::string      line;
    while (std::getline(in, line))
      if (!std::regex_match(line, directory))
        copy << line << '\n';
    copy << "\nsubsection Output\n  set Directory = " << out.string() << "\nend\n";
    return prm;
  }

  /// A run of a model through all load stages of its scene.
  struct Run
  {
    cdea::RunResult                result;
    cdea::StepSummary              last;          ///< the last converged step
    std::vector<cdea::StepSummary> voltage_steps; ///< every step of the voltage stage
  };

  inline Run run_stages(cdea::EquilibriumModel &model, const cdea::Scene &scene,
                        const cdea::SteppingSettings &settings = cdea::SteppingSettings(),
                        const bool keep_voltage_steps = false)
  {
    cdea::LoadStepper stepper(scene, model, settings);
    Run               run;
    stepper.on_step = [&](const cdea::StepSummary &s) {
      run.last = s;
      if (keep_voltage_steps && s.stage == cdea::Stage::voltage)
        run.voltage_steps.push_back(s);
    };
    run.result = stepper.run();
    return run;
  }

  /// A figure that the smoke run found broken.
  class Broken : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Fail the benchmark (exit code 1) unless @p ok.
  inline void require(const bool ok, const std::string &what)
  {
    if (!ok)
      throw Broken(what);
  }

  /// Fail the benchmark unless @p value is finite (and positive if asked).
  inline void require_finite(const double value, const std::string &what,
                             const bool positive = false)
  {
    require(std::isfinite(value) && (!positive || value > 0.),
            what + " is " + std::to_string(value));
  }

  /// Remove @p flag from the arguments; true if it was there.
  inline bool take_flag(std::vector<std::string> &args, const std::string &flag)
  {
    const auto it = std::find(args.begin(), args.end(), flag);
    if (it == args.end())
      return false;
    args.erase(it);
    return true;
  }

  /// The folder the CSV files go to: the one given, or (smoke runs) a new
  /// temporary one that is removed again at the end.
  class OutputFolder
  {
  public:
    OutputFolder(const std::string &given, const bool temporary)
      : temporary(temporary)
      , dir(temporary ? std::filesystem::temp_directory_path() /
                          ("cdea-bench-" + std::to_string(getpid())) :
                        std::filesystem::path(given))
    {
      std::filesystem::create_directories(dir);
    }
    ~OutputFolder()
    {
      std::error_code ignored;
      if (temporary)
        std::filesystem::remove_all(dir, ignored);
    }
    OutputFolder(const OutputFolder &)            = delete;
    OutputFolder &operator=(const OutputFolder &) = delete;

    std::filesystem::path operator/(const std::string &name) const { return dir / name; }
    const std::filesystem::path &path() const { return dir; }

  private:
    bool                  temporary;
    std::filesystem::path dir;
  };

  /// Run a benchmark's body: exit code 1 with a message if it throws (a
  /// failed check of a smoke run, bad input, a run that did not complete).
  inline int guarded(const std::string &name, const std::function<int()> &body)
  {
    try
      {
        return body();
      }
    catch (const Broken &e)
      {
        std::cerr << name << ": check failed: " << e.what() << '\n';
      }
    catch (const std::exception &e)
      {
        std::cerr << name << ": " << e.what() << '\n';
      }
    return 1;
  }

  /// main() of a study whose command line is [DIR] [--smoke]: @p body gets
  /// the folder for its CSV files (DIR, default results/validation; in a
  /// smoke run without DIR a temporary one) and whether this is a smoke run.
  /// A study that writes no file takes no DIR (@p writes_files false).
  inline int study_main(int argc, char **argv, const std::string &name,
                        const std::function<int(const OutputFolder &, bool)> &body,
                        const bool writes_files = true)
  {
    const cdea::MpiSession mpi(argc, argv);
    return guarded(name, [&] {
      std::vector<std::string> args(argv + 1, argv + argc);
      const bool               smoke = take_flag(args, "--smoke");
      require(args.size() <= (writes_files ? 1u : 0u),
              std::string("usage: ") + name + (writes_files ? " [DIR]" : "") + " [--smoke]");
      // (A study that writes nothing gets an unused temporary folder.)
      const OutputFolder dir(args.empty() ? "results/validation" : args.front(),
                             (smoke && args.empty()) || !writes_files);
      return body(dir, smoke);
    });
  }
} // namespace cdea_bench
