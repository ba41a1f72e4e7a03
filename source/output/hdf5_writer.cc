#include <cdea/output/hdf5_support.h>
#include <cdea/output/hdf5_writer.h>
#include <cdea/output/safe_files.h>

#include <stdexcept>

namespace cdea
{
  using hdf5::Handle;

  // The shared checked writer on a file in memory, written to disk whole by
  // commit() through replace_file().
  struct Hdf5Writer::Impl
  {
    explicit Impl(const std::string &path)
      : writer("cannot write '" + path + "'")
    {}

    hdf5::ErrorPrintingOff quiet;
    hdf5::Writer           writer;
    Handle                 file;

    /// The object at @p path ("/" or a group's path).
    Handle object(const std::string &path) const
    {
      return Handle(writer.check(H5Oopen(file, path.c_str(), H5P_DEFAULT),
                                 "H5Oopen(" + path + ")"),
                    H5Oclose);
    }
  };

  Hdf5Writer::Hdf5Writer(const std::string &path)
    : impl(std::make_unique<Impl>(path))
    , target(path)
  {
    hdf5::create_parent_directory(path);
    // No modification times in the object headers: the same content gives
    // the same bytes.
    impl->file = hdf5::create_memory_file(path, false);
  }

  Hdf5Writer::~Hdf5Writer() = default;

  void Hdf5Writer::attribute(const std::string &object, const std::string &name,
                             const std::string &value)
  {
    impl->writer.string_attribute(impl->object(object), name, value);
  }

  void Hdf5Writer::attribute(const std::string &object, const std::string &name, const double value)
  {
    impl->writer.double_attribute(impl->object(object), name, value);
  }

  void Hdf5Writer::attribute(const std::string &object, const std::string &name, const int value)
  {
    impl->writer.int_attribute(impl->object(object), name, value);
  }

  void Hdf5Writer::attribute(const std::string &object, const std::string &name,
                             const std::vector<double> &values)
  {
    impl->writer.double_array_attribute(impl->object(object), name, values);
  }

  void Hdf5Writer::attribute(const std::string &object, const std::string &name,
                             const std::vector<double> &values, const std::size_t rows,
                             const std::size_t columns)
  {
    impl->writer.double_array_attribute(impl->object(object), name, values, unsigned(rows),
                                        unsigned(columns));
  }

  void Hdf5Writer::group(const std::string &path) { impl->writer.group(impl->file, path); }

  void Hdf5Writer::dataset(const std::string &path, const std::vector<std::size_t> &dims,
                           const std::vector<double> &values, const std::string &unit,
                           const std::string &description)
  {
    impl->writer.double_dataset(impl->file, path, std::vector<hsize_t>(dims.begin(), dims.end()),
                                values, unit, description);
  }

  void Hdf5Writer::dataset(const std::string &path, const std::vector<int> &values,
                           const std::string &description)
  {
    impl->writer.int_dataset(impl->file, path, values, description);
  }

  void Hdf5Writer::dataset(const std::string &path, const std::vector<std::string> &values,
                           const std::string &description)
  {
    impl->writer.string_dataset(impl->file, path, values, description);
  }

  void Hdf5Writer::commit()
  {
    const WriteOutcome out =
      replace_file(target, hdf5::file_image(impl->file, impl->writer.name()), true);
    impl->file.reset();
    if (!out.ok)
      throw std::runtime_error("cannot write '" + target + "': " + out.message);
  }
} // namespace cdea
