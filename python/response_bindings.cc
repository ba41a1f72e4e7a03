// cdea.response of the Python module: the datasets of
// <Base name>_response.h5 (analysis/frequency_response.h) as numpy arrays,
// the transfer functions complex; bound in cdea_module.cc.

#include <cdea/analysis/frequency_response.h>

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
