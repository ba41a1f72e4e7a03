#pragma once
// Small helpers for the source files that call the HDF5 C API directly
// (results file, design-map file): HDF5 errors become one-line messages for
// exceptions instead of error stacks printed to stderr. Includes hdf5.h: not
// for headers.

#include <hdf5.h>

#include <string>

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
} // namespace cdea::hdf5
