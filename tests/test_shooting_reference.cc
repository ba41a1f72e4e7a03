// The shooting model against the public reference values of the model notes
// (independent shooting implementation, about 1e-7 relative), reached by
// continuation from the flat pre-stretched film, plus consistency checks of
// the profile: first integral, boundary condition, ring-edge jump, tolerance
// convergence and state save/restore.

#include <cdea/model/scene.h>
#include <cdea/shooting/shooting_model.h>

#include "check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

using namespace cdea;
using namespace cdea::shooting;
using cdea_test::check;
using cdea_test::check_close;
using cdea_test::check_rel;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  bool solve_or_report(ShootingModel &model, const LoadState &load)
  {
    const SolveReport r = model.solve(load);
    if (!r.converged)
      std::cout << "  solve failed: " << r.message << "\n";
    return r.converged;
  }

  /// Flat pre-stretched film, then the dead load in 10 steps.
  bool load_up(ShootingModel &model, const Scene &scene)
  {
    const unsigned int n = scene.n_rings();
    model.set_reference_state();
    LoadState load;
    load.voltages.assign(n, 0.);
    for (unsigned int k = 1; k <= 3; ++k)
      {
        load.stage       = Stage::prestretch;
        load.load_factor = k / 3.;
        load.stretch     = 1. + (scene.prestretch - 1.) * k / 3.;
        if (!solve_or_report(model, load))
          return false;
      }
    for (unsigned int k = 1; k <= 10; ++k)
      {
        load.stage       = Stage::dead_load;
        load.load_factor = k / 10.;
        load.mass        = scene.mass * k / 10.;
        load.force       = scene.dead_load() * k / 10.;
        if (!solve_or_report(model, load))
          return false;
      }
    return true;
  }

  /// Ramp the voltages linearly from the current ones to @p target in @p steps.
  bool ramp(ShootingModel &model, const Scene &scene, const std::vector<double> &target,
            const unsigned int steps)
  {
    LoadState        load = model.load();
    const auto       from = load.voltages;
    load.stage            = Stage::voltage;
    load.mass             = scene.mass;
    load.force            = scene.dead_load();
    for (unsigned int k = 1; k <= steps; ++k)
      {
        for (unsigned int i = 0; i < target.size(); ++i)
          load.voltages[i] = from[i] + (target[i] - from[i]) * k / steps;
        load.load_factor += 1. / steps;
        if (!solve_or_report(model, load))
          return false;
      }
    return true;
  }

  /// Checks of one cone equilibrium's profile.
  void check_profile(const ShootingModel &model, const Scene &scene,
                     const std::string &name)
  {
    const StepFields  f  = model.fields();
    const StepSummary s  = model.summary();
    const double      C  = model.load().force / (2. * pi * scene.material.thickness);
    double            fi = 0., smin = 1e300;
    for (std::size_t i = 0; i < f.R.size(); ++i)
      {
        fi   = std::max(fi, std::abs(f.R[i] * f.s1[i] * std::sin(f.theta[i]) / C - 1.));
        smin = std::min(smin, f.s2[i]);
      }
    check_close(fi, 0., 1e-8,
                name + ": first integral R s1 sin(theta) = F/(2 pi H), max rel. "
                       "deviation over " + std::to_string(f.R.size()) + " samples");
    check_rel(model.profile().r_end, scene.frame_radius, 1e-11, name + ": r(B) = b");
    check_rel(f.r.back(), scene.frame_radius, 1e-11, name + ": last sample r = b");
    check_rel(f.r.front(), scene.disk_radius, 1e-14, name + ": r(A) = a");
    check_close(f.z.back(), 0., 1e-15, name + ": z(B) = 0");
    check_rel(f.z.front(), s.displacement, 1e-14, name + ": z(A) = displacement");
    check(f.R.size() == scene.n_rings() * model.options().samples_per_ring,
          name + ": samples_per_ring samples per ring");
    check(s.s2_min <= smin * (1. + 1e-14), name + ": s2_min <= min over the samples");

    // Each interior ring edge appears twice: r, theta, s1 continuous, l1 jumps.
    for (std::size_t i = 1; i < f.R.size(); ++i)
      if (f.R[i] == f.R[i - 1])
        {
          const std::string at =
            name + ": edge R = " + std::to_string(f.R[i] * 1e3) + " mm";
          check(f.ring[i] == f.ring[i - 1] + 1, at + ": ring index steps");
          check_rel(f.s1[i], f.s1[i - 1], 1e-12, at + ": s1 continuous");
          check_rel(f.r[i], f.r[i - 1], 1e-15, at + ": r continuous");
          check_rel(f.theta[i], f.theta[i - 1], 1e-15, at + ": theta continuous");
          if (f.Phi[i] != f.Phi[i - 1])
            check(std::abs(f.lambda1[i] / f.lambda1[i - 1] - 1.) > 1e-6,
                  at + ": lambda1 jumps " + std::to_string(f.lambda1[i - 1]) +
                    " -> " + std::to_string(f.lambda1[i]));
          check_rel(f.s2[i], s.s2_ring_inner[f.ring[i]], 1e-14,
                    at + ": s2_ring_inner is taken on the outer ring's side");
        }
  }

  void report_cost(const ShootingModel &model, const std::string &name,
                   const double seconds_per_step)
  {
    const ShootingStatistics &st = model.statistics();
    std::cout << "  " << name << ": last step " << st.root_iterations
              << " shooting integrations, " << st.rhs_evaluations
              << " rhs evaluations (" << st.rhs_evaluations_per_integration
              << " per integration, " << st.accepted_steps
              << " accepted steps), " << st.wall_seconds * 1e3
              << " ms; mean over the ramp " << seconds_per_step * 1e3
              << " ms per equilibrium\n";
  }

  std::string sci(const double x)
  {
    std::ostringstream o;
    o << x;
    return o.str();
  }

  double seconds_since(const std::chrono::steady_clock::time_point t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
} // namespace

