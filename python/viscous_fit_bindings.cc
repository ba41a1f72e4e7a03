// cdea.fit_viscoelastic(prm, data): `cdea fit` of a DMA table or a creep curve
// (design/viscous_fit.h) in-process, its results under the names and units of
// <Base name>_fit.h5 (doc/materials.md, "Fits").

#include <cdea/base/format.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/validation.h>
#include <cdea/model/quantities_fit.h>
#include <cdea/output/product_file.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "product_convert.h"

#include <cmath>
#include <iostream>
#include <sstream>

namespace py = pybind11;
using namespace cdea;

namespace
{
  /// An in-process DMA or creep fit.
  struct ViscousCalibration
  {
    FitDataKind kind = FitDataKind::dma;
    std::string parameter_text;
    FitSettings settings;
    DmaData     dma;
    CreepData   creep;
    FitResult   result;

    /// The fit's product (model/quantities_fit.h), once fitted.
    Product product;
  };

  /// CSV text (a str with a line break) or a path, read as @p kind.
  void read_data(const py::object &data, const Parameters &p, ViscousCalibration &c)
  {
    std::string text, name = "data";
    if (py::isinstance<py::str>(data) && data.cast<std::string>().find('\n') != std::string::npos)
      text = data.cast<std::string>();
    else
      {
        name = py::module_::import("os").attr("fspath")(data).cast<std::string>();
        c.kind = fit_data_kind(name);
      }
    std::istringstream in(text);
    if (!text.empty())
      c.kind = fit_data_kind(in), in.clear(), in.seekg(0);
    if (c.kind == FitDataKind::displacement_voltage)
      throw InputError(name + ": no column frequency_Hz or time_s (displacement-voltage points "
                              "are cdea.fit()'s)");
    c.settings = viscous_fit_settings(p, c.kind);
    const Scene scene = p.scene();
    if (c.kind == FitDataKind::dma)
      c.dma = text.empty() ? read_dma_data(name) : read_dma_data(in, name);
    else
      {
        c.creep = text.empty() ? read_creep_data(name, scene.n_rings(), voltage_ceiling(scene)) :
                                 read_creep_data(in, name, scene.n_rings(), voltage_ceiling(scene));
        require_waveform_match(p, c.creep, name);
      }
  }
} // namespace

void bind_viscous_fit(py::module_ &m)
{
  py::class_<ViscousCalibration>(m, "ViscousFitResult",
                                 "The result of cdea.fit_viscoelastic(): the quantities of "
                                 "<Base name>_fit.h5 (doc/materials.md, \"Fits\")")
    .def_property_readonly("kind", [](const ViscousCalibration &c) {
      return c.kind == FitDataKind::dma ? "dma" : "creep";
    })
    .def_property_readonly("values",
                           [](const ViscousCalibration &c) {
                             return python::by_name(c.product.root(), fit_quantity::free_parameters,
                                                    fit_quantity::fitted_values);
                           },
                           "fitted values by parameter name (SI units)")
    .def_property_readonly("standard_errors",
                           [](const ViscousCalibration &c) {
                             return python::by_name(c.product.root(), fit_quantity::free_parameters,
                                                    fit_quantity::standard_errors);
                           },
                           "standard errors by parameter name (SI units)")
    .def_property_readonly("correlation",
                           [](const ViscousCalibration &c) {
                             return python::value(c.product.root().at(fit_quantity::correlation));
                           })
    .def_property_readonly(
      "data",
      [](const ViscousCalibration &c) {
        return python::entries(c.product.at("/data"), Place::dataset);
      },
      "/data of the fit file (dict)")
    .def_property_readonly("rms", [](const ViscousCalibration &c) { return c.result.rms; },
                           "weighted rms residual (SI: Pa for DMA, m for creep)")
    .def_property_readonly("warnings", [](const ViscousCalibration &c) { return c.result.warnings; })
    .def_property_readonly("converged", [](const ViscousCalibration &c) { return c.result.converged; })
    .def("write",
         [](const ViscousCalibration &c, const std::string &path) {
           write_product_file(c.product, path);
         },
         py::arg("path"), "Write the fit file (HDF5) to path")
    .def("__repr__", [](const ViscousCalibration &c) {
      std::string s = std::string("<cdea.ViscousFitResult ") +
                      (c.kind == FitDataKind::dma ? "dma" : "creep") +
                      (c.result.converged ? ", converged" : ", NOT converged");
      for (std::size_t j = 0; j < c.settings.free.size(); ++j)
        s += ", " + c.settings.free[j].name() + " " + format_number(c.result.values[j], 8);
      return s + ">";
    });
  m.def(
    "fit_viscoelastic",
    [m](const py::object &prm, const py::object &data, const py::object &overrides,
        const bool progress) {
      ViscousCalibration c;
      c.parameter_text = m.attr("parameters")(prm, overrides).cast<std::string>();
      std::string      again;
      const Parameters p = read_parameters(ParameterInput::text(c.parameter_text), &again);
      read_data(data, p, c);
      const auto report = [&](unsigned int k, double cost, const std::vector<double> &) {
        if (progress)
          std::cout << "iteration " << k << ": cost " << cost << std::endl;
      };
      c.result = c.kind == FitDataKind::dma ? fit_dma(p.scene(), c.dma, c.settings, report) :
                                              fit_creep(p, c.creep, c.settings, report);
      if (!c.result.started)
        throw InputError(c.result.status);
      c.product = c.kind == FitDataKind::dma ?
                    dma_fit_product(c.parameter_text, c.dma, c.settings, c.result) :
                    creep_fit_product(c.parameter_text, c.creep, c.settings, c.result);
      return c;
    },
    py::arg("prm"), py::arg("data"), py::arg("overrides") = py::none(),
    py::arg("progress") = false,
    "`cdea fit` of a DMA table (header frequency_Hz, storage_kPa, loss_kPa) or a creep curve "
    "(time_s, V1_kV.., displacement_mm) in-process; prm: a path or prm text, data: a CSV path "
    "or CSV text, overrides: {'Subsection/Entry': value}. Writes nothing.");
}
