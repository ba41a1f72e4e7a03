#pragma once
// A creep run with exact sensitivities: the displacement of a quasi-static
// time run (no disk inertia, no water column) at given sample times and its
// derivatives with respect to material parameters, by forward sensitivities
// of the discrete time scheme (fe/time_sensitivity.h; doc/materials.md,
// "Sensitivities through time"). The steps are those the run's own step
// control takes (Time subsection), landing on every sample time; the
// derivative is that of the discrete solution with those steps held fixed.
// The creep and DMA fits (design/) call it.

#include <cdea/input/parameters.h>
#include <cdea/material/membrane_law.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace cdea
{
  struct CreepSensitivity
  {
    std::vector<double> times;        ///< s, the sample times asked for
    std::vector<double> displacement; ///< m, |z(A) - z(B)| at each (as design/fit uses it)
    /// d displacement / d parameter: rows the times, columns the parameters (SI:
    /// Pa, -, F/m, V; a branch's mu_k in Pa and tau_k in s).
    Eigen::MatrixXd jacobian;
  };

  /// Runs the quasi-static time model of @p p (its Time subsection and
  /// voltage waveform; the film starts relaxed), landing on every sample
  /// time (increasing, in [0, end of the waveform]), with exact forward
  /// sensitivities with respect to @p parameters (LawParameter::voltage:
  /// every voltage of the waveform scaled together, per volt of the largest
  /// peak). False with a message naming where and why.
  bool creep_with_sensitivities(const Parameters &p, const std::vector<LawParameter> &parameters,
                                const std::vector<double> &sample_times, CreepSensitivity &out,
                                std::string &message);
} // namespace cdea
