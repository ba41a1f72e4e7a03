// cdea.fit(prm, [files], predict=[...], models=[...]) on material tests
// (design/material_fit.h, design/model_selection.h) in-process: the joint
// fit, or with candidate models the selection and the recommended model's
// fit, under the names of <Base name>_fit.h5 and _models.h5 (doc/python.md,
// "Fits of material tests"). Writes nothing unless .write() is called.

#include <cdea/base/format.h>
#include <cdea/design/material_fit.h>
#include <cdea/design/model_selection.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/model/quantities_fit.h>
#include <cdea/model/quantities_material_fit.h>
#include <cdea/model/quantities_model_selection.h>
#include <cdea/output/product_file.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "product_convert.h"

#include <iostream>
#include <memory>
#include <sstream>

namespace py = pybind11;
using namespace cdea;

void require_directory_of(const std::string &file); // python/cdea_module.cc

namespace
{
  /// A model selection: its product.
  struct Selection
  {
    Product     product;
    std::string recommended, verdict;
    bool        decided = false;
  };

  /// An in-process material-test fit.
  struct MaterialCalibration
  {
    FitSettings                settings;
    FitResult                  result;
    Product                    product;
    std::shared_ptr<Selection> selection; ///< null without candidate models
  };

  /// The unit of a constant's prm entry: kPa for the moduli (network A's
  /// and the branches', whose law constants are in Pa), the SI unit else.
  const Unit &entry_unit(const SceneParameter &p)
  {
    const std::string pa = " (Pa)";
    if (p.kind == ParameterKind::shear_modulus ||
        (p.kind == ParameterKind::law_constant && p.entry.size() > pa.size() &&
         p.entry.compare(p.entry.size() - pa.size(), pa.size(), pa) == 0))
      return units::kPa;
    return units::one;
  }

  /// The constant's name with the unit of entry_unit(): "shear modulus (kPa)".
  std::string entry_name(const SceneParameter &p)
  {
    std::string name = label(p);
    if (&entry_unit(p) != &units::kPa)
      return name;
    const auto open = name.rfind(" (Pa)");
    return (open == std::string::npos ? name : name.substr(0, open)) + " (kPa)";
  }

  /// A CSV path, or CSV text (a str with a line break) named "data N".
  MaterialTestData material_test(const py::handle &item, const std::string &name,
                                 const TestSpecimen &specimen, double &weight)
  {
    if (py::isinstance<py::str>(item))
      if (const std::string s = item.cast<std::string>(); s.find('\n') != std::string::npos)
        {
          std::istringstream w(s), in(s);
          weight = material_test_weight(w, name);
          return read_material_test(in, name, specimen);
        }
    const std::string file = py::module_::import("os").attr("fspath")(item).cast<std::string>();
    weight                 = material_test_weight(file);
    return read_material_test(file, specimen);
  }

  std::vector<MaterialTestData> material_tests(const py::object &files, const std::string &prefix,
                                               const TestSpecimen &specimen,
                                               std::vector<double> &weights)
  {
    std::vector<MaterialTestData> out;
    if (files.is_none())
      return out;
    const py::list list = py::isinstance<py::str>(files) || !py::hasattr(files, "__iter__") ?
                            py::list(py::make_tuple(files)) :
                            py::list(files);
    for (std::size_t k = 0; k < list.size(); ++k)
      {
        double w = 1.;
        out.push_back(material_test(list[k], prefix + std::to_string(k + 1), specimen, w));
        weights.push_back(w);
      }
    return out;
  }

  /// @p v (SI, one per constant) in the constants' entry units, by name.
  py::dict in_entry_units(const std::vector<SceneParameter> &free, const std::vector<double> &v)
  {
    py::dict d;
    for (std::size_t j = 0; j < free.size() && j < v.size(); ++j)
      d[py::str(entry_name(free[j]))] = entry_unit(free[j]).from_si(v[j]);
    return d;
  }

