#pragma once
// The check of a product file against its product and the table of
// quantities (tests/test_products.cc): every group, attribute and dataset of
// the file is a value of the product, named by its row of the table, with
// the row's `unit` and `description`, its dimensions, and values that are
// the row's conversion of the product's SI values bit for bit; nothing else
// is in the file. Plain HDF5 C API.

#include <cdea/model/product.h>
#include <cdea/output/file_attribute.h>

#include <hdf5.h>

#include "check.h"

#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace cdea_test
{
  /// A dataset or attribute as read back: dimensions, numbers, texts.
  struct Read
  {
    bool                     found = false, integer = false, text = false, null_space = false;
    std::vector<hsize_t>     dims;
    std::vector<double>      values;
    std::vector<std::string> texts;
  };

  inline Read read_values(const hid_t object, const bool attribute)
  {
    Read        r;
    const hid_t type  = attribute ? H5Aget_type(object) : H5Dget_type(object);
    const hid_t space = attribute ? H5Aget_space(object) : H5Dget_space(object);
    r.found           = true;
    r.integer         = H5Tget_class(type) == H5T_INTEGER;
    r.text            = H5Tget_class(type) == H5T_STRING;
    r.null_space      = H5Sget_simple_extent_type(space) == H5S_NULL;
    const int rank    = r.null_space ? 0 : H5Sget_simple_extent_ndims(space);
    r.dims.resize(std::size_t(std::max(rank, 0)));
    if (rank > 0)
      H5Sget_simple_extent_dims(space, r.dims.data(), nullptr);
    const hssize_t n = r.null_space ? 0 : H5Sget_simple_extent_npoints(space);
    if (r.text)
      {
        std::vector<char *> pointers(std::size_t(n), nullptr);
        if (n > 0)
          attribute ? H5Aread(object, type, pointers.data()) :
                      H5Dread(object, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data());
        for (char *p : pointers)
          {
            r.texts.emplace_back(p ? p : "");
            H5free_memory(p);
          }
      }
    else
      {
        r.values.resize(std::size_t(n));
        if (n > 0)
          attribute ? H5Aread(object, H5T_NATIVE_DOUBLE, r.values.data()) :
                      H5Dread(object, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                              r.values.data());
      }
    H5Sclose(space);
    H5Tclose(type);
    return r;
  }

  inline Read read_attribute(const hid_t file, const std::string &object, const std::string &name)
  {
    if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
      return {};
    const hid_t a = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    const Read  r = read_values(a, true);
    H5Aclose(a);
    return r;
  }

  inline Read read_dataset(const hid_t file, const std::string &path)
  {
    if (H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0)
      return {};
    const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    const Read  r   = read_values(set, false);
    H5Dclose(set);
    return r;
  }

  /// Bit for bit (NaN equal to the same NaN).
  inline bool same_values(const std::vector<double> &a, const std::vector<double> &b)
  {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
  }

  struct Visit
  {
    std::set<std::string> *all;
    std::string            path;
  };

  inline herr_t add_attribute(hid_t, const char *name, const H5A_info_t *, void *data)
  {
    const Visit *v = static_cast<const Visit *>(data);
    v->all->insert(v->path + "@" + name);
    return 0;
  }

  inline herr_t add_link(hid_t, const char *name, const H5L_info_t *, void *data)
  {
    static_cast<std::vector<std::string> *>(data)->push_back("/" + std::string(name));
    return 0;
  }

  /// Every object below the root and every attribute of each, as
  /// "/path" and "/path@name" ("/@name" for the root's).
  inline std::set<std::string> file_contents(const hid_t file)
  {
    std::set<std::string> all;
    Visit                 root{&all, "/"};
    H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, add_attribute, &root);
    std::vector<std::string> paths;
    H5Lvisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, add_link, &paths);
    for (const std::string &p : paths)
      {
        all.insert(p);
        Visit       v{&all, p};
        const hid_t object = H5Oopen(file, p.c_str(), H5P_DEFAULT);
        H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, add_attribute, &v);
        H5Oclose(object);
      }
    return all;
  }

  /// The row of a value has a name, a unit (none for a text, 1 for a whole
  /// number) and a description.
  inline bool row_described(const cdea::Quantity &row)
  {
    using cdea::Storage;
    const std::string unit = row.unit.name;
    return *row.name && std::strlen(row.description) > 3 &&
           (row.storage == Storage::text ? unit.empty() :
            row.storage == Storage::integer ? unit == "1" : !unit.empty());
  }

  inline bool attribute_agrees(const hid_t file, const std::string &group,
                               const cdea::ProductEntry &e)
  {
    using Kind             = cdea::FileAttribute::Kind;
    const cdea::FileAttribute a = cdea::file_attribute(e);
    const Read                r = read_attribute(file, group, a.name);
    if (!r.found)
      return false;
    if (a.kind == Kind::text)
      return r.text && r.texts.size() == 1 && r.texts[0] == a.text;
    if (a.values.empty())
      return r.null_space;
    const std::vector<hsize_t> dims(a.dims.begin(), a.dims.end());
    return r.integer == (a.kind == Kind::integer) && r.dims == dims &&
           same_values(r.values, a.values);
  }

  /// The file's dataset @p path against @p row with @p values (in the unit).
  inline bool dataset_agrees(const hid_t file, const std::string &path, const cdea::Quantity &row,
                             const std::string &description, const std::vector<hsize_t> &dims,
                             const std::vector<double> &values,
                             const std::vector<std::string> &texts)
  {
    const Read r = read_dataset(file, path);
    const Read unit = read_attribute(file, path, "unit");
    const Read text = read_attribute(file, path, "description");
    if (!r.found || !unit.found || !text.found || unit.texts.at(0) != row.unit.name ||
        text.texts.at(0) != description || r.dims != dims)
      return false;
    if (row.storage == cdea::Storage::text)
      return r.text && r.texts == texts;
    return r.integer == (row.storage == cdea::Storage::integer) && same_values(r.values, values);
  }

  /// Checks that the objects @p found of a file are those @p expected and
  /// that none is @p wrong, listing those that are not.
  inline void check_contents(const std::set<std::string> &found,
                             const std::set<std::string> &expected,
                             const std::vector<std::string> &wrong, const std::string &what)
  {
    std::string odd;
    for (const std::string &f : found)
      if (!expected.count(f))
        odd += " " + f;
    for (const std::string &e : expected)
      if (!found.count(e))
        odd += " missing:" + e;
    check(odd.empty(), what + ": every object of the file is a value of its product" + odd);
    std::string list;
    for (const std::string &w : wrong)
      list += " " + w;
    check(wrong.empty(), what + ": names, units, descriptions, dimensions and values bit for bit "
                                "as the rows say" + list);
  }

  /// The whole check of the file at @p path against @p product.
  inline void check_product_file(const cdea::Product &product, const std::string &path,
                                 const std::string &what)
  {
    using namespace cdea;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (!check(file >= 0, what + ": the file opens"))
      return;
    std::set<std::string>    expected;
    std::vector<std::string> wrong;
    for (const ProductGroup &g : product.groups)
      {
        if (g.name() != "/")
          expected.insert(g.name());
        const std::string prefix = g.name() == "/" ? "/" : g.name() + "/";
        for (const ProductEntry &e : g.attributes)
          {
            expected.insert(g.name() + "@" + e.name());
            if (!attribute_agrees(file, g.name(), e) || !row_described(*e.quantity))
              wrong.push_back(g.name() + "@" + e.name());
          }
        for (const ProductEntry &e : g.datasets)
          {
            const Quantity            &row = *e.quantity;
            const std::vector<hsize_t> dims(e.dims.begin(), e.dims.end());
            std::vector<std::pair<const Quantity *, std::vector<double>>> parts;
            if (row.storage == Storage::complex)
              for (const std::size_t which : {0, 1})
                {
                  std::vector<double> v;
                  for (std::size_t k = 0; k < e.size(); ++k)
                    v.push_back(row.unit.from_si(e.values[2 * k + which]));
                  parts.push_back({which ? row.imaginary_part : row.real_part, v});
                }
            else
              parts.push_back({&row, e.in_unit()});
            for (const auto &[part, values] : parts)
              {
                const std::string p = prefix + part->name;
                expected.insert({p, p + "@unit", p + "@description"});
                const std::string text = part == &row ? e.description() : part->description;
                if (!dataset_agrees(file, p, *part, text, dims, values, e.texts) ||
                    !row_described(*part))
                  wrong.push_back(p);
              }
          }
      }
    const std::set<std::string> found = file_contents(file);
    H5Fclose(file);
    check_contents(found, expected, wrong, what);
  }
} // namespace cdea_test
