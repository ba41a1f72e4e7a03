#pragma once
// Results as bytes for mpi::gather_bytes (base/mpi_session.h): numbers are
// copied with memcpy, so that doubles arrive bit for bit; strings and vectors
// carry their length. Used by the distributed `cdea sweep` and `cdea
// frequency-sweep`.

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace cdea
{
  class BytePacker
  {
  public:
    std::string bytes;
    void put(const double x) { append(&x, sizeof x); }
    void put(const std::uint64_t x) { append(&x, sizeof x); }
    void put(const std::string &s)
    {
      put(std::uint64_t(s.size()));
      append(s.data(), s.size());
    }
    void put(const std::vector<double> &v)
    {
      put(std::uint64_t(v.size()));
      append(v.data(), v.size() * sizeof(double));
    }

  private:
    void append(const void *p, const std::size_t n)
    {
      bytes.append(static_cast<const char *>(p), n);
    }
  };

  /// Reads what a BytePacker wrote, in the same order; throws
  /// std::runtime_error when the bytes end too early.
  class ByteUnpacker
  {
  public:
    explicit ByteUnpacker(const std::string &bytes)
      : p(bytes.data())
      , end(bytes.data() + bytes.size())
    {}
    bool          done() const { return p == end; }
    double        get_double() { return get<double>(); }
    std::uint64_t get_uint() { return get<std::uint64_t>(); }
    std::string   get_string()
    {
      const std::size_t n = get_uint();
      need(n);
      std::string s(p, n);
      p += n;
      return s;
    }
    std::vector<double> get_vector()
    {
      const std::size_t   n = get_uint();
      std::vector<double> v(n);
      need(n * sizeof(double));
      std::memcpy(v.data(), p, n * sizeof(double));
      p += n * sizeof(double);
      return v;
    }

  private:
    const char *p, *end;
    void        need(const std::size_t n) const
    {
      if (std::size_t(end - p) < n)
        throw std::runtime_error("truncated data in the gather of the ranks' results");
    }
    template <typename T>
    T get()
    {
      need(sizeof(T));
      T x;
      std::memcpy(&x, p, sizeof(T));
      p += sizeof(T);
      return x;
    }
  };
} // namespace cdea
