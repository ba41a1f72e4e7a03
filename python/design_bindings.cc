// The design commands in the Python module: cdea.optimize(prm) and
// cdea.fit(prm, data) run `cdea optimize` and `cdea fit` in-process (on this
// process alone, progress off unless asked) and return their results with
// the names and units of <Base name>_optimum.h5 and <Base name>_fit.h5;
// nothing is written unless .write(path) is called. Bad input raises
// ValueError with the command line's message. Documented in doc/python.md.

#include <cdea/base/format.h>
#include <cdea/design/fit.h>
#include <cdea/design/optimize.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/input/validation.h>
#include <cdea/model/output_fields.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace cdea;

void require_directory_of(const std::string &file); // python/cdea_module.cc

namespace
{
  py::array_t<double> array(const std::vector<double> &values, const py::ssize_t rows,
                            const py::ssize_t columns = 0)
  {
    py::array_t<double> a(columns > 0 ? std::vector<py::ssize_t>{rows, columns} :
                                        std::vector<py::ssize_t>{rows});
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
  }

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

  /// An in-process `cdea optimize`.
  struct Optimization
  {
    std::string          parameter_text;
    Scene                base;
    OptimizationSettings settings;
    OptimizationRun      run;

    const StartResult &best() const { return run.starts.at(run.best); }

    /// The root attributes of <Base name>_optimum.h5.
    py::dict attributes() const
    {
      const StartResult      &b = best();
      const LayoutEvaluation &e = b.at_best;
      const bool has_points     = e.ok && e.points.s2.size() > 0;
      unsigned int evaluations = 0, solves = 0;
      for (const auto &r : run.starts)
        {
          evaluations += r.evaluations;
          solves += r.solves;
        }
      std::string active;
      for (const auto &a : b.active)
        active += (active.empty() ? "" : "; ") + a;
      py::dict d;
      d["objective"]            = to_string(settings.objective);
      d["algorithm"]            = to_string(settings.algorithm);
      d["ring_edges_over_a"]    = array(b.best.edges, py::ssize_t(b.best.edges.size()));
      d["voltages_kV"]          = array(scaled(b.best.voltages, 1e-3), py::ssize_t(b.best.voltages.size()));
      d["displacement_mm"]      = e.displacement * 1e3;
      d["stroke_mm"]            = e.stroke * 1e3;
      d["volume_change_mm3"]    = e.volume_change * 1e9;
      d["min_s2_kPa"]           = has_points ? e.points.s2.minCoeff() * 1e-3 : NAN;
      d["max_field_MV_per_m"]   = has_points ? e.points.field.maxCoeff() * 1e-6 : NAN;
      d["active_constraints"]   = active;
      d["iterations"]           = int(evaluations);
      d["solves"]               = int(solves);
      d["converged"]            = int(b.converged);
      d["status"]               = b.status;
      d["first_order_residual"] = b.optimality;
      d["best_start"]           = int(b.start);
      d["starts"]               = int(run.starts.size());
      d["min_tangent_eigenvalue_N_per_m"] = e.min_eigenvalue;
      return d;
    }

    /// /history of the file: every evaluation of every start.
    py::dict history() const
    {
      std::vector<double> start, evaluation, objective, worst, values;
      for (const auto &r : run.starts)
        for (const auto &h : r.history)
          {
            start.push_back(h.start);
            evaluation.push_back(h.evaluation);
            objective.push_back(h.objective);
            worst.push_back(h.worst_constraint);
            values.insert(values.end(), h.free_values.begin(), h.free_values.end());
          }
      const auto n = py::ssize_t(objective.size());
      py::dict   d;
      d["start"]            = array(start, n).attr("astype")("int64");
      d["evaluation"]       = array(evaluation, n).attr("astype")("int64");
      d["objective"]        = array(objective, n);
      d["worst_constraint"] = array(worst, n);
      d["free_values"] = array(values, n, py::ssize_t(settings.free_parameters().size()));
      return d;
    }

    void write(const std::string &path) const
    {
      write_optimum_file(path, run, settings, base, parameter_text);
    }
  };