  /// The predicted files' samples: {file: {time_s, stretch, measured, model}}.
  py::dict predictions(const Product &product)
  {
    const py::dict tests = python::entries(product.at("/tests"), Place::dataset);
    const py::dict samples = python::entries(product.at("/samples"), Place::dataset);
    const py::list files   = tests["file"].attr("tolist")();
    const py::list fitted  = tests["fitted"].attr("tolist")();
    py::dict       out;
    for (std::size_t k = 0; k < files.size(); ++k)
      if (fitted[k].cast<int>() == 0)
        {
          const py::object mask = samples["test"].attr("__eq__")(py::int_(k));
          py::dict         one;
          for (const char *key : {"time_s", "stretch", "measured_stress_kPa", "model_stress_kPa",
                                  "residual_kPa"})
            one[key] = samples[key].attr("__getitem__")(mask);
          out[files[k]] = one;
        }
    return out;
  }

  void write_product(const Product &product, const py::object &path)
  {
    const std::string file = py::module_::import("os").attr("fspath")(path).cast<std::string>();
    require_directory_of(file);
    try
      {
        write_product_file(product, file);
      }
    catch (const std::exception &e)
      {
        PyErr_SetString(PyExc_OSError, e.what());
        throw py::error_already_set();
      }
  }

  void bind_selection(py::module_ &m)
  {
    namespace q = model_selection_quantity;
    py::class_<Selection, std::shared_ptr<Selection>>(
      m, "ModelSelection",
      "The model selection of cdea.fit(..., models=[...]): the quantities of "
      "<Base name>_models.h5 (doc/materials.md, \"Choosing a model\")")
      .def_property_readonly(
        "table", [](const Selection &s) { return python::entries(s.product.at("/models"), Place::dataset); },
        "/models: one row per candidate (dict of numpy arrays)")
      .def_property_readonly(
        "constants",
        [](const Selection &s) { return python::entries(s.product.at("/constants"), Place::dataset); },
        "/constants: every model's constants and standard errors, SI (dict of numpy arrays)")
      .def_property_readonly(
        "attributes", [](const Selection &s) { return python::entries(s.product.root(), Place::attribute); })
      .def_readonly("recommended", &Selection::recommended)
      .def_readonly("decided", &Selection::decided)
      .def_readonly("verdict", &Selection::verdict)
      .def("write", [](const Selection &s, const py::object &path) { write_product(s.product, path); },
           py::arg("path"), "Write the model-selection file (HDF5) to path")
      .def("__repr__", [](const Selection &s) {
        return "<cdea.ModelSelection " +
               std::to_string(s.product.at("/models").at(q::model).size()) + " models, recommended " +
               s.recommended + (s.decided ? "" : " (the data cannot decide)") + ">";
      });
  }
} // namespace

/// cdea.fit() on material tests (python/design_bindings.cc hands them here).
py::object fit_material_data(const py::module_ &m, const py::object &prm, const py::object &files,
                              const py::object &predict, const py::object &models,
                              const py::object &overrides, const bool progress)
{
  py::dict changes = overrides.is_none() ? py::dict() : py::dict(overrides);
  if (!models.is_none())
    {
      std::string list;
      for (const py::handle &item : models)
        list += (list.empty() ? "" : ", ") + item.cast<std::string>();
      changes["Calibration/Candidate models"] = list;
    }
  const std::string parameter_text = m.attr("parameters")(prm, changes).cast<std::string>();
  std::string       again;
  const ParameterInput input = ParameterInput::text(parameter_text);
  const Parameters     p     = read_parameters(input, &again);
  MaterialFitSettings  settings;
  std::vector<double>  predict_weights;
  const std::vector<MaterialTestData> fitted = material_tests(files, "data ", test_specimen(p),
                                                              settings.test_weights);
  const std::vector<MaterialTestData> predicted =
    material_tests(predict, "predict ", test_specimen(p), predict_weights);
  if (fitted.empty())
    throw InputError("cdea.fit(): no material test to fit");
  MaterialCalibration c;
  Scene               base = p.scene();
  std::vector<CandidateSetup> setups;
  for (const CandidateModel &candidate : candidate_models(p.calibration.candidate_models_text))
    setups.push_back(candidate_setup(input, candidate));
  MaterialFitResult r;
  if (setups.empty())
    {
      settings.fit = free_parameter_settings(p);
      r            = fit_material_tests(base, fitted, settings);
    }
  else
    {
      ModelSelection s = select_model(
        setups, fitted, settings.test_weights, settings,
        [&](const std::string &model, const std::string &left_out, const FitResult &f) {
          if (progress)
            std::cout << model << (left_out.empty() ? "" : " without " + left_out) << ": rms "
                      << f.rms << " Pa" << std::endl;
        });
      const ModelAssessment &best = s.models[s.recommended];
      c.selection = std::make_shared<Selection>(
        Selection{model_selection_product(s, fitted), best.setup.candidate.name(), s.verdict, s.decided});
      base         = best.setup.base;
      settings.fit = best.setup.fit;
      r            = best.fit;
    }
  if (!r.fit.started)
    throw InputError(r.fit.status);
  std::vector<std::string> warnings = r.fit.warnings;
  const auto outcomes = material_test_outcomes(base, settings.fit.free, r, fitted,
                                               settings.test_weights, predicted, warnings);
  c.settings        = settings.fit;
  c.result          = r.fit;
  c.result.warnings = warnings;
  c.product         = material_fit_product(parameter_text, settings.fit, r, outcomes);
  return py::cast(std::move(c));
}

