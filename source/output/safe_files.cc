#include <cdea/output/safe_files.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace cdea
{
  namespace
  {
    std::string system_message(const std::string &path, const int error)
    {
      return path + ": " + std::strerror(error);
    }
  } // namespace

  WriteOutcome replace_file(const std::string &path, const std::vector<char> &bytes,
                            const bool sync)
  {
    WriteOutcome      outcome;
    const std::string tmp = path + ".tmp";
    const auto        failed = [&](const int error, const int fd) {
      outcome.error   = error;
      outcome.message = system_message(tmp, error);
      if (fd >= 0)
        ::close(fd);
      ::unlink(tmp.c_str());
      return outcome;
    };
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
      return failed(errno, -1);
    while (outcome.written < bytes.size())
      {
        const ssize_t n =
          ::write(fd, bytes.data() + outcome.written, bytes.size() - outcome.written);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          return failed(n < 0 ? errno : ENOSPC, fd);
        outcome.written += std::size_t(n);
      }
    if (sync && ::fsync(fd) != 0)
      return failed(errno, fd);
    if (::close(fd) != 0)
      return failed(errno, -1);
    if (::rename(tmp.c_str(), path.c_str()) != 0)
      {
        const int error = errno;
        ::unlink(tmp.c_str());
        outcome.error   = error;
        outcome.message = system_message(path, error);
        return outcome;
      }
    outcome.ok = true;
    return outcome;
  }

  OutputLock::~OutputLock() { release(); }

  OutputLock::OutputLock(OutputLock &&other) noexcept
    : fd(other.fd)
    , lock_path(std::move(other.lock_path))
  {
    other.fd = -1;
  }

  OutputLock &OutputLock::operator=(OutputLock &&other) noexcept
  {
    if (this != &other)
      {
        release();
        fd        = other.fd;
        lock_path = std::move(other.lock_path);
        other.fd  = -1;
      }
    return *this;
  }

  bool OutputLock::acquire(const std::string &path, std::string &why)
  {
    release();
    const std::string name = path + ".lock";
    // The lock file is deleted by its holder on release: a lock taken on a
    // file that has meanwhile been deleted or replaced is worthless, so the
    // path must still name the locked file afterwards.
    for (int attempt = 0; attempt < 100; ++attempt)
      {
        const int f = ::open(name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (f < 0)
          {
            why = "cannot create the lock file " + system_message(name, errno);
            return false;
          }
        if (::flock(f, LOCK_EX | LOCK_NB) != 0)
          {
            const int error = errno;
            char      holder[32] = {};
            const ssize_t n = ::pread(f, holder, sizeof(holder) - 1, 0);
            ::close(f);
            if (error != EWOULDBLOCK)
              {
                why = "cannot lock " + system_message(name, error);
                return false;
              }
            std::string pid = n > 0 ? std::string(holder, std::size_t(n)) : std::string();
            while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' '))
              pid.pop_back();
            why = "another cdea process" + (pid.empty() ? std::string() : " (pid " + pid + ")") +
                  " is writing " + path + " (lock file " + name + ")";
            return false;
          }
        struct stat locked, named;
        if (::fstat(f, &locked) == 0 && ::stat(name.c_str(), &named) == 0 &&
            locked.st_dev == named.st_dev && locked.st_ino == named.st_ino)
          {
            const std::string pid = std::to_string(::getpid()) + "\n";
            if (::ftruncate(f, 0) != 0 || ::pwrite(f, pid.data(), pid.size(), 0) < 0)
              {
                // Unreadable holder id: the lock itself still holds.
              }
            fd        = f;
            lock_path = name;
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
    // path gone or new and retries (see acquire()).
    ::unlink(lock_path.c_str());
    ::close(fd);
    fd = -1;
  }

  bool claim_output(const std::string &path, OutputLock &lock, std::string &why,
                    std::vector<std::string> *created_out)
  {
    std::vector<std::string> created;
    try
      {
        const std::string directory = parent_directory(path);
        created                     = create_directories(directory);
        if (::access(directory.c_str(), W_OK) != 0)
          why = "the directory '" + directory + "' is not writable";
        else if (DirectoryIdentity::of(path).valid)
          why = "it is a directory";
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

  void remove_file(const std::string &path) noexcept { ::unlink(path.c_str()); }
} // namespace cdea
