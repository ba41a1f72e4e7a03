#pragma once
// What a study returns: a self-describing dataset in the manner of xarray.
// Named groups ("/", "/dma", "/steps/000003") hold attributes and datasets;
// each value names its row of the table of quantities (model/quantity.h),
// its dimensions and its values in SI. A study builds its product with one
// `set` per value; the HDF5 writer (output/product_file.h), the Python
// converter (python/) and the table printer (output/product_table.h) read
// it and convert each value by its row, so that all three hold the same
// numbers under the same names. No HDF5, no deal.II.

#include <cdea/model/quantity.h>

#include <complex>
#include <cstddef>
#include <deque>
#include <string>
#include <type_traits>
#include <vector>

namespace cdea
{
  /// One attribute or dataset of a product.
  struct ProductEntry
  {
    const Quantity          *quantity = nullptr;
    std::vector<std::size_t> dims;   ///< outermost first; empty: a scalar
    std::vector<double>      values; ///< SI; whole numbers if integer; complex: re, im pairs
    std::vector<std::string> texts;  ///< Storage::text
    std::string              detail; ///< appended to the row's description (e.g. names)

    const char *name() const { return quantity->name; }
    std::string description() const { return quantity->description + detail; }
    /// The number of values (of texts for a text, of complex numbers for a complex).
    std::size_t size() const;
    /// Value @p k in the row's unit (the real part's for a complex).
    double value(std::size_t k) const { return quantity->unit.from_si(values[k]); }
    /// Every value in the row's unit.
    std::vector<double> in_unit() const;
  };

  /// A group of a product: its path, attributes and datasets in the order set.
  class ProductGroup
  {
  public:
    explicit ProductGroup(std::string path)
      : path(std::move(path))
    {}

    /// Sets (or replaces) the value of @p row; it goes to the attributes or
    /// datasets as the row says. A vector is one-dimensional unless @p dims
    /// says otherwise (their product its size). Throws std::logic_error if
    /// the value is not of the row's storage.
    ProductGroup &set(const Quantity &row, double si_value);
    template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
    ProductGroup &set(const Quantity &row, const Integer value)
    {
      return set(row, static_cast<double>(value));
    }
    ProductGroup &set(const Quantity &row, const std::string &text);
    ProductGroup &set(const Quantity &row, const char *text) { return set(row, std::string(text)); }
    ProductGroup &set(const Quantity &row, std::vector<double> si_values,
                      std::vector<std::size_t> dims = {});
    ProductGroup &set(const Quantity &row, std::vector<std::string> texts);
    ProductGroup &set(const Quantity &row, const std::vector<std::complex<double>> &si_values,
                      std::vector<std::size_t> dims = {});
    /// Sets (or replaces) @p entry, a value of another group.
    ProductGroup &set(const ProductEntry &entry);
    /// The same as set(), with @p detail appended to the row's description.
    ProductGroup &set_detailed(const Quantity &row, std::vector<double> si_values,
                               std::vector<std::size_t> dims, std::string detail);

    /// The value of @p row, or of the entry named @p name; null if not set.
    const ProductEntry *find(const Quantity &row) const;
    const ProductEntry *find(const std::string &name) const;
    /// The same; throws std::out_of_range naming the group if not set.
    const ProductEntry &at(const Quantity &row) const;

    const std::string        &name() const { return path; }
    std::vector<ProductEntry> attributes, datasets;

  private:
    std::string   path;
    ProductEntry &entry(const Quantity &row, Storage storage);
  };

  class Product
  {
  public:
    /// A product with its root group "/".
    Product();

    ProductGroup       &root() { return groups.front(); }
    const ProductGroup &root() const { return groups.front(); }
    /// The group at @p path, added after the others if new.
    ProductGroup &group(const std::string &path);
    /// The group at @p path; null if there is none.
    const ProductGroup *find(const std::string &path) const;
    /// The same; throws std::out_of_range if there is none.
    const ProductGroup &at(const std::string &path) const;

    /// The groups, "/" first, then in the order they were added (a group's
    /// parents before it).
    std::deque<ProductGroup> groups;
  };
} // namespace cdea
