#pragma once
// A small writer of complete HDF5 files (attributes, datasets of doubles,
// integers and strings, groups), for results written once at the end of a
// command, on the checked writer of hdf5_support.h. The file is built in
// memory and commit() writes it whole through replace_file() (safe_files.h),
// so that an existing file is only replaced by a complete new one; a writer
// destroyed before commit() leaves nothing on disk. Object time stamps are
// off: the same content gives the same bytes. Every failure throws
// std::runtime_error naming the target path.

#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  class Hdf5Writer
  {
  public:
    /// Creates the parent directory if needed and starts the file in memory.
    explicit Hdf5Writer(const std::string &path);
    ~Hdf5Writer();
    Hdf5Writer(const Hdf5Writer &)            = delete;
    Hdf5Writer &operator=(const Hdf5Writer &) = delete;

    /// Attributes of the object at @p object ("/" or a group's path).
    void attribute(const std::string &object, const std::string &name, const std::string &value);
    void attribute(const std::string &object, const std::string &name, double value);
    void attribute(const std::string &object, const std::string &name, int value);
    void attribute(const std::string &object, const std::string &name,
                   const std::vector<double> &values);
    /// A rows x columns attribute (@p values row by row).
    void attribute(const std::string &object, const std::string &name,
                   const std::vector<double> &values, std::size_t rows, std::size_t columns);

    /// A group (its parents must exist).
    void group(const std::string &path);

    /// Datasets with `unit` and `description` attributes; @p dims row-major,
    /// their product the number of values.
    void dataset(const std::string &path, const std::vector<std::size_t> &dims,
                 const std::vector<double> &values, const std::string &unit,
                 const std::string &description);
    void dataset(const std::string &path, const std::vector<int> &values,
                 const std::string &description);
    void dataset(const std::string &path, const std::vector<std::string> &values,
                 const std::string &description);

    /// Write the file to the target path (replacing it whole).
    void commit();

    const std::string &path() const { return target; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
    std::string           target;
  };
} // namespace cdea
