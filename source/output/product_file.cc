#include <cdea/model/product.h>
#include <cdea/output/file_attribute.h>
#include <cdea/output/hdf5_writer.h>
#include <cdea/output/product_file.h>

#include <stdexcept>

namespace cdea
{
  namespace
  {
    std::string child(const std::string &group, const char *name)
    {
      return (group == "/" ? group : group + "/") + name;
    }

    /// A list of texts as one attribute: its items separated by "; ".
    std::string joined(const std::vector<std::string> &texts)
    {
      std::string all;
      for (const std::string &t : texts)
        all += (all.empty() ? "" : "; ") + t;
      return all;
    }

    void write_attribute(Hdf5Writer &w, const std::string &group, const ProductEntry &e)
    {
      const FileAttribute a = file_attribute(e);
      if (a.kind == FileAttribute::Kind::text)
        w.attribute(group, a.name, a.text);
      else if (a.kind == FileAttribute::Kind::integer)
        w.attribute(group, a.name, static_cast<int>(a.values.at(0)));
      else if (a.dims.empty())
        w.attribute(group, a.name, a.values.at(0));
      else if (a.dims.size() == 2 && !a.values.empty())
        w.attribute(group, a.name, a.values, a.dims[0], a.dims[1]);
      else
        w.attribute(group, a.name, a.values);
    }

    /// The real or the imaginary parts of a complex entry in the row's unit.
    std::vector<double> part(const ProductEntry &e, const std::size_t which)
    {
      std::vector<double> v(e.size());
      for (std::size_t k = 0; k < v.size(); ++k)
        v[k] = e.quantity->unit.from_si(e.values[2 * k + which]);
      return v;
    }

    void write_dataset(Hdf5Writer &w, const std::string &group, const ProductEntry &e)
    {
      const Quantity   &row  = *e.quantity;
      const std::string path = child(group, row.name);
      switch (row.storage)
        {
          case Storage::text:
            w.dataset(path, e.texts, e.description());
            break;
          case Storage::integer:
            w.dataset(path, std::vector<int>(e.values.begin(), e.values.end()), e.description());
            break;
          case Storage::complex:
            for (const std::size_t which : {0, 1})
              {
                const Quantity &p = which == 0 ? *row.real_part : *row.imaginary_part;
                w.dataset(child(group, p.name), e.dims, part(e, which), p.unit.name,
                          p.description);
              }
            break;
          case Storage::real:
            w.dataset(path, e.dims, e.in_unit(), row.unit.name, e.description());
            break;
        }
    }
  } // namespace

  FileAttribute real_attribute(const std::string &name, const std::vector<double> &values,
                               const unsigned int rows, const unsigned int columns)
  {
    FileAttribute a;
    a.name   = name;
    a.dims   = rows > 0 ? std::vector<std::size_t>{rows, columns} :
                          std::vector<std::size_t>{values.size()};
    a.values = values;
    return a;
  }

  FileAttribute file_attribute(const ProductEntry &e)
  {
    const Quantity &row = *e.quantity;
    FileAttribute   a;
    a.name = row.name;
    a.dims = e.dims;
    if (row.storage == Storage::text)
      {
        a.kind = FileAttribute::Kind::text;
        a.text = e.dims.empty() ? e.texts.at(0) : joined(e.texts);
        return a;
      }
    a.kind   = row.storage == Storage::integer ? FileAttribute::Kind::integer :
                                                 FileAttribute::Kind::real;
    a.values = e.in_unit();
    return a;
  }

  void write_product_file(const Product &product, const std::string &path)
  {
    Hdf5Writer w(path);
    for (const ProductGroup &g : product.groups)
      {
        if (g.name() != "/")
          w.group(g.name());
        for (const ProductEntry &e : g.attributes)
          write_attribute(w, g.name(), e);
        for (const ProductEntry &e : g.datasets)
          write_dataset(w, g.name(), e);
      }
    w.commit();
  }
} // namespace cdea
