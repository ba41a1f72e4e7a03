// The layout optimizer in-process (design/optimize.h):
//  A. the checks of subsection Optimization (messages name the parameter) and
//     the starting layouts (inside the bounds, rings at least w_min wide);
//  B. LayoutEvaluator: a layout reached by continuation in the design
//     variables equals the same layout ramped from zero, and its gradients
//     (stroke, volume change, s2, E) agree with central differences of ramps;
//  C. one ring, voltage free: the optimum is the wrinkling onset of a normal
//     run (s2 = 0 at the disk edge, located by the load stepper), for the
//     stroke and for the enclosed volume change, by SLSQP and by MMA;
//  D. the paper's special case (two rings, inner 5 kV): the optimum lies on
//     the red line of `cdea sweep` (the row at the optimal edge) and no
//     neighbouring row's red line gives more;
//  E. a field limit at a fixed edge is active where it should be.
// The command itself (files, replay by `cdea run`, exit codes, mpirun) is
// tested by tests/optimize_run.sh.

#include <cdea/base/mpi_session.h>
#include <cdea/design/optimize.h>
#include <cdea/input/parameters.h>
#include <cdea/design/sweep.h>

#include "check.h"
#include "scenes.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace cdea;
using namespace cdea_test;

namespace
{
  std::string settings_error(const std::string &entries)
  {
    const auto path = std::filesystem::temp_directory_path() /
                      ("cdea_test_optimize_" + std::to_string(getpid()) + ".prm");
    {
      std::ofstream out(path);
      out << "subsection Optimization\n" << entries << "end\n";
    }
    std::string message;
    try
      {
        const Parameters p = read_parameters(path.string());
        optimization_settings(p, p.scene());
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    std::filesystem::remove(path);
    return message;
  }

  void expect_error(const std::string &entries, const std::string &expected)
  {
    const std::string message = settings_error(entries);
    check(message.find(expected) != std::string::npos,
          "'" + expected + "' in: " + (message.empty() ? "(no error)" : message));
  }

  OptimizationSettings two_rings(const double inner_kV)
  {
    OptimizationSettings s;
    s.n_rings  = 2;
    s.voltages = {inner_kV > 0. ? inner_kV * 1e3 : s.free, s.free};
    s.edges    = {1., s.free, 3.};
    s.starts   = 2;
    return s;
  }

  double relative(const Eigen::VectorXd &a, const Eigen::VectorXd &b)
  {
    return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  const Scene      base; // the paper's actuator

  std::cout << "A. Input checks and starting layouts\n";
  expect_error("  set Rings = 2\n  set Fixed voltages (kV) = 5\n",
               "Optimization/Fixed voltages (kV): 1 entries for 2 rings");
  expect_error("  set Rings = 3\n  set Fixed ring edges (r/a) = 1.5\n",
               "Optimization/Fixed ring edges (r/a): 1 entries for the 2 interior edges");
  expect_error("  set Fixed voltages (kV) = 5, fre\n",
               "Optimization/Fixed voltages (kV): 'fre' is not a number");
  expect_error("  set Edge bounds (r/a) = 2, 1.5\n",
               "Optimization/Edge bounds (r/a): the lower bound 2 must be below");
  expect_error("  set Edge bounds (r/a) = 0.5, 2\n", "must lie inside [1, b/a = 3]");
  expect_error("  set Voltage bounds (kV) = -1, 8\n",
               "Optimization/Voltage bounds (kV): the lower bound must not be negative");
  expect_error("  set Maximum field (MV/m) = -3\n",
               "Optimization/Maximum field (MV/m) must be positive or 'inf'");
  expect_error("  set Rings = 8\n  set Minimum ring width (mm) = 4\n",
               "Optimization/Minimum ring width (mm): 8 rings of 4 mm do not fit");
  expect_error("  set Fixed voltages (kV) = 5, 6\n  set Fixed ring edges (r/a) = 1.7\n",
               "Optimization: nothing to optimise");
  expect_error("  set Fixed ring edges (r/a) = 3.5\n",
               "Optimization/Fixed ring edges (r/a): 3.5 is not inside (1, 3)");
  check(settings_error("  set Rings = 3\n  set Fixed voltages (kV) = free\n"
                       "  set Fixed ring edges (r/a) = 1.6, free\n") == "",
        "a valid mixed input is accepted");
  {
    OptimizationSettings s;
    s.n_rings        = 6;
    s.voltages       = std::vector<double>(6, s.free);
    s.edges          = {1., s.free, s.free, 1.9, s.free, s.free, 3.};
    s.edge_lower     = 1.1;
    s.edge_upper     = 2.9;
    s.min_ring_width = 0.12;
    s.starts         = 9;
    bool ok          = true;
    for (const Layout &l : starting_layouts(s))
      {
        ok = ok && l.edges[3] == 1.9;
        for (unsigned int k = 0; k < 6; ++k)
          ok = ok && l.edges[k + 1] - l.edges[k] >= s.min_ring_width - 1e-12 &&
               l.voltages[k] >= s.voltage_lower && l.voltages[k] <= s.voltage_upper;
        for (unsigned int k = 1; k < 6; ++k)
          ok = ok && l.edges[k] >= s.edge_lower && l.edges[k] <= s.edge_upper;
      }
    check(ok, "9 starting layouts of 6 rings: fixed edge kept, bounds and widths hold");
  }

  std::cout << "B. Continuation in the design variables against ramps from zero\n";
  {
    const OptimizationSettings s = two_rings(0.);
    const auto                 free = s.free_parameters();
    LayoutEvaluator            by_continuation(base, s, FeDiscretization(), NewtonSettings(),
                                               SteppingSettings());
    LayoutEvaluator            by_ramp(base, s, FeDiscretization(), NewtonSettings(),
                                       SteppingSettings());
    by_continuation.ramp({{1., 1.5, 3.}, {4.5e3, 5.0e3}});
    const Layout           target{{1., 1.8, 3.}, {5.2e3, 6.3e3}};
    const LayoutEvaluation a = by_continuation.evaluate(target);
    const LayoutEvaluation b = by_ramp.ramp(target);
    check(a.ok && b.ok, "both reach the layout");
    check_close(std::abs(a.stroke / b.stroke - 1.), 0., 1e-9, "stroke, relative");
    check_close(relative(a.points.s2, b.points.s2), 0., 1e-8, "s2 at every point");
    check_close(relative(a.d_stroke, b.d_stroke), 0., 1e-7, "stroke gradient");
    check_close(relative(a.points.d_s2.col(2), b.points.d_s2.col(2)), 0., 1e-7,
                "s2 gradient by the edge");

    // Gradients against central differences of ramps (steps 0.05 V, 1e-6 r/a).
    for (unsigned int j = 0; j < free.size(); ++j)
      {
        const double h     = free[j].kind == ParameterKind::voltage ? 0.05 : 1e-6;
        Layout       plus  = target, minus = target;
        auto         v     = target.free_values(free);
        v[j] += h;
        plus.set_free_values(free, v);
        v[j] -= 2. * h;
        minus.set_free_values(free, v);
        const LayoutEvaluation p = by_ramp.ramp(plus), m = by_ramp.ramp(minus);
        const double fd_stroke = (p.stroke - m.stroke) / (2. * h);
        const double fd_volume = (p.volume_change - m.volume_change) / (2. * h);
        check_close(std::abs(fd_stroke / b.d_stroke[j] - 1.), 0., 1e-6,
                    "d stroke / d " + free[j].name());
        check_close(std::abs(fd_volume / b.d_volume_change[j] - 1.), 0., 1e-6,
                    "d volume change / d " + free[j].name());
        check_close(relative(b.points.d_field.col(j), (p.points.field - m.points.field) / (2. * h)),
                    0., 1e-6, "d E / d " + free[j].name() + " at every point");
      }
  }

  std::cout << "C. One ring, voltage free: the wrinkling onset\n";
  {
    OptimizationSettings s;
    s.n_rings  = 1;
    s.voltages = {s.free};
    s.edges    = {1., 3.};
    s.starts   = 1;
    LayoutEvaluator   evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
    const StartResult r = optimize_from(base, s, evaluator, 0, starting_layouts(s)[0]);
    check(r.converged, "converged: " + r.status);

    Scene            scene = paper_scene({1., 3.}, {{6.}});
    SteppingSettings onset;
    onset.onset_tolerance = 1e-6;
    MembraneModel model(scene, FeDiscretization(), NewtonSettings());
    LoadStepper   stepper(scene, model, onset);
    const RunResult run = stepper.run();
    check(run.onset.found, "the run to 6 kV finds the onset");
    check_close(r.best.voltages[0], run.onset.voltages[0], 2e-3,
                "optimum voltage = onset voltage (V)");
    check(r.active.size() == 1 && r.active[0].find("inner edge of ring 1") != std::string::npos,
          "the active constraint is s2 at the disk edge");

    // The pump's objective: the enclosed volume grows with the voltage too.
    s.objective = DesignObjective::volume_change;
    const StartResult v = optimize_from(base, s, evaluator, 0, starting_layouts(s)[0]);
    check(v.converged, "volume change: converged: " + v.status);
    check_close(v.best.voltages[0], run.onset.voltages[0], 2e-3,
                "volume change: optimum voltage = onset voltage (V)");
    check_close(v.objective, v.at_best.volume_change * 1e6, 1e-12,
                "volume change objective in units of 1000 mm^3");

    // The other algorithm.
    s.objective = DesignObjective::stroke;
    s.algorithm = DesignAlgorithm::mma;
    const StartResult w = optimize_from(base, s, evaluator, 0, starting_layouts(s)[0]);
    check(w.converged, "MMA: converged: " + w.status);
    check_close(w.best.voltages[0], run.onset.voltages[0], 2e-3,
                "MMA: optimum voltage = onset voltage (V)");
  }

  std::cout << "D. The paper's case: inner ring at 5 kV, edge and outer voltage free\n";
  {
    const OptimizationSettings s = two_rings(5.);
    LayoutEvaluator   evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
    const StartResult r = optimize_from(base, s, evaluator, 0, starting_layouts(s)[0]);
    check(r.converged, "converged: " + r.status);
    const double rv = r.best.edges[1];

    // The red line of the sweep at r_v and its neighbours.
    SweepSettings sweep;
    sweep.inner_voltage = 5e3;
    sweep.outer_from    = 6e3;
    sweep.outer_to      = 6.8e3;
    sweep.outer_step    = 0.1e3;
    for (double v = 6e3; v <= 6.8e3 + 1.; v += 100.)
      sweep.outer_voltages.push_back(v);
    sweep.line_tolerance = 1e-4;
    const double zero = zero_voltage_displacement(base, FeDiscretization(), NewtonSettings(),
                                                  SteppingSettings());
    std::vector<double> stroke;
    for (const double e : {rv - 0.02, rv, rv + 0.02})
      {
        const Scene   scene = sweep_scene(base, e, 5e3);
        MembraneModel model(scene, FeDiscretization(), NewtonSettings());
        const SweepRow row =
          compute_sweep_row(model, scene, sweep, SteppingSettings(), zero);
        stroke.push_back(row.red.displacement - zero);
        if (e == rv)
          check_close(row.red.outer_voltage, r.best.voltages[1], 2e-3,
                      "the optimum's outer voltage is on the red line (V)");
      }
    check_close(stroke[1], r.at_best.stroke, 1e-9, "stroke = red-line stroke at r_v (m)");
    check(stroke[0] < stroke[1] && stroke[2] < stroke[1],
          "neighbouring red-line strokes (r_v -+ 0.02) are smaller");

    // The multistart of prm/optimize-paper.prm (4 starts): the chosen
    // optimum is feasible, so that its replay by `cdea run` is not wrinkled.
    std::vector<StartResult> starts;
    OptimizationSettings     four = s;
    four.starts                   = 4;
    const auto layouts            = starting_layouts(four);
    for (unsigned int k = 0; k < layouts.size(); ++k)
      starts.push_back(optimize_from(base, four, evaluator, k, layouts[k]));
    const StartResult &chosen = starts[best_start(starts)];
    check(chosen.converged, "4 starts: the chosen one converged");
    check(chosen.at_best.points.s2.minCoeff() >= 0. && chosen.at_best.points.s2.minCoeff() < 1e-3,
          "4 starts: the chosen optimum has 0 <= min s2 < 1e-3 Pa (feasible, s2 = 0 active): " +
            std::to_string(chosen.at_best.points.s2.minCoeff()) + " Pa");
  }

  std::cout << "D2. Starts at the same optimum: the feasible one is chosen\n";
  {
    // Objectives equal to 2e-8 (relative): the one a little outside the
    // feasible set must not win over the feasible one; a clearly larger
    // objective still wins.
    StartResult outside, inside, worse;
    for (StartResult *r : {&outside, &inside, &worse})
      {
        r->converged  = true;
        r->at_best.ok = true;
        r->optimality = 1e-8;
      }
    outside.objective        = 8.755678149853;
    outside.worst_constraint = 9.1e-8;
    inside.objective         = 8.755677967702;
    inside.worst_constraint  = -1e-9;
    worse.objective          = 8.7;
    worse.worst_constraint   = -0.5;
    check(best_start({outside, inside, worse}) == 1 && best_start({inside, outside}) == 0,
          "the feasible start of two at the same optimum");
    inside.objective = 8.7556;
    check(best_start({outside, inside}) == 0, "a larger objective (by 1e-5) still wins");
  }

  std::cout << "E. A field limit at a fixed edge\n";
  {
    OptimizationSettings s = two_rings(5.);
    s.edges                = {1., 1.8, 3.};
    s.max_field            = 59e6;
    LayoutEvaluator   evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
    const StartResult r = optimize_from(base, s, evaluator, 0, starting_layouts(s)[0]);
    check(r.converged, "converged: " + r.status);
    check_close(r.at_best.points.field.maxCoeff(), 59e6, 1e2, "largest field = the limit (V/m)");
    check(r.at_best.points.s2.minCoeff() > 0., "s2 > 0 everywhere (the field limit binds first)");
  }
  return finish();
}
