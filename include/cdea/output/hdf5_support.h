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

  /// A one-line summary of the current HDF5 error stack (which it clears):
  /// the system error text if the innermost entry carries one, else the
  /// innermost description, followed by the outermost description.
  std::string error_text();
} // namespace cdea::hdf5
