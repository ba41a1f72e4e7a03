#pragma once
// Finite-difference checks of the FE model shared by the test programs.

#include <cdea/fe/membrane_model.h>
#include <cdea/numerics/esdirk.h>

#include "check.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cdea_test
{
  /// The fixed-step scheme of earlier versions whose dashpots use @p scheme
  /// (tests that pin a time run to those steps select it explicitly).
  inline cdea::TimeMethod legacy_method(const cdea::TimeScheme scheme)
  {
    return scheme == cdea::TimeScheme::trapezoidal ? cdea::TimeMethod::trapezoidal :
                                                     cdea::TimeMethod::backward_euler;
  }

  /// A time test's load at time @p t (s): the voltage stage at load factor
  /// t with the pre-stretch @p stretch, one ring at @p voltage (V) and a dead
  /// load of @p mass (kg) on the disk.
  inline cdea::LoadState film_load(const double t, const double stretch, const double voltage,
                                   const double mass = 0.)
  {
    cdea::LoadState l;
    l.mass        = mass;
    l.force       = 9.81 * mass;
    l.stage       = cdea::Stage::voltage;
    l.load_factor = t;
    l.time        = t;
    l.stretch     = stretch;
    l.voltages    = {voltage};
    return l;
  }

  inline cdea::FeDiscretization discretization(const unsigned int degree,
                                               const unsigned int elements,
                                               const unsigned int refinements = 0,
                                               const unsigned int samples     = 4)
  {
    cdea::FeDiscretization d;
    d.degree              = degree;
    d.elements_per_ring   = elements;
    d.refinements         = refinements;
    d.samples_per_element = samples;
    return d;
  }

  /// At the model's current state and load: the largest difference between
  /// the tangent and central differences of the residual (relative to the
  /// largest tangent entry), and, with @p energy_too, between the residual and
  /// central differences of the potential Pi.
  inline void check_derivatives(cdea::MembraneModel &model, const std::string &where,
                                const bool energy_too = true, const double step = 1e-7,
                                const double tolerance = 1e-6)
  {
    const std::vector<double> x0 = model.solution();
    const auto                K  = model.tangent_matrix();
    const auto                r0 = model.residual_vector();
    double worst_K = 0., worst_r = 0., K_scale = 0., r_scale = 0.;
    for (const auto &row : K)
      for (const double k : row)
        K_scale = std::max(K_scale, std::abs(k));
    for (unsigned int j = 0; j < x0.size(); ++j)
      {
        const double h  = step * (1e-3 + std::abs(x0[j]));
        auto         xp = x0, xm = x0;
        xp[j] += h;
        xm[j] -= h;
        model.set_solution(xp);
        const auto   rp = model.residual_vector();
        const double ep = energy_too ? model.energy() : 0.;
        model.set_solution(xm);
        const auto   rm = model.residual_vector();
        const double em = energy_too ? model.energy() : 0.;
        for (unsigned int i = 0; i < x0.size(); ++i)
          worst_K = std::max(worst_K, std::abs((rp[i] - rm[i]) / (2 * h) - K[i][j]));
        // The residual is the gradient of Pi (force F on z(A) included).
        worst_r = std::max(worst_r, std::abs((ep - em) / (2 * h) - r0[j]));
        r_scale = std::max(r_scale, std::abs(r0[j]) + K_scale * 1e-3);
      }
    model.set_solution(x0);
    check_close(worst_K / K_scale, 0., tolerance,
                where + ": tangent vs differences of the residual");
    if (energy_too)
      check_close(worst_r / r_scale, 0., tolerance,
                  where + ": residual vs differences of the energy");
  }
} // namespace cdea_test
