#pragma once
// An attribute as an HDF5 file holds it, values in the file's unit: a
// scalar, a list (an empty one has a null dataspace), rows x columns, a
// whole number (32-bit), or a text. What a product's attribute becomes
// (file_attribute()), and what the journal of a results file records, so
// that a file written at once, one built by steps and one recovered from a
// journal hold the same attributes.

#include <cstddef>
#include <string>
#include <vector>

namespace cdea
{
  struct ProductEntry;

  struct FileAttribute
  {
    enum class Kind : unsigned char
    {
      real,
      integer,
      text
    };
    std::string              name;
    Kind                     kind = Kind::real;
    std::vector<std::size_t> dims; ///< empty: a scalar
    std::vector<double>      values;
    std::string              text;
  };

  /// @p entry (an attribute of a product) as the file holds it: its values
  /// converted by its row, a list of texts joined by "; ".
  FileAttribute file_attribute(const ProductEntry &entry);

  /// The real attribute @p name of @p values: rows x columns, or a list if
  /// @p rows is 0.
  FileAttribute real_attribute(const std::string &name, const std::vector<double> &values,
                               unsigned int rows, unsigned int columns);
} // namespace cdea
