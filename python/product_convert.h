#pragma once
// The one converter from products (model/product.h) to Python: each value
// by its row of the table of quantities, under the row's Python key, in the
// row's unit. Attributes become numbers (int for whole numbers), str, a list
// of str (a list of texts) or numpy arrays; datasets numpy arrays of their
// shape (float64, int32, complex128, object for texts). Rows without a
// Python key stay out.

#include <cdea/model/product.h>

#include <pybind11/pybind11.h>


namespace cdea::python
{
  namespace py = pybind11;

  /// The value of @p entry as Python holds it.
  py::object value(const ProductEntry &entry);

  /// The attributes or the datasets of @p group by their Python keys.
  py::dict entries(const ProductGroup &group, Place place);

  /// The attributes and datasets of every group of @p product by their
  /// Python keys (one dict for a whole product, such as a response).
  py::dict flattened(const Product &product);

  /// The values of @p values (one per item of the list @p names) by those
  /// names: a dict {name: value}.
  py::dict by_name(const ProductGroup &group, const Quantity &names, const Quantity &values);

  /// Key -> (unit, description) of the datasets of @p group.
  py::dict columns(const ProductGroup &group);
} // namespace cdea::python
