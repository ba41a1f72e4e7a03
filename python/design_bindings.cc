// The design commands in the Python module: cdea.optimize(prm) and
// cdea.fit(prm, data) run `cdea optimize` and `cdea fit` in-process (on this
// process alone, progress off unless asked) and return their results with
// the names and units of <Base name>_optimum.h5 and <Base name>_fit.h5;
// nothing is written unless .write(path) is called. Bad input raises
// ValueError with the command line's message. Documented in doc/python.md.

#include <cdea/base/format.h>
#include <cdea/design/fit.h>
#include <cdea/design/material_test_data.h>
#include <cdea/design/optimize.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/input/validation.h>
#include <cdea/model/quantities_fit.h>
#include <cdea/output/product_file.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "product_convert.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace cdea;

void require_directory_of(const std::string &file); // python/cdea_module.cc
py::object fit_material_data(const py::module_ &m, const py::object &prm, const py::object &files,
                              const py::object &predict, const py::object &models,
                              const py::object &overrides,
                              bool progress); // python/material_fit_bindings.cc

namespace
{
  /// The validated parameters of @p prm with @p overrides, through the
  /// module's own cdea.parameters() (the one reading of prm and overrides,
  /// python/cdea_module.cc); @p text: every parameter as the files store them.
  Parameters design_parameters(const py::module_ &m, const py::object &prm,
                               const py::object &overrides, std::string &text)
  {
    text = m.attr("parameters")(prm, overrides).cast<std::string>();
    std::string again;
    return read_parameters(ParameterInput::text(text), &again);
  }

  /// An in-process `cdea optimize`: its product.
  struct Optimization
  {
    std::string          parameter_text;
    Scene                base;
    OptimizationSettings settings;
    OptimizationRun      run;
    Product              product;
    std::string          results_path; ///< <Directory>/<Base name>_optimum.h5

    const StartResult &best() const { return run.starts.at(run.best); }
  };

  /// An in-process `cdea fit`: its product.
  struct Calibration
  {
    FitSettings settings;
    FitResult   result;
    Product     product;
    std::string results_path; ///< <Directory>/<Base name>_fit.h5
  };

  std::string path_of(const py::object &path)
  {
    return py::module_::import("os").attr("fspath")(path).cast<std::string>();
  }

  /// write(path=None) of the results, to @p path or else @p default_path
  /// (<Directory>/<Base name>_optimum.h5, _fit.h5), as RunResult.write():
  /// the folder of @p path is made if the one above it exists, the default's
  /// whole; a file that cannot be
  /// written raises OSError with the writer's message. Returns the path.
  std::string write_to(const py::object &path, const std::string &default_path,
                       const std::function<void(const std::string &)> &writer)
  {
    const std::string file = path.is_none() ? default_path : path_of(path);
    std::error_code   error;
    if (!path.is_none())
      require_directory_of(file);
    else if (const auto folder = std::filesystem::path(file).parent_path();
             !folder.empty() && !std::filesystem::create_directories(folder, error) && error)
      {
        PyErr_SetString(PyExc_OSError, ("cannot write '" + file + "': cannot create the folder '" +
                                        folder.string() + "': " + error.message())
                                         .c_str());
        throw py::error_already_set();
      }
    try
      {
        writer(file);
      }
    catch (const std::exception &e)
      {
        PyErr_SetString(PyExc_OSError, e.what());
        throw py::error_already_set();
      }
    return file;
  }

