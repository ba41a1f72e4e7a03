// The FE model in time on a homogeneous equi-biaxial film against an ODE.
//
// Without weight the flat film stays homogeneous, r = s R, z = 0, for any
// equi-biaxial stretch s prescribed at both edges and any (uniform) voltage.
// With the stretch history s(t) = 2.5 + 0.3 sin(2 pi t / 2 s) from the relaxed
// state, the viscous stretch xi(t) of the two-network law obeys Zhao, Koh and
// Suo's equi-biaxial equation
//
//   dxi/dt = xi mu_B / (6 eta) (s^2 xi^-2 - s^-4 xi^4) / g_B,
//   g_B = 1 - (2 s^2 xi^-2 + s^-4 xi^4 - 3) / Jlim_B,
//
// integrated here by the project's Dormand-Prince 5(4) integrator at 1e-12;
// the meridian stress of the film is s1_A(s, s) + s1_B(s/xi, s/xi) / xi. The
// FE model is stepped through the same history (MembraneModel: time step,
// solve, accept) with both schemes at 20 to 160 steps: its s1 and xi converge
// to the ODE's at first order (backward Euler) and second order (trapezoidal).

#include <cdea/fe/membrane_model.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/numerics/dormand_prince.h>

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
  const ViscousNetwork network_b{45e3, 60., 2.};
  const double         period = 2., t_end = 2., voltage = 3e3;

  double stretch(const double t) { return 2.5 + 0.3 * std::sin(2. * M_PI * t / period); }

  LoadState load(const double t) { return cdea_test::film_load(t, stretch(t), voltage); }

  /// xi(t_end) of the ODE.
  double reference_xi()
  {
    using Integrator = shooting::DormandPrince45<1>;
    Integrator::Control c;
    c.rtol = c.atol = 1e-12;
    const double eta = network_b.shear_modulus * network_b.relaxation_time;
    const auto   rhs = [&](const double t, const Integrator::State &y, Integrator::State &dy) {
      const double s = stretch(t), xi = y[0];
      const double g = 1. - (2. * s * s / (xi * xi) + std::pow(xi / s, 4) - 3.) / network_b.jlim;
      dy[0] = xi * network_b.shear_modulus / (6. * eta) *
              (s * s / (xi * xi) - std::pow(xi / s, 4)) / g;
      return g > 0.;
    };
    Integrator::State y0;
    y0[0]         = stretch(0.);
    const auto r  = Integrator(c).integrate(rhs, 0., t_end, y0, 0.,
                                           [](const auto &, double, const auto &) {});
    check(r.ok, "ODE integrated");
    return r.y[0];
  }

  /// s1 and xi1 of the FE film at t_end with @p steps steps of @p scheme.
  std::pair<double, double> fe_film(const Scene &scene, const unsigned int steps,
                                     const TimeScheme scheme)
  {
    MembraneModel model(scene, cdea_test::discretization(2, 2), NewtonSettings());
    model.set_material_law(std::make_shared<TwoNetworkGentLaw>(scene.material, network_b));
    model.set_time_step(std::numeric_limits<double>::infinity(), scheme);
    check(model.solve(load(0.)).converged, "relaxed start");
    model.relax_internal_variables();
    const double dt = t_end / steps;
    for (unsigned int k = 0; k < steps; ++k)
      {
        model.set_time_step(dt, scheme);
        if (!model.solve(load((k + 1) * dt)).converged)
          {
            check(false, "time step converges");
            return {0., 0.};
          }
        model.accept_time_step();
      }
    model.set_time_step(0., scheme);
    const StepFields           f   = model.fields();
    const std::vector<double> &xi1 = f.internal_values("xi1"), &xi2 = f.internal_values("xi2");
    // Homogeneous: every sample alike.
    double spread = 0.;
    for (std::size_t i = 0; i < f.s1.size(); ++i)
      spread = std::max({spread, std::abs(f.s1[i] - f.s1[0]) / f.s1[0],
                         std::abs(xi1[i] - xi1[0]), std::abs(xi2[i] - xi1[0]),
                         std::abs(f.lambda1[i] - stretch(t_end))});
    check_close(spread, 0., 1e-12, "the film stays homogeneous (s1, xi1 = xi2, lambda1 = s)");
    return {f.s1[0], xi1[0]};
  }
} // namespace

CDEA_TEST_MAIN()
{
  Scene scene = cdea::paper_scene({1., 3.}, {{voltage * 1e-3}});
  scene.mass  = 0.;

  const double         xi = reference_xi(), s = stretch(t_end);
  const GentDielectric a(scene.material, voltage);
  const GentDielectric b({network_b.shear_modulus, network_b.jlim, 0., 1.}, 0.);
  const double         s1 = a.stress(s, s).s1 + b.stress(s / xi, s / xi).s1 / xi;
  std::cout << "ODE at t = 2 s: xi = " << xi << " (stretch " << s << "), s1 = " << s1 << " Pa\n";
  check(std::abs(xi - s) > 1e-2, "the viscous stretch lags the stretch (the test is not trivial)");

  for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::trapezoidal})
    {
      const double order = scheme == TimeScheme::backward_euler ? 1. : 2.;
      double       previous_s1 = 0., previous_xi = 0.;
      for (const unsigned int steps : {20u, 40u, 80u, 160u})
        {
          const auto [fe_s1, fe_xi] = fe_film(scene, steps, scheme);
          const double e_s1 = std::abs(fe_s1 - s1) / scene.material.shear_modulus;
          const double e_xi = std::abs(fe_xi - xi);
          std::cout << (scheme == TimeScheme::backward_euler ? "backward Euler" : "trapezoidal")
                    << ", " << steps << " steps: |s1 - s1_ODE| / mu = " << e_s1
                    << ", |xi - xi_ODE| = " << e_xi;
          if (previous_s1 > 0.)
            {
              const double p_s1 = std::log2(previous_s1 / e_s1);
              const double p_xi = std::log2(previous_xi / e_xi);
              std::cout << ", orders " << p_s1 << ", " << p_xi << '\n';
              check(std::abs(p_s1 - order) < 0.15 && std::abs(p_xi - order) < 0.15,
                    "observed order of s1 and xi near " + std::to_string(int(order)));
            }
          else
            std::cout << '\n';
          previous_s1 = e_s1;
          previous_xi = e_xi;
        }
      check(previous_xi < (order == 1. ? 5e-3 : 5e-5), "error at 160 steps small");
    }
  return cdea_test::finish();
}