CDEA_TEST_MAIN()
{
  std::cout.precision(10);
  const double mm = 1e-3, kV = 1e3;
  Scene        full; // defaults: a = 14 mm, b = 42 mm, full electrode
  const double mu = full.material.shear_modulus;

  // Pre-stretch stage: homogeneous s1 = s2 = mu (lam - lam^-5) / g,
  // g = 1 - (2 lam^2 + lam^-4 - 3) / Jlim.
  {
    ShootingModel model(full);
    LoadState     load;
    load.stretch = full.prestretch;
    check(model.solve(load).converged, "pre-stretch: homogeneous state");
    const double lam = full.prestretch;
    const double g   = 1. - (2. * lam * lam + std::pow(lam, -4) - 3.) / full.material.jlim;
    const double s0  = mu * (lam - std::pow(lam, -5)) / g;
    check_rel(model.summary().s2_ring_inner[0], s0, 1e-14, "pre-stretch: s2 = equibiaxial stress");
    check_rel(model.summary().s2_min, s0, 1e-14, "pre-stretch: s2_min");
    check_close(model.summary().displacement, 0., 0., "pre-stretch: flat");
    check_rel(model.fields().r.back(), full.frame_radius, 1e-15, "pre-stretch: r(B) = b");
  }

  // Full electrode: 0 V, then 5 kV in 0.25 kV steps.
  ShootingModel model(full);
  auto          t0 = std::chrono::steady_clock::now();
  if (!check(load_up(model, full), "full electrode: dead load reached"))
    return cdea_test::finish();
  report_cost(model, "full electrode 0 V", seconds_since(t0) / 13.);
  check_rel(model.summary().displacement, 18.24876 * mm, 2e-6, "full 0 V: displacement");
  check_rel(model.summary().s2_ring_inner[0] / mu, 2.67049, 2e-5, "full 0 V: s2/mu at the disk edge");
  check_profile(model, full, "full 0 V");

  t0 = std::chrono::steady_clock::now();
  if (!check(ramp(model, full, {5. * kV}, 20), "full electrode: 5 kV reached"))
    return cdea_test::finish();
  report_cost(model, "full electrode 5 kV", seconds_since(t0) / 20.);
  check_rel(model.summary().displacement, 23.79359 * mm, 2e-6, "full 5 kV: displacement");
  check_rel(model.summary().s2_ring_inner[0] / mu, 0.56700, 2e-5, "full 5 kV: s2/mu at the disk edge");
  check_profile(model, full, "full 5 kV");

  // Halving the Runge-Kutta tolerance barely moves the equilibrium.
  {
    ShootingOptions fine = model.options();
    fine.tolerance *= 0.5;
    ShootingModel finer(full, fine);
    finer.set_state(model.state());
    check(finer.solve(model.load()).converged, "full 5 kV: re-solved at half the tolerance");
    check_rel(finer.summary().displacement, model.summary().displacement, 1e-9,
              "full 5 kV: displacement at tol/2 vs tol " +
                sci(model.options().tolerance));
    check_rel(finer.summary().s2_ring_inner[0], model.summary().s2_ring_inner[0], 1e-9,
              "full 5 kV: s2 at tol/2 vs tol");
  }

  // State save/restore is exact, and a failed solve leaves the state alone.
  {
    const auto        saved   = model.state();
    const StepSummary before  = model.summary();
    LoadState         jump    = model.load();
    jump.voltages             = {12. * kV};
    const SolveReport r       = model.solve(jump);
    check(!r.converged && !r.message.empty(), "full: 5 -> 12 kV in one step fails: " + r.message);
    check(model.state() == saved, "full: failed solve leaves the state unchanged");
    LoadState other = model.load();
    other.voltages  = {5.25 * kV};
    check(model.solve(other).converged, "full: 5.25 kV");
    model.set_state(saved);
    check(model.state() == saved, "full: set_state(state()) restores the state vector");
    check(model.summary().displacement == before.displacement &&
            model.summary().s2_min == before.s2_min,
          "full: set_state restores the equilibrium bit for bit");
  }

  // Two rings split at r_v/a = 1.7: both to 5 kV, then the outer one to 6 kV.
  Scene split               = full;
  split.ring_edges_over_a   = {1., 1.7, 3.};
  ShootingModel model2(split);
  t0 = std::chrono::steady_clock::now();
  if (!check(load_up(model2, split) && ramp(model2, split, {5. * kV, 5. * kV}, 10) &&
               ramp(model2, split, {5. * kV, 6. * kV}, 4),
             "split 1.7: inner 5 kV, outer 6 kV reached"))
    return cdea_test::finish();
  report_cost(model2, "split 1.7, 5/6 kV", seconds_since(t0) / 27.);
  check_rel(model2.summary().displacement, 25.65070 * mm, 2e-6, "split 5/6 kV: displacement");
  check_rel(model2.summary().s2_ring_inner[0] / mu, 0.62767, 2e-5,
            "split 5/6 kV: s2/mu at the inner edge of ring 1");
  check_rel(model2.summary().s2_ring_inner[1] / mu, 0.65406, 2e-5,
            "split 5/6 kV: s2/mu at the inner edge of ring 2");
  check_profile(model2, split, "split 5/6 kV");

  return cdea_test::finish();
}