  /// An in-process `cdea fit`.
  struct Calibration
  {
    std::string                      parameter_text;
    CalibrationData                  data;
    FitSettings                      settings;
    FitResult                        result;
    std::vector<std::vector<double>> curve_kV;
    std::vector<double>              curve_mm;
    unsigned int                     solves = 0;

    py::list names() const
    {
      py::list l;
      for (const auto &p : settings.free)
        l.append(p.name());
      return l;
    }

    /// The root attributes of <Base name>_fit.h5.
    py::dict attributes() const
    {
      std::string warnings;
      for (const auto &x : result.warnings)
        warnings += (warnings.empty() ? "" : "\n") + x;
      const auto K = py::ssize_t(settings.free.size());
      py::dict   d;
      d["free_parameters"]  = names();
      d["initial_values"]   = array(result.initial, K);
      d["fitted_values"]    = array(result.values, K);
      d["standard_errors"]  = array(result.standard_errors, K);
      d["rms_residual_mm"]  = result.rms * 1e3;
      d["condition_number"] = result.condition;
      d["converged"]        = int(result.converged);
      d["status"]           = result.status;
      d["warnings"]         = warnings;
      d["iterations"]       = int(result.iterations);
      d["evaluations"]      = int(result.evaluations);
      d["solves"]           = int(solves);
      return d;
    }

    py::array_t<double> correlation() const
    {
      const std::size_t   K = settings.free.size();
      std::vector<double> c(K * K, NAN);
      if (result.correlation.size())
        for (std::size_t i = 0; i < K; ++i)
          for (std::size_t j = 0; j < K; ++j)
            c[i * K + j] = result.correlation(i, j);
      return array(c, py::ssize_t(K), py::ssize_t(K));
    }

    /// /data of the file: voltages, measured, fitted, residual, weight.
    py::dict points() const
    {
      const std::size_t   M = data.size(), N = M ? data.voltages[0].size() : 0;
      std::vector<double> volts, measured, fitted, residual;
      for (std::size_t i = 0; i < M; ++i)
        {
          for (const double v : data.voltages[i])
            volts.push_back(v * 1e-3);
          measured.push_back(data.displacement[i] * 1e3);
          fitted.push_back(result.fitted.size() ? result.fitted[i] * 1e3 : NAN);
          residual.push_back(result.residuals.size() ? result.residuals[i] * 1e3 : NAN);
        }
      py::dict d;
      d["voltage_kV"]      = array(volts, py::ssize_t(M), py::ssize_t(N));
      d["displacement_mm"] = array(measured, py::ssize_t(M));
      d["weight"]          = array(data.weight, py::ssize_t(M));
      d["fitted_mm"]       = array(fitted, py::ssize_t(M));
      d["residual_mm"]     = array(residual, py::ssize_t(M));
      return d;
    }

    py::dict curve() const
    {
      std::vector<double> volts;
      for (const auto &v : curve_kV)
        volts.insert(volts.end(), v.begin(), v.end());
      const auto n = py::ssize_t(curve_mm.size());
      py::dict   d;
      d["voltage_kV"]      = array(volts, n, n ? py::ssize_t(curve_kV[0].size()) : 0);
      d["displacement_mm"] = array(curve_mm, n);
      return d;
    }

    void write(const std::string &path) const
    {
      write_fit_file(path, parameter_text, data, settings, result, curve_kV, curve_mm, solves);
    }
  };

  std::string path_of(const py::object &path)
  {
    return py::module_::import("os").attr("fspath")(path).cast<std::string>();
  }

