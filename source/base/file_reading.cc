#include <cdea/base/file_reading.h>
#include <cdea/base/units.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace cdea
{
  namespace
  {
    /// Why a file of @p mode is not read: "it is a directory", "it is not
    /// a regular file (a FIFO)", ...
    std::string kind_of(const mode_t mode)
    {
      if (S_ISDIR(mode))
        return "it is a directory";
      if (S_ISLNK(mode) || S_ISREG(mode))
        return "it is " + file_kind(mode);
      return "it is not a regular file (" + file_kind(mode) + ")";
    }

    std::string size_text(const std::size_t bytes)
    {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g MB", units::MB.from_si(double(bytes)));
      return text;
    }
  } // namespace

  namespace
  {
    /// A descriptor closed on every way out.
    struct Descriptor
    {
      int fd;
      ~Descriptor()
      {
        if (fd >= 0)
          ::close(fd);
      }
    };

    /// Appends up to @p limit + 1 bytes of @p fd to @p bytes (one more than
    /// allowed tells a file that grew past the limit); "" or the error.
    std::string read_up_to(const int fd, const std::size_t limit, std::string &bytes)
    {
      char buffer[65536];
      while (bytes.size() <= limit)
        {
          const std::size_t want = std::min(sizeof buffer, limit + 1 - bytes.size());
          const ssize_t     n    = ::read(fd, buffer, want);
          if (n < 0 && errno == EINTR)
            continue;
          if (n < 0)
            return std::strerror(errno);
          if (n == 0)
            break;
          bytes.append(buffer, std::size_t(n));
        }
      return "";
    }
  } // namespace

  FileRead read_regular_file(const std::string &path, const std::size_t max_bytes,
                             const ReadOptions &options)
  {
    FileRead r;
    // Nothing but a regular file is opened (opening a device can act on it);
    // the open file is checked again below, in case the name changed.
    if (struct stat named = {};
        (options.follow_links ? ::stat(path.c_str(), &named) : ::lstat(path.c_str(), &named)) ==
          0 &&
        !S_ISREG(named.st_mode))
      {
        r.error = kind_of(named.st_mode);
        return r;
      }
    // O_NONBLOCK: opening a FIFO without a writer must not wait for one.
    const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC |
                                                 (options.follow_links ? 0 : O_NOFOLLOW))};
    if (file.fd < 0)
      {
        r.error = errno == ENOENT ? "it does not exist" :
                  errno == ELOOP && !options.follow_links ?
                                    "it is a symbolic link" :
                                    std::strerror(errno);
        return r;
      }
    struct stat st = {};
    if (::fstat(file.fd, &st) != 0)
      r.error = std::strerror(errno);
    else if (!S_ISREG(st.st_mode))
      r.error = kind_of(st.st_mode);
    else if (std::size_t(st.st_size) > max_bytes)
      r.error = "it is larger than " + size_text(max_bytes) + " (" +
                size_text(std::size_t(st.st_size)) + ")";
    if (!r.error.empty())
      return r;
    r.device = std::uint64_t(st.st_dev);
    r.inode  = std::uint64_t(st.st_ino);
    if (options.head_bytes > 0)
      {
        r.error = read_up_to(file.fd, std::min(options.head_bytes, max_bytes + 1) - 1, r.bytes);
        if (r.error.empty() && options.check_head)
          options.check_head(r.bytes);
      }
    // Read until the end, but never past the limit (the file may grow).
    if (r.error.empty())
      r.error = read_up_to(file.fd, max_bytes, r.bytes);
    if (r.error.empty() && r.bytes.size() > max_bytes)
      r.error = "it is larger than " + size_text(max_bytes);
    r.ok = r.error.empty();
    if (!r.ok)
      r.bytes.clear();
    return r;
  }

  bool is_regular_file(const std::string &path, const bool follow_links)
  {
    struct stat st = {};
    return (follow_links ? ::stat(path.c_str(), &st) : ::lstat(path.c_str(), &st)) == 0 &&
           S_ISREG(st.st_mode);
  }

  std::string file_kind(const unsigned int st_mode)
  {
    const mode_t mode = mode_t(st_mode);
    if (S_ISLNK(mode))
      return "a symbolic link";
    if (S_ISDIR(mode))
      return "a directory";
    if (S_ISFIFO(mode))
      return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode))
      return "a device";
    if (S_ISSOCK(mode))
      return "a socket";
    return "a regular file";
  }

  bool has_extension(const std::string &path, const std::string &extension)
  {
    const std::size_t slash = path.rfind('/');
    const std::string name  = slash == std::string::npos ? path : path.substr(slash + 1);
    if (name.size() <= extension.size())
      return false;
    for (std::size_t i = 0; i < extension.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(name[name.size() - extension.size() + i])) !=
          std::tolower(static_cast<unsigned char>(extension[i])))
        return false;
    return true;
  }

  std::string printable(const std::string &text)
  {
    std::string out;
    for (const char c : text)
      {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7f)
          out += c;
        else
          {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02X", u);
            out += hex;
          }
      }
    return out;
  }
} // namespace cdea
