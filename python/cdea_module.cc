// The Python module `cdea` (pybind11): `cdea run` (time runs too), `cdea
// shoot` and `cdea sweep` in-process (analysis/session.h), their results as numpy
// arrays with the names and units of the results files
// (model/output_fields.h for /summary and /steps, the map's product for
// the map), written to HDF5 only when asked. Bad input raises ValueError with the command line's message (a missing file FileNotFoundError). MPI is
// not started (only the Trilinos KLU solver starts it, when it needs it).
// Documented in doc/python.md.

#include <cdea/base/mpi_session.h>
#include <cdea/analysis/frequency_response.h>
#include <cdea/analysis/session.h>
#include <cdea/design/sweep.h>
#include <cdea/output/product_file.h>

#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "product_convert.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace py = pybind11;
using namespace cdea;

/// write(path): the file's folder is created if the folder above it exists
/// (as mkdir does), never a chain of folders (a typo must not build a tree
/// from /); FileNotFoundError otherwise. Only the default path creates
/// Output/Directory whole, as the command line does.
void require_directory_of(const std::string &file)
{
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  std::error_code             error;
  if (parent.empty() || std::filesystem::is_directory(parent, error))
    return;
  const std::filesystem::path above = parent.parent_path();
  if (!std::filesystem::exists(parent, error) &&
      (above.empty() || std::filesystem::is_directory(above, error)))
    {
      if (std::filesystem::create_directory(parent, error) || error.value() == 0)
        return;
      PyErr_SetString(PyExc_OSError, ("cannot write '" + file + "': cannot create the folder '" +
                                      parent.string() + "': " + error.message())
                                       .c_str());
      throw py::error_already_set();
    }
  const std::string message =
    "cannot write '" + file + "': " +
    (std::filesystem::exists(parent, error) ?
       "'" + parent.string() + "' is not a directory" :
       "the directory '" + above.string() + "' does not exist (write(path) creates the " +
         "file's folder only below a folder that exists)");
  PyErr_SetObject(std::filesystem::exists(parent, error) ? PyExc_NotADirectoryError :
                                                           PyExc_FileNotFoundError,
                  py::make_tuple(std::filesystem::exists(parent, error) ? ENOTDIR : ENOENT,
                                 message)
                    .ptr());
  throw py::error_already_set();
}

py::dict response_dict(const FrequencyResponse &r); // python/response_bindings.cc
void bind_frequency_sweep(py::module_ &, const std::string &, // python/response_bindings.cc
                          ParameterInput (*)(const py::object &, const py::object &));

