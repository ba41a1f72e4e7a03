// cdea.response of the Python module: the datasets of
// <Base name>_response.h5 (analysis/frequency_response.h) as numpy arrays,
// the transfer functions complex; bound in cdea_module.cc. And
// cdea.frequency_sweep, bound here (bind_frequency_sweep()).

#include <cdea/analysis/frequency_response.h>
#include <cdea/analysis/frequency_sweep.h>

#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <complex>
#include <vector>

namespace py = pybind11;
using namespace cdea;

namespace
{
  /// The columns of @p values times @p factor as a numpy array (rows x
  /// columns, or rows if one column).
  py::array complex_array(const Eigen::MatrixXcd &values, const double factor)
  {
    const bool vector = values.cols() == 1;
    py::array_t<std::complex<double>> a(
      vector ? std::vector<py::ssize_t>{values.rows()} :
               std::vector<py::ssize_t>{values.rows(), values.cols()});
    std::complex<double> *out = a.mutable_data();
    for (Eigen::Index i = 0; i < values.rows(); ++i)
      for (Eigen::Index k = 0; k < values.cols(); ++k)
        *out++ = factor * values(i, k);
    return a;
  }
} // namespace

/// `cdea response` in-process: the datasets of <Base name>_response.h5
/// (complex arrays for the transfer functions) in a dict.
py::dict response_dict(const FrequencyResponse &r)
{
  const auto n = static_cast<py::ssize_t>(r.frequency.size());
  const auto m = static_cast<py::ssize_t>(r.mode_frequency.size());
  std::vector<double> bias_kV;
  for (const double v : r.bias)
    bias_kV.push_back(v * 1e-3);
  py::dict d;
  d["frequency_Hz"]            = py::array_t<double>(n, r.frequency.data());
  d["disk_mm_per_kV"]          = complex_array(r.disk, 1e6);
  d["volume_mm3_per_kV"]       = complex_array(r.volume_per_volt, 1e12);
  d["drive_disk_mm_per_kV"]    = complex_array(r.disk_drive, 1e6);
  d["drive_volume_mm3_per_kV"] = complex_array(r.volume_drive, 1e12);
  d["mode_frequency_Hz"]       = py::array_t<double>(m, r.mode_frequency.data());
  d["mode_damping_ratio"]      = py::array_t<double>(m, r.mode_damping.data());
  d["bias_voltage_kV"]         = py::array_t<double>(py::ssize_t(bias_kV.size()), bias_kV.data());
  d["displacement_mm"]         = r.displacement * 1e3;
  d["volume_mm3"]              = r.volume * 1e9;
  d["drive_scale_kV"]          = r.drive_scale * 1e-3;
  return d;
}

/// `cdea frequency-sweep` in-process: the datasets of
/// <Base name>_frequency_sweep.h5 (analysis/frequency_sweep.h) in a dict.
void bind_frequency_sweep(py::module_ &m, const std::string &prm_doc,
                          ParameterInput (*input_of)(const py::object &, const py::object &))
{
  m.def(
    "frequency_sweep",
    [input_of](const py::object &prm, const py::object &overrides) {
      const ParameterInput input = input_of(prm, overrides);
      FrequencySweepResult r;
      {
        const py::gil_scoped_release release;
        const RunInput run = read_run_input(input, RunMethod::finite_elements);
        r = frequency_sweep(run, frequency_sweep_settings(run.parameters), nullptr);
      }
      const auto          n = static_cast<py::ssize_t>(r.periods.size());
      std::vector<double> f, stroke, mean, volume, dissipated, work, s2, defect;
      std::vector<std::complex<double>> harmonic;
      std::vector<int>    flag, usable = r.usable, converged;
      for (const SteadyPeriod &s : r.periods)
        {
          f.push_back(s.frequency);
          stroke.push_back(s.stroke_amplitude * 1e3);
          mean.push_back(s.mean_displacement * 1e3);
          harmonic.push_back(s.first_harmonic * 1e3);
          volume.push_back(s.volume_swing * 1e9);
          dissipated.push_back(s.dissipated * 1e3);
          work.push_back(s.electrical_work * 1e3);
          s2.push_back(s.s2_min * 1e-3);
          defect.push_back(std::max(s.defect, s.check_move));
          flag.push_back(s.loss_of_tension ? 1 : 0);
          converged.push_back(s.converged ? 1 : 0);
        }
      py::dict d;
      d["frequency_Hz"]              = py::array_t<double>(n, f.data());
      d["stroke_amplitude_mm"]       = py::array_t<double>(n, stroke.data());
      d["mean_displacement_mm"]      = py::array_t<double>(n, mean.data());
      d["harmonic_mm"]               = py::array_t<std::complex<double>>(n, harmonic.data());
      d["swept_volume_mm3"]          = py::array_t<double>(n, volume.data());
      d["dissipated_energy_mJ"]      = py::array_t<double>(n, dissipated.data());
      d["electrical_work_mJ"]        = py::array_t<double>(n, work.data());
      d["s2_min_kPa"]                = py::array_t<double>(n, s2.data());
      d["periodicity_defect"]        = py::array_t<double>(n, defect.data());
      d["loss_of_tension"]           = py::array_t<int>(n, flag.data());
      d["usable"]                    = py::array_t<int>(n, usable.data());
      d["converged"]                 = py::array_t<int>(n, converged.data());
      d["quasi_static_amplitude_mm"] = r.quasi_static_amplitude * 1e3;
      d["usable_band_low_Hz"]        = r.band_low;
      d["usable_band_high_Hz"]       = r.band_high;
      return d;
    },
    py::arg("prm"), py::arg("overrides") = py::none(),
    ("`cdea frequency-sweep` in-process: the periodic steady states as a dict of numpy arrays "
     "named as the datasets of <Base name>_frequency_sweep.h5 (the first harmonic complex). " +
     prm_doc)
      .c_str());
}