void bind_material_fit(py::module_ &m)
{
  bind_selection(m);
  py::class_<MaterialCalibration>(m, "MaterialFitResult",
                                  "The result of cdea.fit() on material tests: the quantities "
                                  "of <Base name>_fit.h5 (doc/materials.md)")
    .def_property_readonly(
      "values", [](const MaterialCalibration &c) { return in_entry_units(c.settings.free, c.result.values); },
      "fitted constants by name, in their prm entries' units (moduli in kPa)")
    .def_property_readonly(
      "standard_errors",
      [](const MaterialCalibration &c) { return in_entry_units(c.settings.free, c.result.standard_errors); },
      "standard errors by name, in the same units (NaN: not identifiable)")
    .def_property_readonly(
      "covariance",
      [](const MaterialCalibration &c) {
        const std::size_t K = c.settings.free.size();
        py::array_t<double> a({K, K});
        auto                v = a.mutable_unchecked<2>();
        for (std::size_t i = 0; i < K; ++i)
          for (std::size_t j = 0; j < K; ++j)
            v(i, j) = c.result.covariance.rows() == Eigen::Index(K) ?
                        entry_unit(c.settings.free[i]).from_si(entry_unit(c.settings.free[j]).from_si(
                          c.result.covariance(Eigen::Index(i), Eigen::Index(j)))) :
                        NAN;
        return a;
      },
      "covariance of the constants in the order of values, in their units")
    .def_property_readonly(
      "correlation",
      [](const MaterialCalibration &c) { return python::value(c.product.root().at(fit_quantity::correlation)); })
    .def_property_readonly(
      "tests", [](const MaterialCalibration &c) { return python::entries(c.product.at("/tests"), Place::dataset); },
      "/tests: per file (fitted, then predicted) kind, weight, samples, rms_kPa, relative_rms")
    .def_property_readonly(
      "samples",
      [](const MaterialCalibration &c) { return python::entries(c.product.at("/samples"), Place::dataset); },
      "/samples: every sample of every file, measured and modelled")
    .def_property_readonly("predictions", [](const MaterialCalibration &c) { return predictions(c.product); },
                           "the predicted files' samples by file")
    .def_property_readonly(
      "attributes", [](const MaterialCalibration &c) { return python::entries(c.product.root(), Place::attribute); })
    .def_readonly("models", &MaterialCalibration::selection,
                  "the model selection (cdea.ModelSelection), None without models")
    .def_property_readonly("warnings", [](const MaterialCalibration &c) { return c.result.warnings; })
    .def_property_readonly("converged", [](const MaterialCalibration &c) { return c.result.converged; })
    .def("write", [](const MaterialCalibration &c, const py::object &path) { write_product(c.product, path); },
         py::arg("path"), "Write the fit file (HDF5) to path")
    .def("__repr__", [](const MaterialCalibration &c) {
      std::string s = "<cdea.MaterialFitResult " +
                      std::string(c.result.converged ? "converged" : "NOT converged");
      if (c.selection)
        s += ", model " + c.selection->recommended;
      for (std::size_t j = 0; j < c.settings.free.size(); ++j)
        s += ", " + entry_name(c.settings.free[j]) + " " +
             format_number(entry_unit(c.settings.free[j]).from_si(c.result.values[j]), 6);
      return s + ">";
    });
}
