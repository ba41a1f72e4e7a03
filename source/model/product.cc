#include <cdea/model/product.h>

#include <stdexcept>

namespace cdea
{
  std::size_t ProductEntry::size() const
  {
    if (quantity->storage == Storage::text)
      return texts.size();
    return quantity->storage == Storage::complex ? values.size() / 2 : values.size();
  }

  std::vector<double> ProductEntry::in_unit() const
  {
    std::vector<double> converted(values.size());
    for (std::size_t k = 0; k < values.size(); ++k)
      converted[k] = quantity->unit.from_si(values[k]);
    return converted;
  }

  ProductEntry &ProductGroup::entry(const Quantity &row, const Storage storage)
  {
    const bool numbers = storage == Storage::real || storage == Storage::integer;
    if (row.storage != storage && !(numbers && (row.storage == Storage::real ||
                                                row.storage == Storage::integer)))
      throw std::logic_error("product group '" + path + "': '" + row.name +
                             "' is set with a value of another kind than its row's");
    std::vector<ProductEntry> &list = row.place == Place::attribute ? attributes : datasets;
    for (ProductEntry &e : list)
      if (e.quantity == &row)
        {
          e = ProductEntry();
          e.quantity = &row;
          return e;
        }
    list.emplace_back();
    list.back().quantity = &row;
    return list.back();
  }

  ProductGroup &ProductGroup::set(const Quantity &row, const double si_value)
  {
    entry(row, Storage::real).values = {si_value};
    return *this;
  }

  ProductGroup &ProductGroup::set(const Quantity &row, const std::string &text)
  {
    entry(row, Storage::text).texts = {text};
    return *this;
  }

  ProductGroup &ProductGroup::set(const Quantity &row, std::vector<double> si_values,
                                  std::vector<std::size_t> dims)
  {
    return set_detailed(row, std::move(si_values), std::move(dims), "");
  }

  ProductGroup &ProductGroup::set_detailed(const Quantity &row, std::vector<double> si_values,
                                           std::vector<std::size_t> dims, std::string detail)
  {
    ProductEntry &e = entry(row, Storage::real);
    e.dims          = dims.empty() ? std::vector<std::size_t>{si_values.size()} : std::move(dims);
    e.values        = std::move(si_values);
    e.detail        = std::move(detail);
    return *this;
  }

  ProductGroup &ProductGroup::set(const Quantity &row, std::vector<std::string> texts)
  {
    ProductEntry &e = entry(row, Storage::text);
    e.dims          = {texts.size()};
    e.texts         = std::move(texts);
    return *this;
  }

  ProductGroup &ProductGroup::set(const Quantity                          &row,
                                  const std::vector<std::complex<double>> &si_values,
                                  std::vector<std::size_t>                 dims)
  {
    ProductEntry &e = entry(row, Storage::complex);
    e.dims          = dims.empty() ? std::vector<std::size_t>{si_values.size()} : std::move(dims);
    e.values.reserve(2 * si_values.size());
    for (const std::complex<double> &z : si_values)
      {
        e.values.push_back(z.real());
        e.values.push_back(z.imag());
      }
    return *this;
  }

  ProductGroup &ProductGroup::set(const ProductEntry &value)
  {
    entry(*value.quantity, value.quantity->storage) = value;
    return *this;
  }

  const ProductEntry *ProductGroup::find(const Quantity &row) const
  {
    for (const auto *list : {&attributes, &datasets})
      for (const ProductEntry &e : *list)
        if (e.quantity == &row)
          return &e;
    return nullptr;
  }

  const ProductEntry *ProductGroup::find(const std::string &name) const
  {
    for (const auto *list : {&attributes, &datasets})
      for (const ProductEntry &e : *list)
        if (name == e.name())
          return &e;
    return nullptr;
  }

  const ProductEntry &ProductGroup::at(const Quantity &row) const
  {
    if (const ProductEntry *e = find(row))
      return *e;
    throw std::out_of_range("product group '" + path + "' has no '" + row.name + "'");
  }

  Product::Product() { groups.emplace_back("/"); }

  ProductGroup &Product::group(const std::string &path)
  {
    for (ProductGroup &g : groups)
      if (g.name() == path)
        return g;
    groups.emplace_back(path);
    return groups.back();
  }

  const ProductGroup *Product::find(const std::string &path) const
  {
    for (const ProductGroup &g : groups)
      if (g.name() == path)
        return &g;
    return nullptr;
  }

  const ProductGroup &Product::at(const std::string &path) const
  {
    if (const ProductGroup *g = find(path))
      return *g;
    throw std::out_of_range("the product has no group '" + path + "'");
  }
} // namespace cdea
