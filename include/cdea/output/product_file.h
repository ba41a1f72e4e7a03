#pragma once
// The one HDF5 writer of products (model/product.h): every group, attribute
// and dataset of a product, each value converted from SI by its row of the
// table of quantities, written whole through Hdf5Writer (built in memory,
// then replace_file(): an older file stays until the new one is complete).
// Datasets carry their row's `unit` and `description`; integers are 32-bit,
// texts variable-length UTF-8, a complex dataset its two real parts.

#include <string>

namespace cdea
{
  class Product;

  /// Writes @p product to @p path. Throws std::runtime_error naming the path
  /// if it cannot be written (an older file of the name stays as it was).
  void write_product_file(const Product &product, const std::string &path);
} // namespace cdea
