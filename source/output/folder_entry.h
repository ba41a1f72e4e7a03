#pragma once
// A name in an opened folder: the folder is opened once and every operation
// on the name (create, stat, rename, unlink) is made relative to it (openat,
// fstatat, renameat), so that the folder cannot be swapped between a check
// and its use. Internal to output/ (safe_files.cc, output_lock.cc).

#include <sys/stat.h>

#include <string>

namespace cdea::files
{
  class FolderEntry
  {
  public:
    /// The folder of @p path opened; ok() false (error() says why) if it
    /// cannot be, or if @p path names no file ("", "x/", ".", "..").
    explicit FolderEntry(const std::string &path);
    ~FolderEntry();
    FolderEntry(const FolderEntry &)            = delete;
    FolderEntry &operator=(const FolderEntry &) = delete;

    bool               ok() const { return folder >= 0; }
    const std::string &error() const { return why; }
    int                folder_fd() const { return folder; }
    const std::string &name() const { return file; }

    /// fstatat() of @p entry (default: the name) without following a final
    /// link: false if nothing is there.
    bool stat(struct stat &st, const std::string &entry = std::string()) const;
    /// Removes @p entry if it is a regular file; true if nothing is left there.
    bool remove_regular(const std::string &entry) const;

  private:
    int         folder = -1;
    std::string file, why;
  };

  /// "<path>: <strerror(error)>".
  std::string system_message(const std::string &path, int error);
} // namespace cdea::files
