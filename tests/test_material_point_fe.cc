// The material point (material/material_point.h) against the FE model on
// the film's homogeneous equibiaxial state. Without weight and voltage the
// flat film stays homogeneous, r = s R, z = 0, for any equibiaxial stretch s
// prescribed at both edges (tests/test_time_film.cc): every quadrature point
// is a material point in equibiaxial tension. The FE model is stepped
// through a stretch history that is linear between its samples (the one the
// material point sees), from the film relaxed at the first stretch, by
// backward Euler and the trapezoidal rule (MembraneModel: time step, solve,
// accept) and by ESDIRK3 and ESDIRK4 stages (solver/esdirk_step.h, the FE
// time run's stepper), with three branches (one variant with the
// shear-thinning viscosity). After every step the FE film's s1 and every
// branch's viscous stretches xi1, xi2 are compared with the material
// point's: the same law object and update, so they agree to the local
// solvers' tolerances.

#include <cdea/fe/membrane_model.h>
#include <cdea/material/material_point.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/solver/esdirk_step.h>

#include "check.h"
#include "fe_checks.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_close;

namespace
{
  const double step = 0.1;

  /// Samples every step: up from 2.5 to 3.1, down to 2.2, held.
  StretchHistory history()
  {
    StretchHistory h;
    h.kind = TestKind::equibiaxial;
    for (unsigned int k = 0; k <= 30; ++k)
      {
        const double t = step * k;
        h.time.push_back(t);
        h.stretch.push_back(t <= 1. ? 2.5 + 0.6 * t : t <= 2. ? 3.1 - 0.9 * (t - 1.) : 2.2);
      }
    return h;
  }

  /// The stretch at t on the piece of the history holding @p inside
  /// (extrapolated beyond it, as an ESDIRK stage past the step end sees it).
  double stretch_at(const StretchHistory &h, const double t, const double inside)
  {
    std::size_t k = 1;
    while (k + 1 < h.time.size() && h.time[k] < inside)
      ++k;
    return h.stretch[k - 1] +
           (h.stretch[k] - h.stretch[k - 1]) * (t - h.time[k - 1]) / (h.time[k] - h.time[k - 1]);
  }

  struct Compared
  {
    double stress = 0., viscous = 0.;
  };

  /// The largest differences after each step (s1 over mu, xi absolute).
  void compare(const MembraneModel &model, const MaterialPointResult &point, const std::size_t k,
               const MembraneLaw &law, Compared &worst)
  {
    const StepFields   f = model.fields();
    const unsigned int n = law.n_internal_variables();
    worst.stress = std::max(worst.stress, std::abs(f.s1[0] - point.stress[k]) / 25.1e3);
    for (unsigned int i = 0; i < n; ++i)
      {
        const InternalVariable &v = law.internal_variables()[i];
        if (v.written)
          worst.viscous = std::max(worst.viscous, std::abs(f.internal_values(v.name)[0] -
                                                           point.internal[k * n + i]));
      }
  }

  Compared fe_against_point(const std::shared_ptr<const MembraneLaw> &law, const TimeMethod method)
  {
    Scene scene = paper_scene({1., 3.}, {{0.}});
    scene.mass  = 0.;
    const StretchHistory h = history();
    MaterialPointSettings settings;
    settings.method           = method;
    settings.max_stretch_step = HUGE_VAL; // one step per sample, as the FE run
    settings.step_growth      = 0.;
    settings.record_internal  = true;
    MaterialPoint       point(*law, settings);
    MaterialPointResult r;
    std::string         message;
    check(point.run(h, {}, r, message), "material point runs " + message);

    // Newton to round-off: the shear-thinning tangent is inexact (linear
    // convergence), and the comparison is finer than the default tolerance.
    NewtonSettings newton;
    newton.residual_tolerance = newton.update_tolerance = 1e-13;
    MembraneModel model(scene, cdea_test::discretization(2, 2), newton);
    model.set_material_law(law);
    const TimeScheme scheme =
      method == TimeMethod::trapezoidal ? TimeScheme::trapezoidal : TimeScheme::backward_euler;
    model.set_time_step(std::numeric_limits<double>::infinity(), scheme);
    check(model.solve(cdea_test::film_load(0., h.stretch[0], 0.)).converged, "relaxed start");
    model.relax_internal_variables();
    model.set_time_step(0., scheme);
    check(model.solve(cdea_test::film_load(0., h.stretch[0], 0.)).converged, "held start");
    model.accept_time_step();
    Compared worst;
    compare(model, r, 0, *law, worst);

    const EsdirkTableau *tableau = esdirk_tableau(method);
    EsdirkStepSettings   e;
    e.tableau = tableau;
    EsdirkStep stepper(
      model, e,
      [&](const double t, const double inside) {
        return cdea_test::film_load(t, stretch_at(h, t, inside), 0.);
      },
      [](double, double) { return std::vector<double>{0.}; });
    TimePoint start;
    start.state    = model.state();
    start.charges  = model.charges();
    unsigned int failed = 0;
    for (std::size_t k = 1; k < h.time.size() && failed == 0; ++k)
      {
        bool converged = false;
        if (tableau)
          converged = stepper.take(start, step).converged;
        else
          {
            model.set_time_step(step, scheme);
            converged = model.solve(cdea_test::film_load(h.time[k], h.stretch[k], 0.)).converged;
          }
        if (!converged)
          {
            failed = unsigned(k);
            break;
          }
        model.accept_time_step();
        model.set_time_step(0., scheme);
        if (tableau)
          {
            start       = stepper.end();
            start.state = model.state();
          }
        compare(model, r, k, *law, worst);
      }
    check(failed == 0, "every FE step converges (the first that did not: " + std::to_string(failed) + ")");
    return worst;
  }
} // namespace

CDEA_TEST_MAIN()
{
  const MaterialConstants film{25.1e3, 270., 3.98e-11, 1e-3};
  const std::vector<ViscousNetwork> branches{{30e3, 80., 0.2}, {10e3, 80., 1.}, {5e3, 80., 10.}};
  const auto newtonian = std::make_shared<TwoNetworkGentLaw>(film, branches);
  ShearThinning thinning;
  thinning.enabled = true;
  thinning.r       = 0.2;
  thinning.k1      = 0.3;
  thinning.beta1   = 1.5;
  thinning.k2      = 1e-8;
  thinning.beta2   = 0.6;
  const auto thinned = std::make_shared<TwoNetworkGentLaw>(film, branches, std::vector<SpringLaw>{},
                                                           thinning);
  const std::vector<std::pair<TimeMethod, std::string>> methods{
    {TimeMethod::backward_euler, "backward Euler"}, {TimeMethod::trapezoidal, "trapezoidal"},
    {TimeMethod::esdirk3, "ESDIRK3"}, {TimeMethod::esdirk4, "ESDIRK4"}};
  for (const auto &[method, name] : methods)
    {
      const Compared c = fe_against_point(newtonian, method);
      check_close(c.stress, 0., 1e-10, name + ": FE s1 against the material point's (over mu), 30 steps");
      check_close(c.viscous, 0., 1e-10, name + ": FE xi1, xi2 of every branch against the material point's");
    }
  for (const TimeMethod method : {TimeMethod::trapezoidal, TimeMethod::esdirk3})
    {
      const Compared c = fe_against_point(thinned, method);
      check_close(c.stress, 0., 1e-10, "shear thinning: FE s1 against the material point's");
      check_close(c.viscous, 0., 1e-10, "shear thinning: FE xi of every branch against the material point's");
    }
  return cdea_test::finish();
}
