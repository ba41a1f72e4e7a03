// ResultsFile under limits and bad input: a file size limit (a full disk)
// leaves the steps that fit, unwritable paths and malformed steps are
// reported, and a moved writer keeps working with readable checkpoints;
// `cdea recover` bounded on a file that is no journal, files replaced
// together or not at all, a run cut short beside an older file (issue 31).
// The content of a normal file: test_results_file.cc.

#include <cdea/output/paraview_writer.h>
#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <hdf5.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
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

  std::vector<char> bytes_of(const std::string &text) { return {text.begin(), text.end()}; }

  std::string content(const std::string &path)
  {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }

  /// 6. `cdea recover` on a 1 GB file that is no journal, with 256 MB of
  ///    memory to spare: refused after its first bytes, not read whole.
  void foreign_journal_bounded(const std::filesystem::path &base)
  {
    const std::string path = (base / "foreign.h5").string();
    {
      std::ofstream(path + ".journal") << "NOT A JOURNAL";
    }
    std::filesystem::resize_file(path + ".journal", std::uintmax_t(1) << 30);
    std::cout.flush();
    const pid_t child = fork();
    if (child == 0)
      {
        rlimit memory = {};
        getrlimit(RLIMIT_AS, &memory);
        std::ifstream status("/proc/self/statm");
        std::size_t   pages = 0;
        status >> pages;
        const rlimit cap = {pages * 4096 + (std::size_t(256) << 20), memory.rlim_max};
        setrlimit(RLIMIT_AS, &cap);
        try
          {
            cdea::recover_results(path, true);
          }
        catch (const cdea::OutputError &e)
          {
            _exit(std::string(e.what()).find("is not a cdea journal") != std::string::npos ? 0 :
                                                                                            1);
          }
        catch (...)
          {
            _exit(2);
          }
        _exit(3);
      }
    int status = 0;
    waitpid(child, &status, 0);
    check(WIFEXITED(status) && WEXITSTATUS(status) == 0,
          "a 1 GB file that is no journal is refused within 256 MB of memory (exit " +
            std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
    std::filesystem::remove(path + ".journal");
  }

  /// 7. Files replaced together or not at all; after a stop beside the older ones.
  void replace_together(const std::filesystem::path &base)
  {
    const std::string h5 = (base / "pair_fit.h5").string(), prm = (base / "pair_fit.prm").string();
    check(cdea::replace_file(h5, bytes_of("old h5"), false).ok &&
            cdea::replace_file(prm, bytes_of("old prm"), false).ok,
          "the older pair written");
    {
      cdea::ReplaceTogether pair({h5, prm});
      cdea::replace_file(h5, bytes_of("new h5"), false);
      check(content(h5) == "old h5", "a held file is not renamed before the commit");
      cdea::replace_file(prm, bytes_of("new prm"), false);
      const auto wrote = pair.commit(true);
      check(wrote == std::vector<std::string>{cdea::partial_name(h5), cdea::partial_name(prm)} &&
              content(h5) == "old h5" && content(prm) == "old prm" &&
              content(wrote[0]) == "new h5" && content(wrote[1]) == "new prm",
            "a stopped pair goes to pair_fit.partial.h5 and .partial.prm, the older pair kept");
    }
    {
      cdea::ReplaceTogether pair({h5, prm});
      cdea::replace_file(h5, bytes_of("newer h5"), false);
      cdea::replace_file(prm, bytes_of("newer prm"), false);
      // The second name becomes a directory before the commit: its rename
      // fails, and the first is taken back.
      std::filesystem::remove(prm);
      std::filesystem::create_directory(prm);
      bool thrown = false;
      try
        {
          pair.commit(false);
        }
      catch (const cdea::OutputError &e)
        {
          thrown = std::string(e.what()).find("taken back") != std::string::npos;
          std::cout << "  (message: " << e.what() << ")\n";
        }
      check(thrown && content(h5) == "old h5" && !std::filesystem::exists(h5 + ".older") &&
              !std::filesystem::exists(h5 + ".tmp") && !std::filesystem::exists(prm + ".tmp"),
            "a failed second rename takes the first back: the older file returns, nothing left");
    }
    {
      cdea::ReplaceTogether pair({h5});
      cdea::replace_file(h5, bytes_of("dropped"), false);
    }
    check(content(h5) == "old h5" && !std::filesystem::exists(h5 + ".tmp"),
          "a group left without its commit removes its temporary files");
  }

  /// 9. A link, a FIFO and (as root) a device node at every name of a
  ///    results file and of a ParaView output: refused before anything is
  ///    written, each left as it was, the link's target untouched.
  void hostile_side_names(const std::filesystem::path &base)
  {
    namespace fs = std::filesystem;
    const fs::path dir = base / "shared";
    fs::create_directories(dir);
    {
      std::ofstream(dir / "victim") << "someone else's";
    }
    const std::vector<std::string> names = {"r.h5",         "r.h5.tmp",         "r.h5.lock",
                                            "r.h5.journal", "r.partial.h5",     "r.partial.h5.tmp",
                                            "r.pvd",        "r.partial.pvd.tmp", "r_vtu.partial"};
    unsigned int refused = 0, cases = 0;
    for (const std::string &name : names)
      for (const int kind : {0, 1, 2}) // link, FIFO, device
        {
          const fs::path at = dir / name;
          if (kind == 0)
            fs::create_symlink("victim", at);
          else if (kind == 1)
            mkfifo(at.c_str(), 0644);
          else if (geteuid() != 0 || mknod(at.c_str(), S_IFCHR | 0644, makedev(1, 3)) != 0)
            continue;
          ++cases;
          bool thrown = false;
          try
            {
              // (as a run prepares its output: a ParaView writer that cannot
              // start gives the results file up)
              cdea::ResultsFile file((dir / "r.h5").string(), parameters_text, 2);
              try
                {
                  cdea::ParaViewWriter paraview((dir / "r").string(), 8);
                }
              catch (...)
                {
                  file.abandon();
                  throw;
                }
              file.abandon();
            }
          catch (const std::exception &e)
            {
              thrown = std::string(e.what()).find(name) != std::string::npos;
            }
          struct stat st = {};
          const bool  kept = ::lstat(at.c_str(), &st) == 0 &&
                            (kind == 0 ? S_ISLNK(st.st_mode) :
                             kind == 1 ? S_ISFIFO(st.st_mode) :
                                         S_ISCHR(st.st_mode) && st.st_rdev == makedev(1, 3));
          std::size_t left = 0;
          for ([[maybe_unused]] const auto &entry : fs::directory_iterator(dir))
            ++left;
          if (thrown && kept && left == 2 && content((dir / "victim").string()) == "someone else's")
            ++refused;
          else
            std::cout << "  not refused cleanly: " << name << " kind " << kind << "\n";
          fs::remove(at);
        }
    check(refused == cases, std::to_string(refused) + " of " + std::to_string(cases) +
                              " links, FIFOs and devices at the 9 names of a results file and "
                              "its ParaView output refused, each left as it was");
  }

  /// 8. A run cut short (finish with keep_older) leaves an older file.
  void cut_short_keeps_older(const std::filesystem::path &base)
  {
    const std::string path = (base / "older.h5").string();
    check(cdea::replace_file(path, bytes_of("older results"), false).ok, "an older file");
    cdea::ResultsFile file(path, parameters_text, 2);
    file.append(demo_summary(0), demo_fields(0));
    const auto done = file.finish("stopped after step 0: interrupted by SIGINT", true);
    check(done.written && done.file == (base / "older.partial.h5").string() &&
            content(path) == "older results" && !std::filesystem::exists(path + ".journal") &&
            !std::filesystem::exists(path + ".lock"),
          "a run cut short writes older.partial.h5; older.h5 kept, no journal or lock");
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

  foreign_journal_bounded(base);
  replace_together(base);
  cut_short_keeps_older(base);
  hostile_side_names(base);
  return finish();
}
