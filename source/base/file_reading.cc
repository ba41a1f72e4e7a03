#include <cdea/base/file_reading.h>
#include <cdea/base/units.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace cdea
{
  namespace
  {
    std::string kind_of(const mode_t mode)
    {
      if (S_ISDIR(mode))
        return "it is a directory";
      if (S_ISFIFO(mode))
        return "it is not a regular file (a FIFO)";
      if (S_ISCHR(mode) || S_ISBLK(mode))
        return "it is not a regular file (a device)";
      if (S_ISSOCK(mode))
        return "it is not a regular file (a socket)";
      return "it is not a regular file";
    }

    std::string size_text(const std::size_t bytes)
    {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g MB", units::MB.from_si(double(bytes)));
      return text;
    }
  } // namespace

  FileRead read_regular_file(const std::string &path, const std::size_t max_bytes)
  {
    FileRead r;
    // O_NONBLOCK: opening a FIFO without a writer must not wait for one.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
      {
        r.error = errno == ENOENT ? "it does not exist" : std::strerror(errno);
        return r;
      }
    struct stat st = {};
    if (::fstat(fd, &st) != 0)
      r.error = std::strerror(errno);
    else if (!S_ISREG(st.st_mode))
      r.error = kind_of(st.st_mode);
    if (!r.error.empty())
      {
        ::close(fd);
        return r;
      }
    if (std::size_t(st.st_size) > max_bytes)
      {
        r.error = "it is larger than " + size_text(max_bytes) + " (" +
                  size_text(std::size_t(st.st_size)) + ")";
        ::close(fd);
        return r;
      }
    // Read until the end, but never past the limit (the file may grow).
    char buffer[65536];
    while (true)
      {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
          continue;
        if (n < 0)
          {
            r.error = std::strerror(errno);
            ::close(fd);
            return r;
          }
        if (n == 0)
          break;
        if (r.bytes.size() + std::size_t(n) > max_bytes)
          {
            r.error = "it is larger than " + size_text(max_bytes);
            ::close(fd);
            return r;
          }
        r.bytes.append(buffer, std::size_t(n));
      }
    ::close(fd);
    r.ok = true;
    return r;
  }

  bool is_regular_file(const std::string &path)
  {
    struct stat st = {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
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
