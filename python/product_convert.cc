#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "product_convert.h"

#include <complex>

namespace cdea::python
{
  namespace
  {
    std::vector<py::ssize_t> shape_of(const ProductEntry &e)
    {
      std::vector<py::ssize_t> shape(e.dims.begin(), e.dims.end());
      // An empty attribute is one-dimensional, as the file's (null dataspace).
      if (shape.empty() || (e.size() == 0 && e.quantity->place == Place::attribute))
        shape = {py::ssize_t(e.size())};
      return shape;
    }

    template <typename T>
    py::array_t<T> numbers(const ProductEntry &e)
    {
      py::array_t<T> a(shape_of(e));
      T             *out = a.mutable_data();
      for (std::size_t k = 0; k < e.values.size(); ++k)
        out[k] = static_cast<T>(e.value(k));
      return a;
    }

    py::array_t<std::complex<double>> complex_numbers(const ProductEntry &e)
    {
      py::array_t<std::complex<double>> a(shape_of(e));
      std::complex<double>             *out = a.mutable_data();
      for (std::size_t k = 0; k < e.size(); ++k)
        out[k] = {e.value(2 * k), e.value(2 * k + 1)};
      return a;
    }

    py::object texts(const ProductEntry &e)
    {
      if (e.quantity->place == Place::attribute)
        return e.dims.empty() ? py::object(py::str(e.texts.at(0))) : py::object(py::cast(e.texts));
      return py::module_::import("numpy").attr("array")(e.texts, "object");
    }

    py::object array(const ProductEntry &e)
    {
      const Quantity &row = *e.quantity;
      py::object      a   = row.storage == Storage::integer ? py::object(numbers<int>(e)) :
                                                              py::object(numbers<double>(e));
      return row.python_dtype ? a.attr("astype")(row.python_dtype) : a;
    }
  } // namespace

  py::object value(const ProductEntry &e)
  {
    const Quantity &row = *e.quantity;
    if (row.storage == Storage::text)
      return texts(e);
    if (row.storage == Storage::complex)
      return complex_numbers(e);
    if (row.place == Place::attribute && e.dims.empty())
      return row.storage == Storage::integer ? py::object(py::int_(int(e.values.at(0)))) :
                                               py::object(py::float_(e.value(0)));
    return array(e);
  }

  py::dict entries(const ProductGroup &group, const Place place)
  {
    py::dict d;
    for (const ProductEntry &e : place == Place::attribute ? group.attributes : group.datasets)
      if (e.quantity->python)
        d[e.quantity->python] = value(e);
    return d;
  }

  py::dict flattened(const Product &product)
  {
    py::dict d;
    for (const ProductGroup &g : product.groups)
      for (const Place place : {Place::attribute, Place::dataset})
        for (const auto &[key, item] : entries(g, place))
          d[key] = item;
    return d;
  }

  py::dict by_name(const ProductGroup &group, const Quantity &names, const Quantity &values)
  {
    const ProductEntry &n = group.at(names), &v = group.at(values);
    py::dict            d;
    for (std::size_t j = 0; j < n.texts.size(); ++j)
      d[py::str(n.texts[j])] = v.value(j);
    return d;
  }

  py::dict columns(const ProductGroup &group)
  {
    py::dict d;
    for (const ProductEntry &e : group.datasets)
      if (e.quantity->python)
        d[e.quantity->python] = py::make_tuple(e.quantity->unit.name, e.description());
    return d;
  }

} // namespace cdea::python
