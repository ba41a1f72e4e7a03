#pragma once
// File-system pieces of crash-safe output (POSIX), one layer for every file
// cdea writes: whole files replaced atomically, an exclusive lock per output
// file, directories created with a record of what was created (to take back
// on bad input), and a check that the output directory is still the one the
// run started in.
//
// Safe in a shared folder: every name cdea creates (a temporary file, a lock,
// a journal) is created with O_EXCL | O_NOFOLLOW relative to the opened
// folder, so a symbolic link placed there is never followed and no file of
// someone else's is opened for writing; a rename replaces only a regular
// file or nothing (never a link, a device, a FIFO or a directory, whose
// targets and nodes stay untouched); a name is removed only if it holds a
// regular file.

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
    std::string message;     ///< "<path>: <reason>" on failure
  };

  /// Writes @p bytes to "<path>.tmp" (created new: a leftover regular file
  /// of that name is removed first, anything else there is refused),
  /// optionally fsync()s it and the folder, and renames it onto @p path,
  /// which must hold a regular file or nothing: @p path is either its old
  /// content or all of @p bytes, whenever the process dies. On failure the
  /// temporary file is removed and @p path is untouched. While a
  /// ReplaceTogether names @p path, the rename waits for its commit().
  WriteOutcome replace_file(const std::string &path, const std::vector<char> &bytes, bool sync);

  /// Files replaced together or not at all (a results file and the
  /// parameter file that goes with it): while the object lives,
  /// replace_file() onto one of its paths writes the whole temporary file
  /// and holds back the rename; commit() does the renames. One at a time.
  class ReplaceTogether
  {
  public:
    explicit ReplaceTogether(std::vector<std::string> paths);
    /// Removes the temporary files of an uncommitted group.
    ~ReplaceTogether();
    ReplaceTogether(const ReplaceTogether &)            = delete;
    ReplaceTogether &operator=(const ReplaceTogether &) = delete;

    /// Renames every file written onto its path; if one rename fails, those
    /// done are taken back (the older files return) and OutputError is
    /// thrown. With @p keep_older (the work was interrupted) and an older
    /// file at any of the paths, the files go to their partial_name()s
    /// instead and the older ones stay as they are. Returns where each file
    /// went, in the order of the paths ("" where none was written).
    std::vector<std::string> commit(bool keep_older);

    /// Whether @p path is one of the group's.
    bool holds(const std::string &path) const;
    /// replace_file(): the temporary file of @p path is written and waits.
    void hold(const std::string &path);

  private:
    std::vector<std::string> paths;
    std::vector<bool>        written;
    bool                     committed = false;
  };

  /// An exclusive advisory lock (flock) on "<path>.lock", held until
  /// release() or destruction, which delete the lock file. The lock file holds
  /// the holder's process id for the message of a refused second writer. A
  /// lock name taken by anything but a regular file of one link (a symbolic
  /// link, a FIFO, a device, a hard link to another file) is refused.
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
    int         fd        = -1;
    int         folder_fd = -1; ///< the folder of the lock file
    std::string lock_name;      ///< its name in that folder
  };

  /// Makes @p path ours: creates its directory if missing (removed again on
  /// failure), checks that it is writable, that @p path names a file that
  /// holds a regular file or nothing, and takes @p lock. False, with
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

  /// Where an interrupted command's results go beside an older complete
  /// file: ".partial" before the extension of the file name
  /// ("x/a_fit.h5" -> "x/a_fit.partial.h5", "a_fit.prm" -> "a_fit.partial.prm").
  std::string partial_name(const std::string &path);

  /// Something of any kind is at @p path (a symbolic link itself counts).
  bool file_exists(const std::string &path);
  /// Removes @p path if it holds a regular file (never a link, a device, a
  /// FIFO or a directory: those are not cdea's).
  void remove_file(const std::string &path) noexcept;

  /// Why @p path cannot take a file of cdea's, "" if it can (nothing is
  /// there, or a regular file): "it is a symbolic link", "it is a directory",
  /// "it is a FIFO", "it is a device", ... A final link is not followed.
  std::string not_replaceable(const std::string &path);

  /// The same for @p path and the names written beside it: "<path>.tmp",
  /// its partial_name() and that one's ".tmp" (the first refused, naming
  /// it; "" if all can be written).
  std::string refused_names(const std::string &path);
} // namespace cdea
