// Beyond the first failure: arc-length continuation through the fold of the
// full-electrode curve, the limit point against the shooting model traced by
// its angle, stability (smallest tangent eigenvalue) on both sides of the fold,
// and the relaxed (tension-field) membrane: equal to the plain one where
// nothing wrinkles, its FE tangent against finite differences in a wrinkled
// state, and the detection of its loss of ellipticity at the onset.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/angle_trace.h>
#include <cdea/shooting/shooting_model.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <iostream>

using namespace cdea;
using namespace cdea_test;

namespace
{
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  const Scene      scene = paper_scene({1., 3.}, {{8.}});

  std::cout << "Arc length through the full-electrode fold\n";
  SteppingSettings arc;
  arc.arc_length       = true;
  arc.max_displacement = 0.040; // stop on the unstable branch, past the fold
  arc.stability_check  = true;
  MembraneModel fe(scene, discretization(4, 16), NewtonSettings());
  const RunTrace t = trace_run(fe, scene, arc);
  check(t.result.completed && t.result.end.find("displacement") != std::string::npos,
        "arc length passes the fold and ends at the displacement limit: " + t.result.end);
  check(t.result.limit_points.size() == 1, "exactly one limit point before 40 mm");

  // The reference: the shooting model traced by its angle from its 6 kV state.
  shooting::ShootingModel sh(scene);
  {
    SteppingSettings plain;
    LoadStepper      stepper(scene, sh, plain);
    sh.set_reference_state();
    sh.solve(stepper.load(Stage::prestretch, 1.));
    for (int k = 1; k <= 10; ++k)
      sh.solve(stepper.load(Stage::dead_load, 0.1 * k));
    for (int k = 1; k <= 24; ++k)
      sh.solve(stepper.load(Stage::voltage, 0.75 * k / 24.));
  }
  const shooting::AngleTrace trace(scene, shooting::ShootingOptions());
  const auto                 start = trace.solve(sh.shooting_angle(), 0.75, sh.profile().lambda1_start);
  const auto                 fold  = trace.limit_point(start, 0.01);
  check(fold.has_value(), "shooting angle trace finds the fold");
  if (fold && !t.result.limit_points.empty())
    {
      const LimitPoint &lp = t.result.limit_points.front();
      check_close(lp.voltages[0], fold->t * 8e3, 1e-3,
                  "limit-point voltage (V): FE arc length vs shooting by angle");
      check_rel(lp.displacement, fold->displacement, 1e-5,
                "limit-point displacement: FE arc length vs shooting by angle");
    }

  // Stability: stable up to the fold, unstable after it (same branch).
  double last_before = NAN, first_after = NAN;
  bool   passed      = false, all_stable_before = true;
  for (const StepSummary &s : t.steps)
    {
      if (s.stage != Stage::voltage)
        continue;
      if (!t.result.limit_points.empty() &&
          std::abs(s.load_factor - t.result.limit_points[0].load_factor) < 1e-12 &&
          std::abs(s.displacement - t.result.limit_points[0].displacement) < 1e-12)
        {
          passed = true;
          continue;
        }
      if (!passed)
        {
          all_stable_before = all_stable_before && s.min_eigenvalue > 0.;
          last_before       = s.min_eigenvalue;
        }
      else if (std::isnan(first_after))
        first_after = s.min_eigenvalue;
    }
  check(all_stable_before && last_before > 0., "every state before the fold is stable");
  check(first_after < 0., "the state after the fold is unstable (min eigenvalue < 0)");