namespace
{
  bool is_sequence(const py::handle value)
  {
    return py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value);
  }

  /// One value of an override as prm text: str as it is, bool as
  /// true/false, a number as Python prints it (numpy scalars and arrays
  /// through tolist()).
  std::string scalar_text(const std::string &key, py::object value)
  {
    if (py::hasattr(value, "tolist"))
      value = value.attr("tolist")();
    if (py::isinstance<py::str>(value))
      return value.cast<std::string>();
    if (py::isinstance<py::bool_>(value))
      return value.cast<bool>() ? "true" : "false";
    if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))
      return py::str(value).cast<std::string>();
    throw py::type_error("override '" + key +
                         "': the value must be a str, a number, a bool or a list of numbers, "
                         "got " +
                         py::str(value.get_type().attr("__name__")).cast<std::string>());
  }

  /// An override's value as prm text: a list of numbers becomes "a, b, c",
  /// a list of such lists "a, b; c, d" (the waypoints of Voltage path).
  std::string override_text(const std::string &key, py::object value)
  {
    if (py::hasattr(value, "tolist"))
      value = value.attr("tolist")();
    if (!is_sequence(value))
      return scalar_text(key, value);
    std::string text;
    for (const py::handle item : value)
      {
        std::string part;
        if (is_sequence(item))
          for (const py::handle x : item)
            part += (part.empty() ? "" : ", ") +
                    scalar_text(key, py::reinterpret_borrow<py::object>(x));
        else
          part = scalar_text(key, py::reinterpret_borrow<py::object>(item));
        text += (text.empty() ? "" : is_sequence(item) ? "; " : ", ") + part;
      }
    return text;
  }

  /// @p prm: a path (str or os.PathLike), or prm text (a str holding a line
  /// break, or "" for every default).
  ParameterInput parameter_input(const py::object &prm, const py::object &overrides)
  {
    ParameterInput input;
    if (py::isinstance<py::str>(prm))
      {
        const std::string s = prm.cast<std::string>();
        input = s.empty() || s.find('\n') != std::string::npos ? ParameterInput::text(s) :
                                                                 ParameterInput::file(s);
      }
    else if (py::hasattr(prm, "__fspath__"))
      input =
        ParameterInput::file(py::module_::import("os").attr("fspath")(prm).cast<std::string>());
    else
      throw py::type_error("prm must be the path of a parameter file or its text");
    if (!overrides.is_none() && !py::isinstance<py::dict>(overrides) &&
        !py::hasattr(overrides, "items"))
      throw py::type_error("overrides must be a dict {'Subsection/Entry': value}, e.g. "
                           "{'Loading/Mass (g)': 300}; got " +
                           py::str(py::type::of(overrides).attr("__name__")).cast<std::string>() +
                           " " + py::repr(overrides).cast<std::string>());
    if (!overrides.is_none())
      for (const auto &[key, value] : py::dict(overrides))
        {
          const std::string name = py::str(key).cast<std::string>();
          const std::string text = override_text(name, py::reinterpret_borrow<py::object>(value));
          input.overrides.emplace_back(name, text);
        }
    return input;
  }

  py::array_t<double> real_array(const std::vector<double> &values,
                                 const std::vector<py::ssize_t> &shape)
  {
    py::array_t<double> a(shape);
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
  }

  py::array_t<int> integer_array(const std::vector<double> &values,
                                 const std::vector<py::ssize_t> &shape)
  {
    py::array_t<int> a(shape);
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
  }

  /// Writes a results file with @p writer at @p path, or at @p default_path
  /// if @p path is None; returns where. A file that cannot be written raises
  /// OSError with the writer's message. The GIL stays held: it keeps two
  /// threads out of the HDF5 library at once (Debian's is not thread-safe).
  std::string write_file(const py::object &path, const std::string &default_path,
                         const std::function<void(const std::string &)> &writer)
  {
    const std::string file =
      path.is_none() ? default_path :
                       py::module_::import("os").attr("fspath")(path).cast<std::string>();
    if (!path.is_none())
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
    return file;
  }

  /// The result of cdea.run() and cdea.shoot().
  class Run
  {
  public:
    explicit Run(RunRecord record)
      : record(std::move(record))
    {}

    /// /summary: the standard columns, then the postprocessors' columns in
    /// the order they first appear (NaN in the rows without them).
    py::dict summary()
    {
      if (summary_cache)
        return summary_cache.cast<py::dict>();
      py::dict summary;
      for (const Quantity *column : standard_summary_columns())
        summary[column->name] = standard_column(*column);
      for (const Quantity *column : postprocessor_columns())
        {
          std::vector<double> values;
          for (const StepSummary &s : record.steps)
            values.push_back(s.columns.in_file_units(*column));
          summary[column->name] = real_array(values, {py::ssize_t(values.size())});
        }
      summary_cache = summary;
      return summary;
    }

    /// /steps/NNNNNN of step @p step (negative: from the end).
    py::dict fields(long step) const
    {
      const long n = long(record.fields.size());
      if (step < -n || step >= n)
        throw py::index_error("step " + std::to_string(step) + " is not one of the " +
                              std::to_string(n) + " steps (0 to " + std::to_string(n - 1) +
                              ", or -" + std::to_string(n) + " to -1 from the end)");
      if (step < 0)
        step += n;
      const StepFields &f = record.fields[std::size_t(step)];
      if (f.R.empty())
        throw py::index_error("step " + std::to_string(step) +
                              " has no fields: a time run keeps them at the steps its results "
                              "file has a /steps group for (field_steps)");
      py::dict fields;
      for (const StepField &row : step_fields())
        if (row.in_file)
          {
            const std::vector<double> values =
              in_unit(step_field_values(row, f), row.field.unit);
            const std::vector<py::ssize_t> shape = {py::ssize_t(values.size())};
            fields[row.field.name] = row.field.storage == Storage::integer ?
                                       py::object(integer_array(values, shape)) :
                                       py::object(real_array(values, shape));
          }
      // The law's internal variables (the viscous stretches of a time run).
      for (const InternalField &internal : f.internal)
        fields[internal.name.c_str()] =
          real_array(internal.values, {py::ssize_t(internal.values.size())});
      return fields;
    }

    /// The steps fields() has: every step, or for a time run those of /steps.
    std::vector<std::size_t> field_steps() const
    {
      std::vector<std::size_t> steps;
      for (std::size_t i = 0; i < record.fields.size(); ++i)
        if (!record.fields[i].R.empty())
          steps.push_back(i);
      return steps;
    }

    /// None, or the onset attributes but onset_found, without "onset_".
    py::object onset() const
    {
      using namespace summary_attribute;
      if (record.attributes.at(onset_found).values.at(0) == 0.)
        return py::none();
      py::dict onset;
      for (const Quantity *row : {&onset_voltage, &onset_radius, &onset_load_factor})
        onset[std::string(row->name).substr(std::string("onset_").size()).c_str()] =
          python::value(record.attributes.at(*row));
      return onset;
    }

    /// The /summary attributes: onset, limit points, breakdown, time integration.
    py::dict attributes() const { return python::entries(record.attributes, Place::attribute); }

    /// Unit and description of every /summary column.
    py::dict columns() const
    {
      py::dict columns;
      for (const Quantity *c : standard_summary_columns())
        columns[c->name] = py::make_tuple(c->unit.name, c->description);
      for (const Quantity *c : postprocessor_columns())
        columns[c->name] = py::make_tuple(c->unit.name, c->description);
      return columns;
    }

    std::string write(const py::object &path) const
    {
      return write_file(path, record.results_path,
                        [this](const std::string &file) { write_run(record, file); });
    }

    RunRecord record;

  private:
    py::object summary_cache; // the summary dict once built

    /// A standard column over the steps, as the file stores it.
    py::object standard_column(const Quantity &column) const
    {
      const std::size_t   n     = record.steps.size();
      const std::size_t   width = column.shape == shape::step_ring ? record.n_rings : 1;
      std::vector<double> values;
      values.reserve(n * width);
      for (const StepSummary &s : record.steps)
        {
          const std::vector<double> row = in_unit(column.summary_values(s), column.unit);
          values.insert(values.end(), row.begin(), row.end());
        }
      std::vector<py::ssize_t> shape = {py::ssize_t(n)};
      if (column.shape == shape::step_ring)
        shape.push_back(py::ssize_t(width));
      return column.storage == Storage::integer ? py::object(integer_array(values, shape)) :
                                                  py::object(real_array(values, shape));
    }

    /// The postprocessors' columns of the steps, in the order they first appear.
    std::vector<const Quantity *> postprocessor_columns() const
    {
      std::vector<const Quantity *> columns;
      for (const StepSummary &s : record.steps)
        for (const auto &entry : s.columns)
          if (std::find(columns.begin(), columns.end(), entry.first) == columns.end())
            columns.push_back(entry.first);
      return columns;
    }
  };

  /// The result of cdea.sweep(): the map's product.
  class Sweep
  {
  public:
    explicit Sweep(SweepRecord record)
      : record(std::move(record))
      , product(sweep_product(this->record.map, this->record.parameters))
    {}

    std::string write(const py::object &path) const
    {
      return write_file(path, record.results_path,
                        [this](const std::string &file) { write_product_file(product, file); });
    }

    SweepRecord record;
    Product     product;
  };

  Run run_method(const py::object &prm, const py::object &overrides, const RunMethod method)
  {
    const ParameterInput input = parameter_input(prm, overrides);
    std::string          note;
    RunRecord            record;
    {
      const py::gil_scoped_release release;
      record = run_in_memory(read_run_input(input, method, &note), method);
    }
    if (!note.empty())
      record.notes.push_back(note);
    return Run(std::move(record));
  }
  void bind_run_result(py::module_ &m)
  {
    py::class_<Run>(m, "RunResult",
                    "The steps of cdea.run() or cdea.shoot(), in memory: /summary and /steps of "
                    "the results file as numpy arrays (same names, same units).")
      .def_property_readonly("summary", &Run::summary,
                             "dict of numpy arrays, one per /summary dataset (steps, or steps x "
                             "rings)")
      .def("fields", &Run::fields, py::arg("step"),
           "dict of numpy arrays along the meridian: the datasets of /steps/NNNNNN (negative "
           "steps count from the end; a time run has them at field_steps only)")
      .def_property_readonly("field_steps", &Run::field_steps,
                             "the steps with fields: all of them, or for a time run those its "
                             "results file has a /steps group for")
      .def_property_readonly("onset", &Run::onset,
                             "None, or dict voltage_kV, radius_mm, load_factor of the loss of "
                             "tension")
      .def_property_readonly("attributes", &Run::attributes,
                             "dict of the /summary attributes (onset, limit points, breakdown)")
      .def_property_readonly("columns", &Run::columns,
                             "dict name -> (unit, description) of the /summary columns")
      .def_property_readonly("completed", [](const Run &r) { return r.record.result.completed; },
                             "True if the run reached the end of its voltage path (or waveform)")
      .def_property_readonly("message", [](const Run &r) { return r.record.result.message; },
                             "why the run stopped early ('' if it did not)")
      .def_property_readonly("end", [](const Run &r) { return r.record.result.end; },
                             "how an arc-length continuation ended ('' otherwise)")
      .def_property_readonly("notes", [](const Run &r) { return r.record.notes; })
      .def_property_readonly("n_steps", [](const Run &r) { return r.record.steps.size(); })
      .def("__len__", [](const Run &r) { return r.record.steps.size(); })
      .def_property_readonly("n_rings", [](const Run &r) { return r.record.n_rings; })
      .def_property_readonly("newton_iterations",
                             [](const Run &r) { return r.record.result.newton_iterations; })
      .def_property_readonly("seconds", [](const Run &r) { return r.record.seconds; },
                             "wall time of the load stages (s)")
      .def_property_readonly("method", [](const Run &r) { return to_string(r.record.method); })
      .def_property_readonly("parameters", [](const Run &r) { return r.record.parameters; },
                             "every parameter of the run, as the results file stores them")
      .def_property_readonly("results_path", [](const Run &r) { return r.record.results_path; },
                             "where the command line would write the results")
      .def("write", &Run::write, py::arg("path") = py::none(),
           "write the results file (HDF5, as the command line writes it) to path, by default "
           "<Directory>/<Base name>.h5 of the parameters; returns the path")
      .def("__repr__", [](const Run &r) {
        return "<cdea.RunResult " + to_string(r.record.method) + ": " +
               std::to_string(r.record.steps.size()) + " steps, " +
               (r.record.result.completed ? "completed" : "stopped early") + ">";
      });
  }

  void bind_sweep_result(py::module_ &m)
  {
    py::class_<Sweep>(m, "SweepResult",
                      "The design map of cdea.sweep(), in memory: the datasets and root "
                      "attributes of the map file as numpy arrays (same names, same units).")
      .def_property_readonly(
        "arrays", [](const Sweep &s) { return python::entries(s.product.root(), Place::dataset); },
        "dict of numpy arrays, one per dataset")
      .def_property_readonly(
        "attributes",
        [](const Sweep &s) { return python::entries(s.product.root(), Place::attribute); },
        "dict of the root attributes")
      .def_property_readonly(
        "columns", [](const Sweep &s) { return python::columns(s.product.root()); },
        "dict name -> (unit, description) of the datasets")
      .def_property_readonly("seconds", [](const Sweep &s) { return s.record.seconds; })
      .def_property_readonly("parameters", [](const Sweep &s) { return s.record.parameters; })
      .def_property_readonly("results_path", [](const Sweep &s) { return s.record.results_path; })
      .def("write", &Sweep::write, py::arg("path") = py::none(),
           "write the map file (HDF5) to path, by default <Directory>/<Base name>_map.h5; "
           "returns the path")
      .def("__repr__", [](const Sweep &s) {
        return "<cdea.SweepResult " + std::to_string(s.record.map.rows.size()) + " x " +
               std::to_string(s.record.map.settings.outer_voltages.size()) + " points>";
      });
  }

  void bind_response(py::module_ &m, const std::string &prm_doc)
  {
    m.def(
      "response",
      [](const py::object &prm, const py::object &overrides) {
        const ParameterInput input = parameter_input(prm, overrides);
        FrequencyResponse    r;
        {
          const py::gil_scoped_release release;
          r = frequency_response(read_run_input(input, RunMethod::finite_elements));
        }
        return response_dict(r);
      },
      py::arg("prm"), py::arg("overrides") = py::none(),
      ("`cdea response` in-process: the small-signal frequency response as a dict of numpy "
       "arrays named as the datasets of <Base name>_response.h5 (the transfer functions "
       "complex). " + prm_doc).c_str());
  }

  /// cdea.run, cdea.shoot, cdea.sweep, cdea.parameters and cdea.response.
  void bind_runs(py::module_ &m)
  {
    const std::string prm_doc = "prm: the path of a parameter file (str or os.PathLike) or its "
                                "text (a str with a line break; '' for every default); "
                                "overrides: dict {'Subsection/Entry': value} set after it.";
    const std::tuple<const char *, RunMethod, const char *> runs[] = {
      {"run", RunMethod::finite_elements,
       "`cdea run` in-process: the FE model along the load stages (in time if Time/Enabled). "},
      {"shoot", RunMethod::shooting,
       "`cdea shoot` in-process: the shooting model on the same scene. "}};
    for (const auto &[name, method, what] : runs)
      m.def(
        name,
        [method = method](const py::object &prm, const py::object &overrides) {
          return run_method(prm, overrides, method);
        },
        py::arg("prm"), py::arg("overrides") = py::none(), (what + prm_doc).c_str());
    m.def(
      "sweep",
      [](const py::object &prm, const py::object &overrides) {
        const ParameterInput input = parameter_input(prm, overrides);
        SweepRecord          record;
        {
          const py::gil_scoped_release release;
          record = sweep_in_memory(input);
        }
        return Sweep(std::move(record));
      },
      py::arg("prm"), py::arg("overrides") = py::none(),
      ("`cdea sweep` in-process, on this process alone. " + prm_doc).c_str());
    m.def(
      "parameters",
      [](const py::object &prm, const py::object &overrides) {
        std::string text;
        read_parameters(parameter_input(prm, overrides), &text);
        return text;
      },
      py::arg("prm") = "", py::arg("overrides") = py::none(),
      ("Every parameter, validated, as a results file stores them. " + prm_doc).c_str());
    bind_response(m, prm_doc);
    bind_frequency_sweep(m, prm_doc, parameter_input);
  }
} // namespace

