// cdea.response of the Python module: the response's product
// (analysis/frequency_response.h) as numpy arrays through the product
// converter, the transfer functions complex; bound in cdea_module.cc. And
// cdea.frequency_sweep, bound here (bind_frequency_sweep()).

#include <cdea/analysis/frequency_response.h>
#include <cdea/analysis/frequency_sweep.h>

#include <pybind11/pybind11.h>

#include "product_convert.h"

namespace py = pybind11;
using namespace cdea;

/// `cdea response` in-process: the response's product as one dict (the
/// transfer functions complex).
py::dict response_dict(const FrequencyResponse &r)
{
  return python::flattened(response_product("", r));
}

/// `cdea frequency-sweep` in-process: the sweep's product as one dict.
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
      return python::flattened(frequency_sweep_product("", r));
    },
    py::arg("prm"), py::arg("overrides") = py::none(),
    ("`cdea frequency-sweep` in-process: the periodic steady states as a dict of numpy arrays "
     "named as the datasets of <Base name>_frequency_sweep.h5 (the first harmonic complex). " +
     prm_doc)
      .c_str());
}
