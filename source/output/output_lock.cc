// The lock of an output file and the claim of its folder (safe_files.h).
#include <cdea/base/file_reading.h>
#include <cdea/output/safe_files.h>

#include "folder_entry.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <stdexcept>

namespace cdea
{
  using files::FolderEntry;
  using files::system_message;

  OutputLock::~OutputLock() { release(); }

  OutputLock::OutputLock(OutputLock &&other) noexcept
    : fd(other.fd)
    , folder_fd(other.folder_fd)
    , lock_name(std::move(other.lock_name))
  {
    other.fd        = -1;
    other.folder_fd = -1;
  }

  OutputLock &OutputLock::operator=(OutputLock &&other) noexcept
  {
    if (this != &other)
      {
        release();
        fd              = other.fd;
        folder_fd       = other.folder_fd;
        lock_name       = std::move(other.lock_name);
        other.fd        = -1;
        other.folder_fd = -1;
      }
    return *this;
  }

  namespace
  {
    /// The process id in the lock file @p f of another holder, for the message.
    std::string holder_of(const int f)
    {
      char          holder[32] = {};
      const ssize_t n          = ::pread(f, holder, sizeof(holder) - 1, 0);
      std::string   pid = n > 0 ? std::string(holder, std::size_t(n)) : std::string();
      while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' '))
        pid.pop_back();
      if (pid.find_first_not_of("0123456789") != std::string::npos)
        pid.clear(); // not written by cdea: not shown
      return pid;
    }

    /// Opens the lock file (created if missing) in @p at without following a
    /// link, without blocking on a FIFO and without opening a device; -1
    /// with @p why if the name holds anything but a regular file of one link.
    int open_lock_file(const FolderEntry &at, const std::string &name, std::string &why)
    {
      struct stat before = {};
      if (at.stat(before) && !S_ISREG(before.st_mode))
        {
          why = "the lock file " + name + " is " + file_kind(before.st_mode) +
                ", not cdea's: remove it";
          return -1;
        }
      const int f = ::openat(at.folder_fd(), at.name().c_str(),
                             O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
      if (f < 0)
        {
          why = errno == ELOOP ? "the lock file " + name + " is a symbolic link, not cdea's: "
                                 "remove it" :
                                 "cannot create the lock file " + system_message(name, errno);
          return -1;
        }
      struct stat opened = {};
      if (::fstat(f, &opened) != 0 || !S_ISREG(opened.st_mode) || opened.st_nlink != 1)
        {
          why = "the lock file " + name + " is " +
                (S_ISREG(opened.st_mode) ? std::string("a hard link to another file") :
                                           file_kind(opened.st_mode)) +
                ", not cdea's: remove it";
          ::close(f);
          return -1;
        }
      return f;
    }
  } // namespace

  bool OutputLock::acquire(const std::string &path, std::string &why)
  {
    release();
    const std::string name = path + ".lock";
    FolderEntry       at(name);
    if (!at.ok())
      {
        why = at.error();
        return false;
      }
    // The lock file is deleted by its holder on release: a lock taken on a
    // file that has meanwhile been deleted or replaced is worthless, so the
    // name must still hold the locked file afterwards.
    for (int attempt = 0; attempt < 100; ++attempt)
      {
        const int f = open_lock_file(at, name, why);
        if (f < 0)
          return false;
        if (::flock(f, LOCK_EX | LOCK_NB) != 0)
          {
            const int         error = errno;
            const std::string pid   = holder_of(f);
            ::close(f);
            why = error != EWOULDBLOCK ?
                    "cannot lock " + system_message(name, error) :
                    "another cdea process" + (pid.empty() ? std::string() : " (pid " + pid + ")") +
                      " is writing " + path + " (lock file " + name + ")";
            return false;
          }
        struct stat locked = {}, named = {};
        if (::fstat(f, &locked) == 0 && at.stat(named) && locked.st_dev == named.st_dev &&
            locked.st_ino == named.st_ino)
          {
            const std::string pid = std::to_string(::getpid()) + "\n";
            if (::ftruncate(f, 0) != 0 || ::pwrite(f, pid.data(), pid.size(), 0) < 0)
              {
                // Unreadable holder id: the lock itself still holds.
              }
            fd        = f;
            folder_fd = ::dup(at.folder_fd());
            lock_name = at.name();
            return true;
          }
        ::close(f);
      }
    why = "cannot take the lock " + name + ": it keeps being replaced";
    return false;
  }

  void OutputLock::release() noexcept
  {
    if (fd < 0)
      return;
    // Unlink while still holding the lock: a waiting process then finds the
    // name gone or new and retries (see acquire()). Only our own file.
    struct stat locked = {}, named = {};
    if (folder_fd >= 0 && ::fstat(fd, &locked) == 0 &&
        ::fstatat(folder_fd, lock_name.c_str(), &named, AT_SYMLINK_NOFOLLOW) == 0 &&
        locked.st_dev == named.st_dev && locked.st_ino == named.st_ino)
      ::unlinkat(folder_fd, lock_name.c_str(), 0);
    ::close(fd);
    if (folder_fd >= 0)
      ::close(folder_fd);
    fd        = -1;
    folder_fd = -1;
  }

  bool claim_output(const std::string &path, OutputLock &lock, std::string &why,
                    std::vector<std::string> *created_out)
  {
    std::vector<std::string> created;
    try
      {
        const std::string directory = parent_directory(path);
        created                     = create_directories(directory);
        const FolderEntry at(path);
        if (!at.ok())
          why = at.error();
        else if (::faccessat(at.folder_fd(), ".", W_OK, 0) != 0)
          why = "the directory '" + directory + "' is not writable";
        else if (const std::string refused = refused_names(path); !refused.empty())
          why = refused;
        else
          lock.acquire(path, why);
      }
    catch (const std::exception &e)
      {
        why = e.what();
      }
    if (!lock.held())
      remove_created_directories(created);
    else if (created_out)
      *created_out = created;
    return lock.held();
  }

  std::vector<std::string> create_directories(const std::string &directory)
  {
    namespace fs = std::filesystem;
    std::vector<std::string> created;
    fs::path                 walked;
    for (const fs::path &part : fs::path(directory))
      {
        walked /= part;
        if (part.empty() || part == "/" || part == "." || part == "..")
          continue;
        if (::mkdir(walked.c_str(), 0755) == 0)
          created.push_back(walked.string());
        else if (errno != EEXIST)
          {
            const int error = errno;
            remove_created_directories(created);
            throw std::runtime_error("cannot create directory " +
                                     system_message(walked.string(), error));
          }
      }
    struct stat s;
    if (::stat(directory.c_str(), &s) != 0 || !S_ISDIR(s.st_mode))
      {
        remove_created_directories(created);
        throw std::runtime_error("cannot create directory '" + directory +
                                 "': a file of that name is in the way");
      }
    return created;
  }

  void remove_created_directories(const std::vector<std::string> &created) noexcept
  {
    for (auto it = created.rbegin(); it != created.rend(); ++it)
      ::rmdir(it->c_str());
  }

  DirectoryIdentity DirectoryIdentity::of(const std::string &directory)
  {
    DirectoryIdentity id;
    struct stat       s;
    if (::stat(directory.c_str(), &s) == 0 && S_ISDIR(s.st_mode))
      {
        id.device = s.st_dev;
        id.inode  = s.st_ino;
        id.valid  = true;
      }
    return id;
  }
} // namespace cdea