void bind_design(py::module_ &); // python/design_bindings.cc: optimize, fit
void bind_viscous_fit(py::module_ &); // python/viscous_fit_bindings.cc: fit_viscoelastic
void bind_material_fit(py::module_ &); // python/material_fit_bindings.cc: fit on material tests

PYBIND11_MODULE(cdea, m)
{
  prepare_in_process_runs();
  m.doc() = "cdea in-process: cone dielectric elastomer actuators with partitioned electrodes "
            "(run, shoot, sweep without a process per run; doc/python.md)";
  m.attr("__version__") = CDEA_VERSION;
  py::register_exception_translator([](std::exception_ptr p) {
    try
      {
        if (p)
          std::rethrow_exception(p);
      }
    catch (const MissingFileError &e)
      {
        PyErr_SetString(PyExc_FileNotFoundError, e.what());
      }
    catch (const InputError &e)
      {
        PyErr_SetString(PyExc_ValueError, e.what());
      }
  });
  bind_run_result(m);
  bind_sweep_result(m);
  bind_runs(m);
  m.def("mpi_initialized", &mpi::initialized,
        "True once this process has started MPI (only the Trilinos KLU solver does)");
  bind_design(m);
  bind_viscous_fit(m);
  bind_material_fit(m);
  // The pure-Python part (python/cdea_load.py): cdea.load, to_pandas, to_xarray.
  py::module_::import("cdea_load").attr("extend")(m);
}
