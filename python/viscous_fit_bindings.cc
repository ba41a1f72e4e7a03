// cdea.fit_viscoelastic(prm, data): `cdea fit` of a DMA table or a creep curve
// (design/viscous_fit.h) in-process, its results under the names and units of
// <Base name>_fit.h5 (doc/materials.md, "Fits").

#include <cdea/base/format.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/validation.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace py = pybind11;
using namespace cdea;

namespace
{
  py::array_t<double> numbers(const std::vector<double> &v)
  {
    py::array_t<double> a(py::ssize_t(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
  }

  /// An in-process DMA or creep fit.
  struct ViscousCalibration
  {
    FitDataKind kind = FitDataKind::dma;
    std::string parameter_text;
    FitSettings settings;
    DmaData     dma;
    CreepData   creep;
    FitResult   result;

    py::dict by_name(const std::vector<double> &values) const
    {
      py::dict d;
      for (std::size_t j = 0; j < settings.free.size(); ++j)
        d[py::str(settings.free[j].name())] = values[j];
      return d;
    }

    py::array_t<double> correlation() const
    {
      const auto          K = py::ssize_t(settings.free.size());
      py::array_t<double> a({K, K});
      for (py::ssize_t i = 0; i < K; ++i)
        for (py::ssize_t j = 0; j < K; ++j)
          a.mutable_at(i, j) = result.correlation.size() ? result.correlation(i, j) : NAN;
      return a;
    }

    /// /data of the fit file (kPa or mm, as written).
    py::dict data() const
    {
      py::dict            d;
      std::vector<double> fitted, residual;
      const double        unit = kind == FitDataKind::dma ? 1e-3 : 1e3;
      for (Eigen::Index i = 0; i < result.fitted.size(); ++i)
        {
          fitted.push_back(result.fitted[i] * unit);
          residual.push_back(result.residuals[i] * unit);
        }
      if (kind == FitDataKind::dma)
        {
          std::vector<double> storage, loss, fs, fl, rs, rl;
          for (std::size_t i = 0; i < dma.size(); ++i)
            {
              storage.push_back(dma.storage[i] * 1e-3);
              loss.push_back(dma.loss[i] * 1e-3);
              if (!fitted.empty())
                {
                  fs.push_back(fitted[2 * i]), fl.push_back(fitted[2 * i + 1]);
                  rs.push_back(residual[2 * i]), rl.push_back(residual[2 * i + 1]);
                }
            }
          d["frequency_Hz"]          = numbers(dma.frequency);
          d["storage_kPa"]           = numbers(storage);
          d["loss_kPa"]              = numbers(loss);
          d["weight"]                = numbers(dma.weight);
          d["fitted_storage_kPa"]    = numbers(fs);
          d["fitted_loss_kPa"]       = numbers(fl);
          d["residual_storage_kPa"]  = numbers(rs);
          d["residual_loss_kPa"]     = numbers(rl);
          return d;
        }
      std::vector<double> measured;
      for (const double x : creep.displacement)
        measured.push_back(x * 1e3);
      d["time_s"]          = numbers(creep.times);
      d["displacement_mm"] = numbers(measured);
      d["weight"]          = numbers(creep.weight);
      d["fitted_mm"]       = numbers(fitted);
      d["residual_mm"]     = numbers(residual);
      return d;
    }

    void write(const std::string &path) const
    {
      if (kind == FitDataKind::dma)
        write_dma_fit_file(path, parameter_text, dma, settings, result);
      else
        write_creep_fit_file(path, parameter_text, creep, settings, result);
    }
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
                           [](const ViscousCalibration &c) { return c.by_name(c.result.values); },
                           "fitted values by parameter name (SI units)")
    .def_property_readonly(
      "standard_errors", [](const ViscousCalibration &c) { return c.by_name(c.result.standard_errors); },
      "standard errors by parameter name (SI units)")
    .def_property_readonly("correlation", &ViscousCalibration::correlation)
    .def_property_readonly("data", &ViscousCalibration::data, "/data of the fit file (dict)")
    .def_property_readonly("rms", [](const ViscousCalibration &c) { return c.result.rms; },
                           "weighted rms residual (SI: Pa for DMA, m for creep)")
    .def_property_readonly("warnings", [](const ViscousCalibration &c) { return c.result.warnings; })
    .def_property_readonly("converged", [](const ViscousCalibration &c) { return c.result.converged; })
    .def("write", [](const ViscousCalibration &c, const std::string &path) { c.write(path); },
         py::arg("path"), "Write the fit file (HDF5) to path");
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
      return c;
    },
    py::arg("prm"), py::arg("data"), py::arg("overrides") = py::none(),
    py::arg("progress") = false,
    "`cdea fit` of a DMA table (header frequency_Hz, storage_kPa, loss_kPa) or a creep curve "
    "(time_s, V1_kV.., displacement_mm) in-process; prm: a path or prm text, data: a CSV path "
    "or CSV text, overrides: {'Subsection/Entry': value}. Writes nothing.");
}