  // The banded LAPACK eigenvalue against a dense solve of the same tangent.
  {
    const auto                K = fe.tangent_matrix();
    std::vector<unsigned int> free;
    const auto                support = fe.dof_support();
    const double              A = scene.inner_reference_radius(), B = scene.outer_reference_radius();
    for (unsigned int i = 0; i < K.size(); ++i)
      {
        const bool at_A = std::abs(support[i].first - A) < 1e-12 * B;
        const bool at_B = std::abs(support[i].first - B) < 1e-12 * B;
        // Constrained: r at both ends, z at the frame.
        if (!((at_A && support[i].second == 0) || at_B))
          free.push_back(i);
      }
    Eigen::MatrixXd Kf(free.size(), free.size());
    for (unsigned int i = 0; i < free.size(); ++i)
      for (unsigned int j = 0; j < free.size(); ++j)
        Kf(i, j) = 0.5 * (K[free[i]][free[j]] + K[free[j]][free[i]]);
    const double dense =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Kf, Eigen::EigenvaluesOnly).eigenvalues()(0);
    check_rel(fe.min_tangent_eigenvalue(), dense, 1e-9,
              "smallest eigenvalue: banded LAPACK vs dense Eigen");
  }

  std::cout << "Load stepping stops at the fold, arc length goes on\n";
  {
    MembraneModel fe_ls(scene, discretization(4, 16), NewtonSettings());
    const RunTrace ls = trace_run(fe_ls, scene, SteppingSettings());
    check(!ls.result.completed, "load stepping stops before 8 kV");
    if (!t.result.limit_points.empty())
      check(ls.steps.back().voltages[0] <= t.result.limit_points[0].voltages[0] + 1e-6 &&
              ls.steps.back().voltages[0] > t.result.limit_points[0].voltages[0] - 5.,
            "load stepping stops within 5 V below the limit point");
  }

  std::cout << "Relaxed membrane\n";
  {
    const Scene   five = paper_scene({1., 1.7, 3.}, {{5., 5.}});
    MembraneModel plain(five, discretization(3, 8), NewtonSettings());
    MembraneModel relaxed(five, discretization(3, 8), NewtonSettings());
    relaxed.set_relaxed(true);
    const RunTrace a = trace_run(plain, five, SteppingSettings());
    const RunTrace b = trace_run(relaxed, five, SteppingSettings());
    check(a.result.completed && b.result.completed, "both runs reach (5, 5) kV");
    check_close(b.steps.back().displacement, a.steps.back().displacement, 0.,
                "no wrinkles: relaxed displacement equals the plain one exactly");
    check(std::isnan(b.steps.back().wrinkled_zone_inner), "no wrinkled zone reported");
  }
  {
    // A wrinkled state: the plain equilibrium at 5.6 kV has s2 < 0 next to
    // the disk; switch the relaxation on and compare the relaxed residual and
    // tangent with finite differences there (not an equilibrium of it).
    const Scene   charged = paper_scene({1., 3.}, {{5.6}});
    MembraneModel model(charged, discretization(3, 8), NewtonSettings());
    run_to_end(model, charged);
    model.set_relaxed(true);
    const StepSummary s = model.summary();
    check(s.wrinkled_zone_inner > 0. && s.wrinkled_zone_outer > s.wrinkled_zone_inner,
          "a wrinkled zone of finite width next to the disk");
    check_derivatives(model, "relaxed FE, wrinkled state", true, 1e-8, 1e-5);
    check(!s.validity_limit.empty() &&
            s.validity_limit.find("ellipticity") != std::string::npos,
          "the wrinkled state is flagged: relaxed law not elliptic there");
  }
  {
    // A relaxed run stops where the relaxed law loses ellipticity, which in
    // this actuator is at the onset itself (model-notes: electrical loss of
    // tension), and says where.
    const Scene   charged = paper_scene({1., 3.}, {{6.}});
    MembraneModel model(charged, discretization(3, 8), NewtonSettings());
    model.set_relaxed(true);
    const RunTrace r = trace_run(model, charged, SteppingSettings());
    check(!r.result.completed, "relaxed run to 6 kV stops");
    check(r.result.message.find("ellipticity") != std::string::npos &&
            r.result.message.find("r/a = 1") != std::string::npos,
          "it says why and where: " + r.result.message.substr(0, 120));
    check(r.result.onset.found && std::abs(r.result.onset.voltages[0] - 5382.41) < 0.1,
          "the onset (5.38241 kV) is located before it stops");
    check(r.steps.back().voltages[0] - r.result.onset.voltages[0] < 1e-2,
          "the last valid state lies within 10 mV of the onset");
  }
  return finish();
}
