#pragma once
// Small helpers for the source files that call the HDF5 C API directly
// (results file, map file, Hdf5Writer): HDF5 errors become one-line messages
// for exceptions instead of error stacks printed to stderr; one attribute and
// dataset writer for every file; files built in memory (the core driver
// without backing store), so that HDF5 itself never writes to disk and a file
// on disk is always a complete image written by cdea through replace_file()
// (safe_files.h). Includes hdf5.h: not for headers.

#include <hdf5.h>

#include <string>
#include <vector>

namespace cdea::hdf5
{
  /// HDF5's automatic error-stack printing off while alive; the previous
  /// handler is restored afterwards.
  class ErrorPrintingOff
  {
  public:
    ErrorPrintingOff();
    ~ErrorPrintingOff();
    ErrorPrintingOff(const ErrorPrintingOff &)            = delete;
    ErrorPrintingOff &operator=(const ErrorPrintingOff &) = delete;

  private:
    H5E_auto2_t old_func = nullptr;
    void       *old_data = nullptr;
  };

  /// An owned HDF5 identifier with its close function (H5Fclose, H5Gclose,
  /// ...); closed when the handle is reset or destroyed.
  class Handle
  {
  public:
    Handle() = default;
    Handle(const hid_t handle, herr_t (*close_function)(hid_t))
      : id(handle)
      , closer(close_function)
    {}
    ~Handle() { reset(); }
    Handle(Handle &&other) noexcept
      : id(other.id)
      , closer(other.closer)
    {
      other.id = -1;
    }
    Handle &operator=(Handle &&other) noexcept
    {
      if (this != &other)
        {
          reset();
          id       = other.id;
          closer   = other.closer;
          other.id = -1;
        }
      return *this;
    }
    Handle(const Handle &)            = delete;
    Handle &operator=(const Handle &) = delete;

    void reset() noexcept
    {
      if (id >= 0 && closer != nullptr)
        closer(id);
      id = -1;
    }
    hid_t get() const { return id; }
    operator hid_t() const { return id; }

  private:
    hid_t id = -1;
    herr_t (*closer)(hid_t) = nullptr;
  };

  /// Create the directory that will hold @p path (and its parents) if missing;
  /// throws std::runtime_error "cannot write '<path>': cannot create
  /// directory ..." if that fails.
  void create_parent_directory(const std::string &path);

  /// A one-line summary of the current HDF5 error stack (which it clears):
  /// the system error text if the innermost entry carries one, else the
  /// innermost description, followed by the outermost description.
  std::string error_text();

  /// Checked HDF5 calls and attributes, for one file. A failing call throws
  /// std::runtime_error "<context>: <call> failed: <error_text()>".
  class Writer
  {
  public:
    explicit Writer(std::string context)
      : context(std::move(context))
    {}

    [[noreturn]] void fail(const std::string &what) const;
    hid_t check(const hid_t id, const std::string &what) const
    {
      if (id < 0)
        fail(what);
      return id;
    }
    void check_status(const herr_t status, const std::string &what) const
    {
      if (status < 0)
        fail(what);
    }

    /// Attributes of @p object; an existing attribute of the name is replaced.
    /// Strings are variable-length UTF-8 (h5py reads them as str).
    void string_attribute(hid_t object, const std::string &name, const std::string &value) const;
    void int_attribute(hid_t object, const std::string &name, int value) const;
    void double_attribute(hid_t object, const std::string &name, double value) const;
    /// 1D (empty: a null dataspace) or, with @p rows > 0, rows x columns
    /// (values row by row).
    void double_array_attribute(hid_t object, const std::string &name,
                                const std::vector<double> &values, unsigned int rows = 0,
                                unsigned int columns = 0) const;
    /// The attributes "unit" and "description" of a dataset.
    void describe(hid_t object, const std::string &unit, const std::string &description) const;

    /// Datasets at @p name below @p parent, without object time stamps, with
    /// "unit" and "description"; @p dims row-major, their product the number
    /// of values (empty @p dims: a scalar). Integers have the unit "1",
    /// strings (variable-length UTF-8) none.
    void double_dataset(hid_t parent, const std::string &name, const std::vector<hsize_t> &dims,
                        const std::vector<double> &values, const std::string &unit,
                        const std::string &description) const;
    void int_dataset(hid_t parent, const std::string &name, const std::vector<int> &values,
                     const std::string &description) const;
    void string_dataset(hid_t parent, const std::string &name,
                        const std::vector<std::string> &values,
                        const std::string              &description) const;
    /// A group at @p name below @p parent (its parents must exist), without
    /// object time stamps.
    void group(hid_t parent, const std::string &name) const;

    const std::string &name() const { return context; }

  private:
    std::string context;
    void write_attribute(hid_t object, const std::string &name, hid_t file_type,
                         hid_t memory_type, hid_t space, const void *data) const;
    Handle write_dataset(hid_t parent, const std::string &name, hid_t file_type,
                       hid_t memory_type, const std::vector<hsize_t> &dims,
                       const void *data, bool empty) const;
    Handle text_type() const;
  };

  /// A new, empty HDF5 file that lives in memory only; @p track_times false
  /// leaves modification times out of the object headers (same data, same
  /// bytes). Throws std::runtime_error naming @p context.
  Handle create_memory_file(const std::string &context, bool track_times = true);

  /// The bytes of a file made by create_memory_file() as it would be on
  /// disk (flushed first). Throws std::runtime_error naming @p context.
  std::vector<char> file_image(hid_t file, const std::string &context);

  /// The size in bytes of that image, without copying it.
  std::size_t file_image_size(hid_t file, const std::string &context);
} // namespace cdea::hdf5
