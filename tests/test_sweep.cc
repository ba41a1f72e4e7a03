// `cdea sweep` in-process:
//  A. the value lists and the checks of the subsection Sweep (messages name
//     the parameter);
//  B. a small map (3 r_v/a x 5 outer voltages, one of them below the inner
//     voltage) against the shooting model, each point of which is loaded from
//     scratch along the path "both rings to 5 kV, then the outer one";
//  C. the red and blue lines against independent root solves: plain bisection
//     to 1 mV with the shooting model (another solver, another root finder)
//     and with the FE model of the same discretization (which isolates the
//     0.1 V tolerance of the sweep's bracketed root search);
//  D. the row distribution over ranks.
// The serial-vs-mpirun identity and the command's bad-input handling are in
// tests/sweep_mpi.sh and tests/sweep_bad_input.sh.

#include <cdea/input/solver_settings.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameters.h>
#include <cdea/design/sweep.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/shooting_model.h>

#include "check.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <set>
#include <string>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// A parameter file with the given Sweep entries (paper's actuator otherwise).
  std::string write_prm(const std::string &name, const std::string &edges,
                        const std::string &inner, const std::string &range,
                        const std::string &extra = "")
  {
    const auto path = std::filesystem::temp_directory_path() /
                      ("cdea_test_sweep_" + std::to_string(getpid()) + "_" + name + ".prm");
    std::ofstream out(path);
    out << "subsection Sweep\n"
        << "  set Ring edge values (r/a)   = " << edges << "\n"
        << "  set Inner voltage (kV)       = " << inner << "\n"
        << "  set Outer voltage range (kV) = " << range << "\n"
        << "end\n"
        << extra;
    return path.string();
  }

  /// The InputError message of reading and checking the sweep input ("" if none).
  std::string sweep_error(const std::string &edges, const std::string &inner,
                          const std::string &range, const std::string &extra = "")
  {
    const std::string file = write_prm("error", edges, inner, range, extra);
    std::string       message;
    try
      {
        const Parameters p = read_parameters(file);
        sweep_settings(p, p.scene());
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    std::filesystem::remove(file);
    return message;
  }

  void expect_error(const std::string &edges, const std::string &inner, const std::string &range,
                    const std::string &expected)
  {
    const std::string message = sweep_error(edges, inner, range);
    check(message.find(expected) != std::string::npos,
          "rejected (edges '" + edges + "', inner '" + inner + "', range '" + range +
            "'): message '" + message + "' contains '" + expected + "'");
  }

  bool list_error(const std::string &text, const std::string &expected)
  {
    std::string message;
    try
      {
        expand_value_list(text, "List");
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    return check(message.find(expected) != std::string::npos,
                 "'" + text + "' rejected: '" + message + "'");
  }

  /// Shooting model loaded from scratch: both rings to @p inner, then the
  /// outer ring to @p outer (volts). Returns the last step; stroke from its
  /// own dead-load state.
  StepSummary shooting_point(const Scene &base, const double rv, const double inner,
                             const double outer)
  {
    Scene scene = sweep_scene(base, rv, inner);
    scene.path  = VoltagePath(std::vector<std::vector<double>>{{inner, inner}, {inner, outer}});
    shooting::ShootingModel model(scene);
    LoadStepper             stepper(scene, model, SteppingSettings());
    StepSummary             last;
    stepper.on_step = [&](const StepSummary &s) { last = s; };
    const RunResult result = stepper.run();
    if (!result.completed)
      throw std::runtime_error("shooting reference did not complete: " + result.message);
    return last;
  }

  /// Root of a line function by bisection to @p tol volts along the outer
  /// voltage, with @p model (any EquilibriumModel of @p scene): load to both
  /// rings at the inner voltage, march up in 25 V steps to a sign change,
  /// then bisect, each solve starting from the bracket's lower converged state.
  struct Root
  {
    double voltage = std::numeric_limits<double>::quiet_NaN();
    double displacement = std::numeric_limits<double>::quiet_NaN();
  };
  Root bisect_line(EquilibriumModel &model, const Scene &scene, const double inner,
                   const std::function<double(const StepSummary &)> &f, const double tol)
  {
    LoadStepper stepper(scene, model, SteppingSettings());
    if (!stepper.run().completed)
      throw std::runtime_error("base state not reached");
    LoadState load = stepper.load(Stage::voltage, 1.);
    auto      at   = [&](const double v) {
      load.voltages = {inner, v};
      if (!model.solve(load).converged)
        throw std::runtime_error("bisection: solve failed at " + std::to_string(v) + " V");
      return f(model.summary());
    };
    double              lo = inner, f_lo = f(model.summary());
    ModelState          state_lo = model.state();
    double              hi       = lo;
    for (;;)
      {
        hi             = lo + 25.;
        const double g = at(hi);
        if ((g < 0.) != (f_lo < 0.))
          break;
        lo       = hi;
        f_lo     = g;
        state_lo = model.state();
        if (lo > inner + 3000.)
          return Root();
      }
    while (hi - lo > tol)
      {
        const double mid = 0.5 * (lo + hi);
        model.set_state(state_lo);
        const double g = at(mid);
        if ((g < 0.) == (f_lo < 0.))
          {
            lo       = mid;
            state_lo = model.state();
          }
        else
          hi = mid;
      }
    Root r;
    r.voltage = 0.5 * (lo + hi);
    model.set_state(state_lo);
    at(r.voltage);
    r.displacement = model.summary().displacement;
    return r;
  }

  double red(const StepSummary &s) { return s.s2_ring_inner[1]; }
  double blue(const StepSummary &s) { return s.s2_ring_inner[0] - s.s2_ring_inner[1]; }

  double seconds_since(const std::chrono::steady_clock::time_point t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  out() << "A. value lists and sweep input\n";
  {
    const auto v = expand_value_list("1.2, 1.25, ..., 1.4", "List");
    check(v == std::vector<double>{1.2, 1.25, 1.3, 1.35, 1.4},
          "'1.2, 1.25, ..., 1.4' gives exactly 1.2, 1.25, 1.3, 1.35, 1.4");
    const auto w = expand_value_list("1.6, 1.7, ..., 2, 2.5", "List");
    check(w == std::vector<double>{1.6, 1.7, 1.8, 1.9, 2., 2.5},
          "'1.6, 1.7, ..., 2, 2.5' gives exactly 1.6, 1.7, 1.8, 1.9, 2, 2.5");
    check(expand_value_list("1.2, 1.25, ..., 2.6", "List").size() == 29,
          "the paper's 1.2, 1.25, ..., 2.6 has 29 values");
    check(expand_value_list(" 1.5 ", "List") == std::vector<double>{1.5}, "a single value");
    list_error("1.2, ..., 2", "'...' needs two numbers before it");
    list_error("1.2, 1.3, ...", "'...' needs two numbers before it and one after it");
    list_error("1.2, 1.25, ..., 1.33", "1.33 after '...' is not on the sequence");
    list_error("1.2, 1.2, ..., 2", "the two values before '...' are equal");
    list_error("1.2, 1.3, ..., 1.1", "1.1 after '...' does not continue 1.2, 1.3");
    list_error("1.2, , 1.3", "empty entry");
    list_error("1.2, x", "'x' is not a number");

    expect_error("1.2, 3.2", "5", "5, 8, 0.05",
                 "Sweep/Ring edge values (r/a): 3.2 is not inside (1, 3)");
    expect_error("1, 1.5", "5", "5, 8, 0.05",
                 "Sweep/Ring edge values (r/a): 1 is not inside (1, 3)");
    expect_error("1.5, 3", "5", "5, 8, 0.05",
                 "Sweep/Ring edge values (r/a): 3 is not inside (1, 3)");
    expect_error("1.7, 1.5", "5", "5, 8, 0.05",
                 "Sweep/Ring edge values (r/a): values must increase strictly, but 1.5 follows 1.7");
    expect_error("1.5", "5", "8, 5, 0.05",
                 "Sweep/Outer voltage range (kV): the range is empty: 'to' (5) is below 'from' (8)");
    expect_error("1.5", "5", "5, 8, -0.05",
                 "Sweep/Outer voltage range (kV): the step must be positive, got -0.05");
    expect_error("1.5", "5", "5, 8, 0", "Sweep/Outer voltage range (kV): the step must be positive");
    expect_error("1.5", "5", "5, 8", "Sweep/Outer voltage range (kV): expected three numbers");
    expect_error("1.5", "5", "-1, 8, 0.5", "Sweep/Outer voltage range (kV): voltages must not be negative");
    expect_error("1.5", "0", "5, 8, 0.5", "Sweep/Inner voltage (kV) must be positive");
    for (const auto &[extra, expected] :
         {std::pair<std::string, std::string>{"subsection Wrinkling\n  set Model = relaxed\nend\n",
                                              "Wrinkling/Model = relaxed is not supported by cdea sweep"},
          {"subsection Reservoir\n  set Water load = true\nend\n",
           "Reservoir/Water load = true is not supported by cdea sweep"}})
      {
        const std::string message = sweep_error("1.5", "5", "5, 8, 0.5", extra);
        check(message.find(expected) != std::string::npos,
              "rejected: '" + message + "' contains '" + expected + "'");
      }

    const std::string file = write_prm("grid", "1.2, 1.25, ..., 2.6", "5", "5, 8, 0.05");
    const Parameters  p    = read_parameters(file);
    std::filesystem::remove(file);
    const SweepSettings s = sweep_settings(p, p.scene());
    check(s.outer_voltages.size() == 61, "5, 8, 0.05 kV gives 61 outer voltages");
    check(s.outer_voltages[30] == 6500. && s.outer_voltages.back() == 8000. &&
            s.outer_voltages[1] == 5050.,
          "grid values are exact: 5050, 6500, 8000 V");
    check(s.inner_voltage == 5000., "inner voltage 5000 V");
    check(sweep_error("1.5", "5", "5, 5, 0.1").empty(), "a one-point range is accepted");
  }

  out() << "D. rows over ranks (round-robin, every row once)\n";
  {
    bool ok = true;
    for (unsigned int size : {1u, 2u, 3u, 7u, 40u})
      {
        std::multiset<std::size_t> all;
        for (unsigned int r = 0; r < size; ++r)
          for (const std::size_t i : rows_of_rank(29, r, size))
            {
              all.insert(i);
              ok = ok && i % size == r;
            }
        ok = ok && all.size() == 29 && std::set<std::size_t>(all.begin(), all.end()).size() == 29;
      }
    check(ok, "rows_of_rank: each of 29 rows on exactly one rank, row i on rank i mod size");
  }

  out() << "B. small map (3 x 5) against the shooting model\n";
  const std::string file = write_prm("map", "1.4, 1.7, 2", "5", "4.8, 6.8, 0.5");
  const Parameters  p    = read_parameters(file);
  std::filesystem::remove(file);
  const Scene         base     = p.scene();
  const SweepSettings settings = sweep_settings(p, base);
  auto                t0       = std::chrono::steady_clock::now();
  const SweepMap      map      = compute_sweep_map(p, base, settings);
  out() << "  FE map: " << seconds_since(t0) << " s\n";
  check(map.rows.size() == 3 && settings.outer_voltages.size() == 5, "3 x 5 map");
  const double mu = base.material.shear_modulus;
  {
    // Zero-voltage displacement: the model notes' reference value, and the
    // same state on each row's own two-ring mesh (it is computed once, on the
    // full-electrode mesh).
    check_rel(map.zero_voltage_displacement, 18.24876e-3, 2e-6,
              "zero-voltage displacement vs model notes (18.24876 mm)");
    double worst_zero = 0.;
    for (const double rv : settings.ring_edge_values)
      {
        const Scene   scene = sweep_scene(base, rv, 0.);
        MembraneModel fe(scene, fe_discretization(p), newton_settings(p));
        LoadStepper   stepper(scene, fe, sweep_stepping_settings(p));
        stepper.run();
        worst_zero = std::max(worst_zero, std::abs(fe.summary().displacement -
                                                   map.zero_voltage_displacement));
      }
    check_close(worst_zero * 1e3, 0., 1e-6,
                "zero-voltage displacement on the rows' meshes vs the one used, mm");
    t0 = std::chrono::steady_clock::now();
    double worst_d = 0., worst_inc = 0., worst_s2 = 0.;
    for (const SweepRow &row : map.rows)
      {
        check(row.message.empty(), "r_v/a = " + std::to_string(row.rv_over_a) +
                                     ": continuation reached the whole range");
        const StepSummary sh_base = shooting_point(base, row.rv_over_a, 5e3, 5e3);
        for (std::size_t k = 0; k < settings.outer_voltages.size(); ++k)
          {
            const double      v  = settings.outer_voltages[k];
            const StepSummary sh = shooting_point(base, row.rv_over_a, 5e3, v);
            const double inc_sh  = 100. * (sh.stroke / sh_base.stroke - 1.);
            worst_d   = std::max(worst_d, std::abs(row.displacement[k] / sh.displacement - 1.));
            worst_inc = std::max(worst_inc, std::abs(row.stroke_increase[k] - inc_sh));
            worst_s2  = std::max({worst_s2, std::abs(row.s2_inner_ring1[k] - sh.s2_ring_inner[0]),
                                 std::abs(row.s2_inner_ring2[k] - sh.s2_ring_inner[1])});
            if (row.rv_over_a == 1.7 && v == 5.8e3)
              {
                out() << "  point r_v/a 1.7, 5.8 kV: FE " << row.displacement[k] * 1e3
                      << " mm, shooting " << sh.displacement * 1e3 << " mm\n";
              }
          }
      }
    out() << "  shooting references: " << seconds_since(t0) << " s\n";
    check_close(worst_d, 0., 2e-6, "displacement, largest relative FE - shooting difference");
    check_close(worst_inc, 0., 2e-3,
                "stroke increase, largest FE - shooting difference (percentage points)");
    check_close(worst_s2 / mu, 0., 5e-4,
                "s2 at both ring inner edges, largest |FE - shooting| / mu");
  }

  out() << "C. red and blue lines against independent root solves\n";
  t0 = std::chrono::steady_clock::now();
  for (const SweepRow &row : map.rows)
    {
      const Scene       scene = sweep_scene(base, row.rv_over_a, 5e3);
      const std::string at    = "r_v/a = " + std::to_string(row.rv_over_a).substr(0, 4);
      for (const bool is_red : {true, false})
        {
          const SweepLine  &line = is_red ? row.red : row.blue;
          const std::string name = at + (is_red ? ", red line" : ", blue line");
          const auto        f    = is_red ? red : blue;
          // Same FE discretization: isolates the root finder (0.1 V).
          MembraneModel fe(scene, fe_discretization(p), newton_settings(p));
          const Root    fe_root = bisect_line(fe, scene, 5e3, f, 1e-3);
          check_close(line.outer_voltage, fe_root.voltage, settings.line_tolerance,
                      name + ": sweep (bracketed root, 0.1 V) vs FE bisection (1 mV), V");
          check(line.bracket_width <= settings.line_tolerance * 1.000001,
                name + ": final bracket " + std::to_string(line.bracket_width) + " V <= 0.1 V");
          // Another solver and another root finder.
          shooting::ShootingModel sh(scene);
          const Root              sh_root = bisect_line(sh, scene, 5e3, f, 1e-3);
          check_close(line.outer_voltage, sh_root.voltage, 0.15,
                      name + ": sweep vs shooting bisection, V");
          const StepSummary sh_base = shooting_point(base, row.rv_over_a, 5e3, 5e3);
          const double      sh_zero = sh_base.displacement - sh_base.stroke;
          const double      sh_inc =
            100. * ((sh_root.displacement - sh_zero) / sh_base.stroke - 1.);
          check_close(line.stroke_increase, sh_inc, 0.01,
                      name + ": stroke increase on the line vs shooting (percentage points)");
          if (is_red)
            check_close(line.s2_inner[1] / mu, 0., 1e-4, name + ": s2/mu at r_v is 0 there");
          else
            check_close((line.s2_inner[0] - line.s2_inner[1]) / mu, 0., 1e-4,
                        name + ": s2 equal at both inner edges there");
        }
    }
  out() << "  root solves: " << seconds_since(t0) << " s\n";
  check_close(map.rows[1].red.outer_voltage, 6485.3, 0.2,
              "r_v/a = 1.7: red line at 6.4853 kV (known value)");

  out() << "E. inner 5.5 kV (inner ring already wrinkled) and a fold inside the range\n";
  {
    const std::string f55 = write_prm("inner55", "1.7", "5.5", "5.5, 7, 0.5");
    const Parameters  q   = read_parameters(f55);
    std::filesystem::remove(f55);
    const SweepSettings s55 = sweep_settings(q, base);
    const SweepMap      m55 = compute_sweep_map(q, base, s55);
    const SweepRow     &row = m55.rows.at(0);
    check(row.base_s2_inner[0] < 0. && row.base_s2_inner[1] > 0.,
          "both rings at 5.5 kV: s2 < 0 at the disk edge, > 0 at r_v");
    const Scene   scene = sweep_scene(base, 1.7, 5.5e3);
    MembraneModel fe(scene, fe_discretization(q), newton_settings(q));
    check_close(row.red.outer_voltage, bisect_line(fe, scene, 5.5e3, red, 1e-3).voltage,
                s55.line_tolerance, "red line (outer ring's edge) vs FE bisection, V");
    shooting::ShootingModel sh(scene);
    check_close(row.blue.outer_voltage, bisect_line(sh, scene, 5.5e3, blue, 1e-3).voltage, 0.15,
                "blue line (equal negative s2) vs shooting bisection, V");
    check(row.blue.s2_inner[0] < 0. && row.blue.outer_voltage > row.red.outer_voltage,
          "blue line beyond the red one, at a negative common s2");

    // r_v/a = 1.2 folds near 6.79 kV: 7 and 7.5 kV are not reached.
    const std::string ff = write_prm("fold", "1.2", "5", "6.5, 7.5, 0.5");
    const Parameters  r  = read_parameters(ff);
    std::filesystem::remove(ff);
    const SweepMap  mf   = compute_sweep_map(r, base, sweep_settings(r, base));
    const SweepRow &fold = mf.rows.at(0);
    check(!std::isnan(fold.displacement[0]) && std::isnan(fold.displacement[1]) &&
            std::isnan(fold.displacement[2]) && std::isnan(fold.stroke_increase[2]) &&
            std::isnan(fold.s2_inner_ring2[1]),
          "r_v/a = 1.2: 6.5 kV reached, 7 and 7.5 kV NaN");
    check(fold.message.find("no equilibrium found beyond 6.7") != std::string::npos,
          "the stop is recorded: '" + fold.message + "'");
    check(fold.highest_voltage == 6500., "highest reached grid voltage 6.5 kV");
    bool shooting_failed = false;
    try
      {
        shooting_point(base, 1.2, 5e3, 7e3);
      }
    catch (const std::exception &)
      {
        shooting_failed = true;
      }
    check(shooting_failed, "the shooting model cannot reach (5, 7) kV at r_v/a = 1.2 either");
  }
  return finish();
}