  /// CSV text (a str with a line break) or a path.
  CalibrationData calibration_data(const py::object &data, const Scene &scene)
  {
    const unsigned int n_rings = scene.n_rings();
    const double       ceiling = voltage_ceiling(scene);
    if (py::isinstance<py::str>(data))
      {
        const std::string s = data.cast<std::string>();
        if (s.find('\n') != std::string::npos)
          {
            std::istringstream in(s);
            return read_calibration_data(in, "data", n_rings, ceiling);
          }
      }
    return read_calibration_data(path_of(data), n_rings, ceiling);
  }
  /// Whether cdea.fit()'s data are material tests: a list of files or
  /// texts, or one whose header names a test's stretch (or force_N).
  bool is_material_data(const py::object &data)
  {
    if (py::isinstance<py::list>(data) || py::isinstance<py::tuple>(data))
      return true;
    if (py::isinstance<py::str>(data))
      if (const std::string s = data.cast<std::string>(); s.find('\n') != std::string::npos)
        {
          std::istringstream in(s);
          return is_material_test(in);
        }
    return is_material_test(path_of(data));
  }

  void bind_optimize(py::module_ &m)
  {
    py::class_<Optimization>(m, "OptimizeResult",
                             "The result of cdea.optimize(): the quantities of "
                             "<Base name>_optimum.h5 (doc/optimization.md)")
      .def_property_readonly(
        "attributes",
        [](const Optimization &o) { return python::entries(o.product.root(), Place::attribute); },
        "the root attributes of the optimum file (dict)")
      .def_property_readonly(
        "history",
        [](const Optimization &o) {
          return python::entries(o.product.at("/history"), Place::dataset);
        },
        "/history: every evaluation of every start (dict of numpy arrays)")
      .def_property_readonly("converged",
                             [](const Optimization &o) { return o.best().converged; })
      .def(
        "write",
        [](const Optimization &o, const py::object &path) {
          return write_to(path, o.results_path,
                          [&](const std::string &file) { write_product_file(o.product, file); });
        },
        py::arg("path") = py::none(),
        "Write the optimum file (HDF5) to path (default: results_path, the command's "
        "<Directory>/<Base name>_optimum.h5); returns the path")
      .def_readonly("results_path", &Optimization::results_path,
                    "where `cdea optimize` writes its file, <Directory>/<Base name>_optimum.h5")
      .def("__repr__", [](const Optimization &o) {
        const StartResult &b = o.best();
        return "<cdea.OptimizeResult " +
               std::string(b.converged ? "converged" : "NOT converged") + ", ring edges " +
               format_fixed_list(b.best.edges, 4) + ", voltages " +
               format_fixed_list(b.best.voltages, 4, units::kV.multiply) + " kV>";
      });

    m.def(
      "optimize",
      [m](const py::object &prm, const py::object &overrides, const bool progress) {
        Optimization     o;
        const Parameters p  = design_parameters(m, prm, overrides, o.parameter_text);
        o.base              = p.scene();
        o.settings          = optimization_settings(p, o.base);
        const auto on_start = [&](const StartResult &r) {
          if (progress)
            std::cout << "start " << r.start << ": " << r.status << std::endl;
        };
        o.run     = optimize_layouts(p, o.base, o.settings, {}, on_start);
        o.product = optimum_product(o.run, o.settings, o.base, o.parameter_text);
        o.results_path = p.results_path("_optimum");
        return o;
      },
      py::arg("prm"), py::arg("overrides") = py::none(), py::arg("progress") = false,
      "`cdea optimize` in-process, on this process alone; prm: a path or prm text, overrides: "
      "{'Subsection/Entry': value}. Writes nothing.");
  }

