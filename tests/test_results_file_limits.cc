// ResultsFile under limits and bad input: a file size limit (a full disk)
// leaves the steps that fit, unwritable paths and malformed steps are
// reported, and a moved writer keeps working with readable checkpoints.
// The content of a normal file: test_results_file.cc.

#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <hdf5.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "check.h"

#include "results_file_demo.h"

using namespace cdea_test;
using namespace results_file_demo;

namespace
{
  bool throws_runtime_error_naming(const std::string &path)
  {
    try
      {
        cdea::ResultsFile file(path, parameters_text, 2);
      }
    catch (const std::runtime_error &e)
      {
        std::cout << "  (message: " << e.what() << ")\n";
        return std::string(e.what()).find(path) != std::string::npos;
      }
    return false;
  }
} // namespace

CDEA_TEST_MAIN()
{
  namespace fs = std::filesystem;
  const fs::path base = "test_results_file_limits_out";
  fs::remove_all(base);
  fs::create_directories(base);

  // 2d. A file size limit (a full disk): a step whose checkpoint does not
  //     fit raises OutputError; finish() writes the leading steps that fit.
  {
    const std::string limited = (base / "limited.h5").string();
    std::cout.flush();
    const pid_t child = fork();
    if (child == 0)
      {
        std::signal(SIGXFSZ, SIG_IGN);
        setenv("CDEA_CHECKPOINT_SECONDS", "0", 1);
        const rlimit limit = {60000, 60000};
        setrlimit(RLIMIT_FSIZE, &limit);
        cdea::ResultsFile file(limited, parameters_text, 2, demo_root_attributes);
        unsigned int      appended = 0;
        try
          {
            for (; appended < 40; ++appended)
              file.append(demo_summary(appended % 3), demo_fields(appended % 3));
          }
        catch (const cdea::OutputError &)
          {
          }
        const unsigned int held = file.n_steps(); // a failed append's step is held too
        const auto         done = file.finish("stopped");
        // Exit code: steps in the file, or 100 + steps held if none or all.
        // (Whether a checkpoint hits the limit during the appends depends on
        // timing; the final file does, as 40 steps need about 100 kB.)
        _exit(done.written && done.steps_written > 0 && done.steps_written < held ?
                int(done.steps_written) :
                100 + int(held));
      }
    int status = 0;
    waitpid(child, &status, 0);
    const int steps = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    check(steps > 0 && steps < 40, "60 kB file size limit: finish() wrote " +
                                     std::to_string(steps) + " steps that fit, no crash");
    const hid_t f = H5Fopen(limited.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    check(f >= 0 && fs::file_size(limited) <= 60000, "that file opens and is within the limit");
    if (f >= 0)
      H5Fclose(f);
  }

  // 3. Unwritable paths: a directory under a regular file, and a path that is
  //    a directory.
  {
    std::ofstream(base / "plain_file") << "not a directory\n";
  }
  check(throws_runtime_error_naming((base / "plain_file" / "sub" / "r.h5").string()),
        "path under a regular file throws std::runtime_error naming the path");
  fs::create_directories(base / "a_directory");
  check(throws_runtime_error_naming((base / "a_directory").string()),
        "path that is a directory throws std::runtime_error naming the path");

  // 4. Bad input is rejected before anything is written.
  {
    const std::string bad_path = (base / "bad.h5").string();
    cdea::ResultsFile file(bad_path, parameters_text, 2);
    file.append(demo_summary(0), demo_fields(0));
    auto wrong_rings = demo_summary(1);
    wrong_rings.voltages.pop_back();
    bool thrown = false;
    try
      {
        file.append(wrong_rings, demo_fields(1));
      }
    catch (const std::invalid_argument &)
      {
        thrown = true;
      }
    check(thrown, "wrong number of ring voltages throws std::invalid_argument");
    auto ragged = demo_fields(1);
    ragged.s2.pop_back();
    thrown = false;
    try
      {
        file.append(demo_summary(1), ragged);
      }
    catch (const std::invalid_argument &)
      {
        thrown = true;
      }
    check(thrown, "fields of different lengths throw std::invalid_argument");
    thrown = false;
    try
      {
        file.append(demo_summary(1), demo_fields(1), {{"stage", 1.}});
      }
    catch (const std::invalid_argument &)
      {
        thrown = true;
      }
    check(thrown, "extra column with a standard name throws std::invalid_argument");
    check(file.n_steps() == 1, "rejected appends leave one step");
    file.append(demo_summary(1), demo_fields(1));
    check(file.n_steps() == 2, "a good append after rejected ones works");
    bool zero_rings_thrown = false;
    try
      {
        cdea::ResultsFile zero((base / "zero.h5").string(), parameters_text, 0);
      }
    catch (const std::invalid_argument &)
      {
        zero_rings_thrown = true;
      }
    check(zero_rings_thrown, "n_rings = 0 throws std::invalid_argument");
  }

  // 5. Move construction keeps the file usable; with checkpoints due at
  //    every step another process can read the checkpoint while the writer
  //    is open.
  {
    setenv("CDEA_CHECKPOINT_SECONDS", "0", 1);
    const std::string moved_path = (base / "moved.h5").string();
    cdea::ResultsFile a(moved_path, parameters_text, 2);
    cdea::ResultsFile b(std::move(a));
    b.append(demo_summary(0), demo_fields(0));
    check(b.n_steps() == 1 && b.n_rings() == 2, "moved-to ResultsFile appends");
    check(b.checkpoint_path() == (base / "moved.partial.h5").string() &&
            fs::exists(b.checkpoint_path()),
          "checkpoint moved.partial.h5 written");
    if (fs::exists("/usr/bin/h5dump"))
      check(std::system(("/usr/bin/h5dump -H " + b.checkpoint_path() + " > " +
                         (base / "h5dump.log").string() + " 2>&1")
                          .c_str()) == 0,
            "h5dump reads the checkpoint while the writer is open");
    unsetenv("CDEA_CHECKPOINT_SECONDS");
  }

  return finish();
}
