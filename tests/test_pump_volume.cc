// Enclosed volume (issue 6): closed-form shapes in the FE space (a flat disk
// with a conical frustum, a curved quadratic meridian, the flat film), the
// volume of computed FE profiles against an independent quadrature of the
// same profile (trapezoidal rule in z on a fine grid of profile_at), and the
// shooting model's volume against the FE one for the same scene.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/shooting_model.h>

#include "check.h"
#include "scenes.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <string>

using namespace cdea;
using namespace cdea_test;

namespace
{
  FeDiscretization discretization(const unsigned int degree, const unsigned int elements)
  {
    FeDiscretization d;
    d.degree            = degree;
    d.elements_per_ring = elements;
    return d;
  }

  /// Interpolate r(s), z(s) with s = (R - A) / (B - A) into the FE space.
  void set_shape(MembraneModel &model, const Scene &scene,
                 const std::function<double(double)> &r_of_s,
                 const std::function<double(double)> &z_of_s)
  {
    const double A = scene.inner_reference_radius(), B = scene.outer_reference_radius();
    const auto   support = model.dof_support();
    std::vector<double> x(support.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        const double s = (support[i].first - A) / (B - A);
        x[i]           = support[i].second == 0 ? r_of_s(s) : z_of_s(s);
      }
    model.set_solution(x);
  }

  /// pi int r^2 dz by the trapezoidal rule on n + 1 points of profile_at
  /// (uses nothing of the FE volume code).
  double trapezoid_volume(const MembraneModel &model, const Scene &scene, const unsigned int n)
  {
    const double        A = scene.inner_reference_radius(), B = scene.outer_reference_radius();
    std::vector<double> R(n + 1), r, z;
    for (unsigned int i = 0; i <= n; ++i)
      R[i] = A + (B - A) * i / n;
    model.profile_at(R, r, z);
    double v = 0.;
    for (unsigned int i = 0; i < n; ++i)
      v += M_PI * 0.5 * (r[i] * r[i] + r[i + 1] * r[i + 1]) * (z[i] - z[i + 1]);
    return v;
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  const Scene      pump = paper_scene({1., 1.7, 3.}, {{4., 4.}, {4., 5.}});
  const double     a = pump.disk_radius, b = pump.frame_radius, h = 20e-3;

  std::cout << "Closed-form shapes\n";
  for (const unsigned int degree : {1u, 2u, 3u, 4u})
    {
      MembraneModel     model(pump, discretization(degree, 3), NewtonSettings());
      const std::string p = " (p = " + std::to_string(degree) + ")";
      // Disk at depth h, straight meridian to the frame: a frustum whose
      // volume includes the column above the disk.
      set_shape(model, pump, [&](double s) { return a + (b - a) * s; },
                [&](double s) { return h * (1. - s); });
      check_rel(model.enclosed_volume(), M_PI * h * (a * a + a * b + b * b) / 3., 1e-13,
                "disk and cone frustum, pi h (a^2 + a b + b^2) / 3" + p);
      // The film's state after the pre-stretch: flat, no volume.
      model.set_reference_state();
      check_close(model.enclosed_volume(), 0., 1e-20, "flat film" + p);
      if (degree >= 2)
        {
          // z = h (1 - s^2): pi int_0^1 (a + c s)^2 2 h s ds, c = b - a.
          const double c = b - a;
          set_shape(model, pump, [&](double s) { return a + c * s; },
                    [&](double s) { return h * (1. - s * s); });
          check_rel(model.enclosed_volume(),
                    2. * M_PI * h * (a * a / 2. + 2. * a * c / 3. + c * c / 4.), 1e-13,
                    "curved meridian z = h (1 - s^2)" + p);
        }
    }

  std::cout << "Computed profiles against the trapezoidal rule in z\n";
  for (const Scene &scene : {pump, paper_scene({1., 3.}, {{5.}})})
    {
      MembraneModel model(scene, FeDiscretization(), NewtonSettings());
      run_to_end(model, scene);
      const double v    = model.enclosed_volume();
      const double v_tr = trapezoid_volume(model, scene, 40000);
      const std::string name = scene.n_rings() == 2 ? "pump scene at 4 / 5 kV" : "full electrode at 5 kV";
      check_rel(v, v_tr, 2e-8, name + ": FE Gauss volume vs trapezoid (40000 points)");
      // The trapezoidal error is O(h^2): halving the points quarters it.
      const double v_coarse = trapezoid_volume(model, scene, 20000);
      check(std::abs(v_coarse - v) > 3. * std::abs(v_tr - v),
            name + ": the trapezoid converges to the FE volume");

      // The shooting model reaches the same state with its own volume quadrature.
      shooting::ShootingModel sh(scene);
      run_to_end(sh, scene);
      check_rel(sh.enclosed_volume(), v, 1e-8, name + ": shooting volume vs FE volume");
    }

  std::cout << "Volume change along the pump path (4 / 4 kV, then outer ring to 5 kV)\n";
  {
    MembraneModel model(pump, FeDiscretization(), NewtonSettings());
    SteppingSettings settings;
    LoadStepper      stepper(pump, model, settings);
    double           v_ref = std::nan(""), v_prev = 0.;
    bool             increasing = true;
    stepper.on_step = [&](const StepSummary &s) {
      const double v = model.enclosed_volume();
      if (s.stage == Stage::dead_load && s.load_factor == 1.)
        v_ref = v;
      if (s.stage == Stage::voltage)
        increasing = increasing && v > v_prev;
      v_prev = v;
    };
    const RunResult result = stepper.run();
    check(result.completed, "pump path completes");
    check(v_ref > 0., "zero-voltage volume recorded at the end of the load stage");
    check(increasing, "the volume grows with every voltage step");
    check(v_prev - v_ref > 0., "volume change at 4 / 5 kV is positive");
  }
  return finish();
}