  void bind_fit_result(py::module_ &m)
  {
    py::class_<Calibration>(m, "FitResult",
                            "The result of cdea.fit(): the quantities of <Base name>_fit.h5 "
                            "(doc/optimization.md)")
      .def_property_readonly(
        "attributes",
        [](const Calibration &c) { return python::entries(c.product.root(), Place::attribute); },
        "the root attributes of the fit file (dict)")
      .def_property_readonly(
        "values",
        [](const Calibration &c) {
          return python::by_name(c.product.root(), fit_quantity::free_parameters,
                                 fit_quantity::fitted_values);
        },
        "fitted values by parameter name (SI units)")
      .def_property_readonly(
        "standard_errors",
        [](const Calibration &c) {
          return python::by_name(c.product.root(), fit_quantity::free_parameters,
                                 fit_quantity::standard_errors);
        },
        "standard errors by parameter name (SI units; NaN if not identifiable)")
      .def_property_readonly(
        "correlation",
        [](const Calibration &c) {
          return python::value(c.product.root().at(fit_quantity::correlation));
        },
        "correlation matrix (order of attributes['free_parameters'])")
      .def_property_readonly(
        "data",
        [](const Calibration &c) { return python::entries(c.product.at("/data"), Place::dataset); },
        "/data: voltages, measured, fitted, residual, weight (dict)")
      .def_property_readonly(
        "curve",
        [](const Calibration &c) {
          return python::entries(c.product.at("/curve"), Place::dataset);
        },
        "/curve: the model along the data (dict)")
      .def_property_readonly("warnings", [](const Calibration &c) { return c.result.warnings; })
      .def_property_readonly("converged", [](const Calibration &c) { return c.result.converged; })
      .def(
        "write",
        [](const Calibration &c, const py::object &path) {
          return write_to(path, c.results_path,
                          [&](const std::string &file) { write_product_file(c.product, file); });
        },
        py::arg("path") = py::none(),
        "Write the fit file (HDF5) to path (default: results_path, the command's "
        "<Directory>/<Base name>_fit.h5); returns the path")
      .def_readonly("results_path", &Calibration::results_path,
                    "where `cdea fit` writes its file, <Directory>/<Base name>_fit.h5")
      .def("__repr__", [](const Calibration &c) {
        std::string s = "<cdea.FitResult " +
                        std::string(c.result.converged ? "converged" : "NOT converged");
        for (std::size_t j = 0; j < c.settings.free.size(); ++j)
          s += ", " + c.settings.free[j].name() + " " + format_number(c.result.values[j], 8);
        return s + ">";
      });
  }

  void bind_fit(py::module_ &m)
  {
    bind_fit_result(m);
    m.def(
      "fit",
      [m](const py::object &prm, const py::object &data, const py::object &overrides,
          const bool progress, const py::object &predict, const py::object &models) -> py::object {
        if (is_material_data(data) || !predict.is_none() || !models.is_none())
          return fit_material_data(m, prm, data, predict, models, overrides, progress);
        Calibration           c;
        std::string           parameter_text;
        const Parameters      p    = design_parameters(m, prm, overrides, parameter_text);
        const Scene           base = p.scene();
        c.settings                 = fit_settings(p);
        const CalibrationData points = calibration_data(data, base);
        require_enough_points(points, c.settings, "data");
        const Calibrated run =
          calibrate(p, base, points, c.settings,
                    [&](unsigned int k, double cost, const std::vector<double> &) {
                      if (progress)
                        std::cout << "iteration " << k << ": cost " << cost << " mm^2"
                                  << std::endl;
                    });
        c.result  = run.result;
        c.product      = fit_product(parameter_text, points, c.settings, run);
        c.results_path = p.results_path("_fit");
        return py::cast(std::move(c));
      },
      py::arg("prm"), py::arg("data"), py::arg("overrides") = py::none(),
      py::arg("progress") = false, py::arg("predict") = py::none(), py::arg("models") = py::none(),
      "`cdea fit` in-process; prm: a path or prm text, data: a CSV path or CSV text (a str "
      "with a line break), overrides: {'Subsection/Entry': value}. Material tests (a list of "
      "files, or one file whose header names a test's stretch): fitted jointly, predict: files "
      "evaluated at the fitted values, models: candidate models ['elastic 0', 'elastic 1'] "
      "compared (Calibration/Candidate models); returns a MaterialFitResult. Writes nothing.");
  }
} // namespace

void bind_design(py::module_ &m)
{
  bind_optimize(m);
  bind_fit(m);
}