  /// write(path) of the results: the folder must exist; a file that cannot
  /// be written raises OSError with the writer's message.
  void write_to(const py::object &path, const std::function<void(const std::string &)> &writer)
  {
    const std::string file = path_of(path);
    require_directory_of(file);
    try
      {
        writer(file);
      }
    catch (const std::exception &e)
      {
        PyErr_SetString(PyExc_OSError, e.what());
        throw py::error_already_set();
      }
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
  void bind_optimize(py::module_ &m)
  {
    py::class_<Optimization>(m, "OptimizeResult",
                             "The result of cdea.optimize(): the quantities of "
                             "<Base name>_optimum.h5 (doc/optimization.md)")
      .def_property_readonly("attributes", &Optimization::attributes,
                             "the root attributes of the optimum file (dict)")
      .def_property_readonly("history", &Optimization::history,
                             "/history: every evaluation of every start (dict of numpy arrays)")
      .def_property_readonly("converged",
                             [](const Optimization &o) { return o.best().converged; })
      .def(
        "write",
        [](const Optimization &o, const py::object &path) {
          write_to(path, [&](const std::string &file) { o.write(file); });
        },
        py::arg("path"), "Write the optimum file (HDF5) to path")
      .def("__repr__", [](const Optimization &o) {
        const StartResult &b = o.best();
        return "<cdea.OptimizeResult " +
               std::string(b.converged ? "converged" : "NOT converged") + ", ring edges " +
               format_fixed_list(b.best.edges, 4) + ", voltages " +
               format_fixed_list(b.best.voltages, 4, 1e-3) + " kV>";
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
        o.run = optimize_layouts(p, o.base, o.settings, {}, on_start);
        return o;
      },
      py::arg("prm"), py::arg("overrides") = py::none(), py::arg("progress") = false,
      "`cdea optimize` in-process, on this process alone; prm: a path or prm text, overrides: "
      "{'Subsection/Entry': value}. Writes nothing.");
  }

  /// A dict parameter name -> value of each free parameter.
  py::dict by_name(const Calibration &c, const std::vector<double> &values)
  {
    py::dict d;
    for (std::size_t j = 0; j < c.settings.free.size(); ++j)
      d[py::str(c.settings.free[j].name())] = values[j];
    return d;
  }

  void bind_fit_result(py::module_ &m)
  {
    py::class_<Calibration>(m, "FitResult",
                            "The result of cdea.fit(): the quantities of <Base name>_fit.h5 "
                            "(doc/optimization.md)")
      .def_property_readonly("attributes", &Calibration::attributes,
                             "the root attributes of the fit file (dict)")
      .def_property_readonly(
        "values", [](const Calibration &c) { return by_name(c, c.result.values); },
        "fitted values by parameter name (SI units)")
      .def_property_readonly(
        "standard_errors", [](const Calibration &c) { return by_name(c, c.result.standard_errors); },
        "standard errors by parameter name (SI units; NaN if not identifiable)")
      .def_property_readonly("correlation", &Calibration::correlation,
                             "correlation matrix (order of attributes['free_parameters'])")
      .def_property_readonly("data", &Calibration::points,
                             "/data: voltages, measured, fitted, residual, weight (dict)")
      .def_property_readonly("curve", &Calibration::curve,
                             "/curve: the model along the data (dict)")
      .def_property_readonly("warnings", [](const Calibration &c) { return c.result.warnings; })
      .def_property_readonly("converged", [](const Calibration &c) { return c.result.converged; })
      .def(
        "write",
        [](const Calibration &c, const py::object &path) {
          write_to(path, [&](const std::string &file) { c.write(file); });
        },
        py::arg("path"), "Write the fit file (HDF5) to path")
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
          const bool progress) {
        Calibration      c;
        const Parameters p    = design_parameters(m, prm, overrides, c.parameter_text);
        const Scene      base = p.scene();
        c.settings            = fit_settings(p);
        c.data                = calibration_data(data, base);
        require_enough_points(c.data, c.settings, "data");
        const Calibrated run =
          calibrate(p, base, c.data, c.settings,
                    [&](unsigned int k, double cost, const std::vector<double> &) {
                      if (progress)
                        std::cout << "iteration " << k << ": cost " << cost << " mm^2"
                                  << std::endl;
                    });
        c.result   = run.result;
        c.curve_kV = run.curve_kV;
        c.curve_mm = run.curve_mm;
        c.solves   = run.solves;
        return c;
      },
      py::arg("prm"), py::arg("data"), py::arg("overrides") = py::none(),
      py::arg("progress") = false,
      "`cdea fit` in-process; prm: a path or prm text, data: a CSV path or CSV text (a str "
      "with a line break), overrides: {'Subsection/Entry': value}. Writes nothing.");
  }
} // namespace

void bind_design(py::module_ &m)
{
  bind_optimize(m);
  bind_fit(m);
}
