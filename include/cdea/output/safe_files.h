#pragma once
// File-system pieces of crash-safe output (POSIX): whole files replaced
// atomically, an exclusive lock per output file, directories created with a
// record of what was created (to take back on bad input), and a check that
// the output directory is still the one the run started in.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <sys/types.h>
#include <vector>

namespace cdea
{
  /// The results cannot be written where they should go: raised at the start
  /// of a run (the run does not start: bad output settings, exit code 1) or
  /// during it (the run stops and keeps what it has, exit code 2).
  class OutputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// How a write to disk went.
  struct WriteOutcome
  {
    bool        ok      = false;
    std::size_t written = 0; ///< bytes that reached the file before a failure
    int         error   = 0; ///< errno of the failure
    std::string message;     ///< "<path>: <strerror>" on failure
  };

  /// Writes @p bytes to "<path>.tmp", optionally fsync()s it, and renames it
  /// onto @p path: @p path is either its old content or all of @p bytes,
  /// whenever the process dies. On failure the temporary file is removed and
  /// @p path is untouched.
  WriteOutcome replace_file(const std::string &path, const std::vector<char> &bytes, bool sync);

  /// An exclusive advisory lock (flock) on "<path>.lock", held until
  /// release() or destruction, which delete the lock file. The lock file holds
  /// the holder's process id for the message of a refused second writer.
  class OutputLock
  {
  public:
    OutputLock() = default;
    ~OutputLock();
    OutputLock(OutputLock &&other) noexcept;
    OutputLock &operator=(OutputLock &&other) noexcept;
    OutputLock(const OutputLock &)            = delete;
    OutputLock &operator=(const OutputLock &) = delete;

    /// Takes the lock for @p path; false if another process holds it, with
    /// @p why saying which (or what failed).
    bool acquire(const std::string &path, std::string &why);
    void release() noexcept;
    bool held() const { return fd >= 0; }

  private:
    int         fd = -1;
    std::string lock_path;
  };

  /// Makes @p path ours: creates its directory if missing (removed again on
  /// failure), checks that it is writable and takes @p lock. False, with
  /// @p why, if any of it fails. On success @p created (if given) lists the
  /// directories it made, for remove_created_directories().
  bool claim_output(const std::string &path, OutputLock &lock, std::string &why,
                    std::vector<std::string> *created = nullptr);

  /// Creates @p directory and its missing parents; returns those it created,
  /// innermost last. Throws std::runtime_error naming the directory.
  std::vector<std::string> create_directories(const std::string &directory);

  /// Removes the directories that create_directories() made, if empty.
  void remove_created_directories(const std::vector<std::string> &created) noexcept;

  /// Which directory a path names (device and inode), to notice that it was
  /// removed or replaced.
  struct DirectoryIdentity
  {
    dev_t device = 0;
    ino_t inode  = 0;
    bool  valid  = false;
    static DirectoryIdentity of(const std::string &directory);
    bool operator==(const DirectoryIdentity &o) const
    {
      return valid && o.valid && device == o.device && inode == o.inode;
    }
  };

  /// The parent directory of @p path ("." if it has none).
  std::string parent_directory(const std::string &path);

  /// "<stem><tag>.h5" beside @p path ("x/a.h5", ".recovered" -> "x/a.recovered.h5"),
  /// or "<stem><tag>-2.h5", "-3", ... if taken.
  std::string free_sibling_name(const std::string &path, const std::string &tag);

  /// @p path with ".h5" replaced by @p tag + ".h5" (appended if it has none).
  std::string sibling_name(const std::string &path, const std::string &tag);

  bool file_exists(const std::string &path);
  void remove_file(const std::string &path) noexcept;
} // namespace cdea
