// Flat states of the shooting model (no dead load): the homogeneous closed
// form, the in-plane problem under unequal ring voltages (radial equilibrium
// d(R s1)/dR = s2, s1 continuous at the ring edge), loading a cone from such
// a state and unloading back to it; and the scalar lambda1 solve.

#include <cdea/model/scene.h>
#include <cdea/shooting/shooting_model.h>
#include <cdea/shooting/shooting_solver.h>

#include "check.h"

#include <cmath>
#include <iostream>

using namespace cdea;
using namespace cdea::shooting;
using cdea_test::check;
using cdea_test::check_close;
using cdea_test::check_rel;

CDEA_TEST_MAIN()
{
  std::cout.precision(10);
  const double kV = 1e3;
  Scene        scene;
  scene.ring_edges_over_a = {1., 1.7, 3.};
  ShootingOptions opt;
  opt.samples_per_ring = 101; // 100 intervals per ring for Simpson's rule

  // The in-plane shooting with equal voltages reproduces the closed form.
  {
    const MeridianIntegrator integ(scene, opt);
    const MeridianLoad       load{scene.prestretch, 0., {3. * kV, 3. * kV}};
    const auto sol = solve_flat(integ, load, 2.3, false);
    check(sol.converged, "equal voltages: in-plane shooting converges");
    check_rel(sol.profile.lambda1_start, scene.prestretch, 1e-10,
              "equal voltages: l1(A) = pre-stretch");
    check_rel(sol.profile.s2_ring_inner[1], integ.equibiaxial_stress(scene.prestretch, 3. * kV),
              1e-9, "equal voltages: s2 = equibiaxial stress");
  }

  ShootingModel model(scene, opt);
  LoadState     load;
  load.stretch  = scene.prestretch;
  load.voltages = {4. * kV, 0.};
  const SolveReport r = model.solve(load);
  check(r.converged, "inner 4 kV, outer 0 V, no load: " + r.message);
  const StepFields f = model.fields();
  check_rel(f.r.back(), scene.frame_radius, 1e-11, "r(B) = b");
  check_close(model.summary().displacement, 0., 0., "flat");

  // Radial equilibrium per ring: [R s1] between the ring's edges equals the
  // integral of s2 over R (Simpson's rule on the samples).
  const unsigned int m = opt.samples_per_ring;
  for (unsigned int k = 0; k < 2; ++k)
    {
      const unsigned int i0 = k * m, i1 = i0 + m - 1;
      const double       h  = (f.R[i1] - f.R[i0]) / (m - 1);
      double             integral = f.s2[i0] + f.s2[i1];
      for (unsigned int i = 1; i + 1 < m; ++i)
        integral += (i % 2 == 1 ? 4. : 2.) * f.s2[i0 + i];
      integral *= h / 3.;
      check_rel(f.R[i1] * f.s1[i1] - f.R[i0] * f.s1[i0], integral, 1e-8,
                "ring " + std::to_string(k + 1) + ": [R s1] = integral of s2 dR");
    }
  check_rel(f.s1[m], f.s1[m - 1], 1e-12, "s1 continuous at the ring edge");
  check(f.lambda1[m] < f.lambda1[m - 1],
        "l1 drops into the unpowered ring: " + std::to_string(f.lambda1[m - 1]) + " -> " +
          std::to_string(f.lambda1[m]));
  const double l1_flat = model.profile().lambda1_start;

  // Dead load from this flat state, then unloaded back to it.
  load.stage = Stage::dead_load;
  bool ok    = true;
  for (unsigned int k = 1; k <= 10 && ok; ++k)
    {
      load.force = scene.dead_load() * k / 10.;
      load.mass  = scene.mass * k / 10.;
      ok         = model.solve(load).converged;
    }
  check(ok, "dead load applied from the flat non-uniform state");
  std::cout << "  displacement " << model.summary().displacement * 1e3 << " mm, theta0 "
            << model.shooting_angle() << "\n";
  check(model.summary().displacement > 0.015, "the disk moved");
  load.force = 0.;
  load.mass  = 0.;
  check(model.solve(load).converged, "unloaded");
  check_rel(model.profile().lambda1_start, l1_flat, 1e-9, "back to the same flat state");

  // The lambda1 solve: s1(l1, l2) = target, and refusal where ds1/dl1 <= 0.
  {
    const GentDielectric law(scene.material, 0.);
    const auto           l1 = solve_lambda1(law, 2.5, 3e5, 2.5);
    check(l1.has_value() && std::abs(law.stress(*l1, 2.5).s1 / 3e5 - 1.) < 1e-13,
          "solve_lambda1 hits the target stress");
    // At 12 kV and l2 = 2.5, s1 falls with l1 around l1 = 2.5 (the voltage term
    // -eps Phi^2/H^2 l2^2 beats the elastic stiffness) and rises again towards the
    // Gent limit: roots on the far side of the falling part are refused.
    const GentDielectric hot(scene.material, 12. * kV);
    const double         l = 2.5;
    check(hot.tangent(l, l).s11 < 0., "12 kV: ds1/dl1 < 0 at l1 = l2 = 2.5");
    std::string why;
    const auto  falling = solve_lambda1(hot, l, hot.stress(l, l).s1 - 1., l, &why);
    check(!falling.has_value(), "guess on the falling part refused: " + why);
    const double l_low = 0.8, l_high = 10.;
    check(hot.tangent(l_low, l).s11 > 0. && hot.tangent(l_high, l).s11 > 0.,
          "12 kV: s1 rises at l1 = 0.8 and at l1 = 10");
    const auto across = solve_lambda1(hot, l, hot.stress(l_high, l).s1, l_low, &why);
    check(!across.has_value(), "root across the falling part refused: " + why);
    const auto near = solve_lambda1(hot, l, hot.stress(l_high, l).s1, 9., &why);
    check(near.has_value() && std::abs(*near / l_high - 1.) < 1e-12,
          "root on the guess's rising branch accepted");
  }
  return cdea_test::finish();
}
