// Whole files replaced atomically, alone or in groups, and the names of
// cdea's side files (safe_files.h).
#include <cdea/base/file_reading.h>
#include <cdea/output/safe_files.h>

#include "folder_entry.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace cdea
{
  namespace files
  {
    FolderEntry::FolderEntry(const std::string &path)
    {
      const auto slash = path.rfind('/');
      file = slash == std::string::npos ? path : path.substr(slash + 1);
      const std::string dir =
        slash == std::string::npos ? std::string(".") : slash == 0 ? "/" : path.substr(0, slash);
      if (file.empty() || file == "." || file == "..")
        {
          why = "'" + path + "' names no file";
          return;
        }
      folder = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      if (folder < 0)
        why = "cannot open the folder " + system_message(dir, errno);
    }

    FolderEntry::~FolderEntry()
    {
      if (folder >= 0)
        ::close(folder);
    }

    bool FolderEntry::stat(struct stat &st, const std::string &entry) const
    {
      return ::fstatat(folder, (entry.empty() ? file : entry).c_str(), &st,
                       AT_SYMLINK_NOFOLLOW) == 0;
    }

    bool FolderEntry::remove_regular(const std::string &entry) const
    {
      struct stat st = {};
      if (!stat(st, entry))
        return true;
      if (!S_ISREG(st.st_mode))
        return false;
      return ::unlinkat(folder, entry.c_str(), 0) == 0 || errno == ENOENT;
    }

    std::string system_message(const std::string &path, const int error)
    {
      return path + ": " + std::strerror(error);
    }
  } // namespace files

  using files::FolderEntry;
  using files::system_message;

  namespace
  {
    /// The group whose renames replace_file() holds back (one at a time).
    ReplaceTogether *active_group = nullptr;

    /// Why the entry cannot take a file of ours, "" if it can.
    std::string refusal(const FolderEntry &at, const std::string &entry)
    {
      struct stat st = {};
      if (!at.stat(st, entry) || S_ISREG(st.st_mode))
        return "";
      return "it is " + file_kind(st.st_mode) +
             " (cdea replaces only a regular file or nothing; remove it or choose another name)";
    }

    /// The temporary file "<name>.tmp" created new (a leftover regular file
    /// removed first, anything else refused); -1 with @p outcome filled.
    int create_temporary(const FolderEntry &at, const std::string &tmp_path, WriteOutcome &outcome)
    {
      const std::string tmp = at.name() + ".tmp";
      for (int attempt = 0; attempt < 3; ++attempt)
        {
          if (!at.remove_regular(tmp))
            {
              outcome.error   = EEXIST;
              outcome.message = tmp_path + ": " + refusal(at, tmp);
              return -1;
            }
          const int fd = ::openat(at.folder_fd(), tmp.c_str(),
                                  O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
          if (fd >= 0 || errno != EEXIST)
            {
              if (fd < 0)
                {
                  outcome.error   = errno;
                  outcome.message = system_message(tmp_path, errno);
                }
              return fd;
            }
        }
      outcome.error   = EEXIST;
      outcome.message = tmp_path + ": it keeps being created by someone else";
      return -1;
    }

    /// The whole of @p bytes into @p fd (optionally synced); false with
    /// @p outcome filled on failure.
    bool write_all(const int fd, const std::vector<char> &bytes, const bool sync,
                   const std::string &tmp_path, WriteOutcome &outcome)
    {
      while (outcome.written < bytes.size())
        {
          const ssize_t n =
            ::write(fd, bytes.data() + outcome.written, bytes.size() - outcome.written);
          if (n < 0 && errno == EINTR)
            continue;
          if (n <= 0)
            {
              outcome.error   = n < 0 ? errno : ENOSPC;
              outcome.message = system_message(tmp_path, outcome.error);
              return false;
            }
          outcome.written += std::size_t(n);
        }
      if (sync && ::fsync(fd) != 0)
        {
          outcome.error   = errno;
          outcome.message = system_message(tmp_path, errno);
          return false;
        }
      return true;
    }

    /// Renames the entry @p from onto @p to in the folder: only onto a
    /// regular file, or onto nothing (then never onto a name taken
    /// meanwhile). 0 or the errno; @p why says more for a refused target.
    int rename_onto(const FolderEntry &at, const std::string &from, const std::string &to,
                    std::string &why)
    {
      for (int attempt = 0; attempt < 3; ++attempt)
        {
          why = refusal(at, to);
          if (!why.empty())
            return EEXIST;
          struct stat st = {};
          if (at.stat(st, to))
            return ::renameat(at.folder_fd(), from.c_str(), at.folder_fd(), to.c_str()) == 0 ?
                     0 :
                     errno;
          if (::renameat2(at.folder_fd(), from.c_str(), at.folder_fd(), to.c_str(),
                          RENAME_NOREPLACE) == 0)
            return 0;
          if (errno == EINVAL || errno == ENOSYS) // a file system without it
            return ::renameat(at.folder_fd(), from.c_str(), at.folder_fd(), to.c_str()) == 0 ?
                     0 :
                     errno;
          if (errno != EEXIST)
            return errno;
        }
      return EEXIST;
    }

    /// The rename of "<path>.tmp" onto @p target (both in @p path's folder).
    WriteOutcome rename_temporary(const std::string &path, const std::string &target,
                                  const bool sync)
    {
      WriteOutcome      outcome;
      const FolderEntry at(path), onto(target);
      std::string       why;
      const int error = !at.ok()   ? ENOENT :
                        !onto.ok() ? ENOENT :
                                     rename_onto(at, at.name() + ".tmp", onto.name(), why);
      if (error != 0)
        {
          if (at.ok())
            at.remove_regular(at.name() + ".tmp");
          outcome.error   = error;
          outcome.message = !at.ok()     ? at.error() :
                            !why.empty() ? target + ": " + why :
                                           system_message(target, error);
          return outcome;
        }
      if (sync)
        ::fsync(at.folder_fd()); // the rename itself on disk
      outcome.ok = true;
      return outcome;
    }
  } // namespace

  WriteOutcome replace_file(const std::string &path, const std::vector<char> &bytes,
                            const bool sync)
  {
    WriteOutcome      outcome;
    const std::string tmp_path = path + ".tmp";
    const FolderEntry at(path);
    if (!at.ok())
      {
        outcome.error   = EINVAL;
        outcome.message = at.error();
        return outcome;
      }
    if (const std::string why = refusal(at, at.name()); !why.empty())
      {
        outcome.error   = EEXIST;
        outcome.message = path + ": " + why;
        return outcome;
      }
    const int fd = create_temporary(at, tmp_path, outcome);
    if (fd < 0)
      return outcome;
    const bool whole = write_all(fd, bytes, sync, tmp_path, outcome);
    if (::close(fd) != 0 && whole)
      {
        outcome.error   = errno;
        outcome.message = system_message(tmp_path, errno);
      }
    if (!outcome.message.empty())
      {
        at.remove_regular(at.name() + ".tmp");
        return outcome;
      }
    if (active_group && active_group->holds(path))
      {
        active_group->hold(path);
        outcome.ok = true;
        return outcome;
      }
    outcome = rename_temporary(path, path, sync);
    outcome.written = bytes.size();
    return outcome;
  }

  ReplaceTogether::ReplaceTogether(std::vector<std::string> paths_)
    : paths(std::move(paths_))
    , written(paths.size(), false)
  {
    if (active_group)
      throw std::logic_error("ReplaceTogether: a group is already open");
    active_group = this;
  }

  ReplaceTogether::~ReplaceTogether()
  {
    if (active_group == this)
      active_group = nullptr;
    if (committed)
      return;
    for (std::size_t k = 0; k < paths.size(); ++k)
      if (written[k])
        remove_file(paths[k] + ".tmp");
  }

  bool ReplaceTogether::holds(const std::string &path) const
  {
    for (const std::string &p : paths)
      if (p == path)
        return true;
    return false;
  }

  void ReplaceTogether::hold(const std::string &path)
  {
    for (std::size_t k = 0; k < paths.size(); ++k)
      if (paths[k] == path)
        written[k] = true;
  }

  namespace
  {
    /// Puts back what a failed group commit replaced: the older file from
    /// its hard link "<target>.older", or nothing where there was none (an
    /// older file without that link cannot come back: the new one stays).
    void take_back(const std::string &target, const bool existed, const bool linked) noexcept
    {
      if (linked)
        std::rename((target + ".older").c_str(), target.c_str());
      else if (!existed)
        remove_file(target);
    }
  } // namespace

  std::vector<std::string> ReplaceTogether::commit(const bool keep_older)
  {
    if (active_group == this)
      active_group = nullptr;
    committed = true;
    const std::size_t        n = paths.size();
    std::vector<std::string> targets(n);
    bool                     older = false;
    for (std::size_t k = 0; k < n; ++k)
      older = older || (written[k] && file_exists(paths[k]));
    // Each older file keeps a second name until every rename is done, so
    // that a failed rename can take the earlier ones back.
    std::vector<bool> existed(n, false), linked(n, false);
    for (std::size_t k = 0; k < n; ++k)
      if (written[k])
        {
          targets[k] = keep_older && older ? partial_name(paths[k]) : paths[k];
          existed[k] = file_exists(targets[k]);
          if (n > 1 && existed[k] && not_replaceable(targets[k]).empty())
            {
              remove_file(targets[k] + ".older");
              linked[k] = ::link(targets[k].c_str(), (targets[k] + ".older").c_str()) == 0;
            }
        }
    for (std::size_t k = 0; k < n; ++k)
      {
        if (!written[k])
          continue;
        const WriteOutcome out = rename_temporary(paths[k], targets[k], true);
        if (out.ok)
          continue;
        for (std::size_t j = k + 1; j < n; ++j)
          if (written[j])
            remove_file(paths[j] + ".tmp");
        for (std::size_t j = 0; j < k; ++j)
          if (written[j])
            take_back(targets[j], existed[j], linked[j]);
        for (std::size_t j = k; j < n; ++j)
          if (linked[j])
            remove_file(targets[j] + ".older");
        throw OutputError("cannot write " + out.message +
                          (k > 0 ? " (the files written with it were taken back)" : ""));
      }
    for (std::size_t k = 0; k < n; ++k)
      if (linked[k])
        remove_file(targets[k] + ".older");
    return targets;
  }

  std::string parent_directory(const std::string &path)
  {
    const std::string parent = std::filesystem::path(path).parent_path().string();
    return parent.empty() ? std::string(".") : parent;
  }

  std::string sibling_name(const std::string &path, const std::string &tag)
  {
    const std::string extension = ".h5";
    if (path.size() > extension.size() &&
        path.compare(path.size() - extension.size(), extension.size(), extension) == 0)
      return path.substr(0, path.size() - extension.size()) + tag + extension;
    return path + tag;
  }

  std::string partial_name(const std::string &path)
  {
    const auto slash = path.rfind('/');
    const auto dot   = path.rfind('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash) ||
        dot == (slash == std::string::npos ? 0 : slash + 1))
      return path + ".partial";
    return path.substr(0, dot) + ".partial" + path.substr(dot);
  }

  std::string free_sibling_name(const std::string &path, const std::string &tag)
  {
    std::string candidate = sibling_name(path, tag);
    for (int k = 2; file_exists(candidate) || file_exists(candidate + ".lock"); ++k)
      candidate = sibling_name(path, tag + "-" + std::to_string(k));
    return candidate;
  }

  bool file_exists(const std::string &path)
  {
    struct stat s;
    return ::lstat(path.c_str(), &s) == 0;
  }

  void remove_file(const std::string &path) noexcept
  {
    const FolderEntry at(path);
    if (at.ok())
      at.remove_regular(at.name());
  }

  std::string not_replaceable(const std::string &path)
  {
    const FolderEntry at(path);
    if (at.ok())
      return refusal(at, at.name());
    return file_exists(parent_directory(path)) || at.name().empty() ? at.error() : "";
  }

  std::string refused_names(const std::string &path)
  {
    for (const std::string &name :
         {path, path + ".tmp", partial_name(path), partial_name(path) + ".tmp"})
      if (const std::string why = not_replaceable(name); !why.empty())
        return name == path ? why : "its side file " + name + ": " + why;
    return "";
  }
} // namespace cdea
