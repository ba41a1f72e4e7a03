#pragma once
// The quasi-static time model of a parameter file at given sample times with
// the derivatives of the displacement with respect to law parameters: the
// model of a creep fit (design/viscous_fit.h). The declaration is the one the
// engine of exact forward sensitivities (branch creepsens) defines; until it
// is merged, source/design/creep_model_fd.cc implements it with a
// finite-difference Jacobian.

#include <cdea/input/parameters.h>
#include <cdea/material/membrane_law.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace cdea
{
  struct CreepSensitivity
  {
    std::vector<double> times;        // s, the sample times asked for
    std::vector<double> displacement; // m, |z(A) - z(B)| at each (the fit's displacement)
    Eigen::MatrixXd     jacobian;     // d displacement / d parameter, rows: times, columns: parameters (SI)
  };

  // Runs the quasi-static time model of p (its Time subsection and waveform), landing on every sample time,
  // with exact forward sensitivities with respect to parameters; false with a message naming where and why.
  bool creep_with_sensitivities(const Parameters &p, const std::vector<LawParameter> &parameters,
                                const std::vector<double> &sample_times, CreepSensitivity &out,
                                std::string &message);
} // namespace cdea
