// The straight cone (shooting/straight_cone.h), the continuous limit of
// partitioning, against an independent solver: the shooting model of M equal
// rings, each at the smallest voltage the cone needs over its ring (so that
// the cone's s2 = 0 is approached from s2 > 0). As M grows its displacement
// must approach the cone's from below, at first order in 1/M. Also the cone's own relations
// (tan(theta) = F / (2 pi H C), z(A) = tan(theta) (b - a)) and the values of
// doc/optimization.md (section 3: cone angle 49.489 degrees, largest voltage
// 7.971 kV).

#include <cdea/model/scene.h>
#include <cdea/shooting/shooting_model.h>
#include <cdea/shooting/straight_cone.h>

#include "check.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace cdea;
using namespace cdea::shooting;
using cdea_test::check;
using cdea_test::check_close;
using cdea_test::check_rel;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  /// Samples per ring at which the cone's voltage is looked up.
  constexpr unsigned int samples_per_ring = 6;

  /// Reference radii of @p M equal rings' samples (edges included), ring by ring.
  std::vector<double> ring_samples(const Scene &scene, const unsigned int M)
  {
    const double        A = scene.inner_reference_radius(), B = scene.outer_reference_radius();
    std::vector<double> R;
    for (unsigned int k = 0; k < M; ++k)
      for (unsigned int j = 0; j < samples_per_ring; ++j)
        R.push_back(A + (B - A) * (k + double(j) / (samples_per_ring - 1)) / M);
    return R;
  }

  /// The displacement of the shooting model with M equal rings at the
  /// smallest cone voltage of each ring (NaN if a solve fails): pre-stretch,
  /// dead load, then the voltages in 20 steps.
  double graded_displacement(const Scene &base, const unsigned int M)
  {
    Scene scene = base;
    scene.ring_edges_over_a.clear();
    for (unsigned int k = 0; k <= M; ++k)
      scene.ring_edges_over_a.push_back(1. + (scene.frame_radius / scene.disk_radius - 1.) * k / M);
    const StraightCone  cone = straight_cone(scene, ring_samples(scene, M));
    std::vector<double> target(M);
    for (unsigned int k = 0; k < M; ++k)
      target[k] = *std::min_element(cone.sample_voltage.begin() + k * samples_per_ring,
                                    cone.sample_voltage.begin() + (k + 1) * samples_per_ring);
    ShootingModel model(scene);
    model.set_reference_state();
    LoadState load;
    load.voltages.assign(M, 0.);
    load.stage = Stage::prestretch;
    for (unsigned int k = 1; k <= 3; ++k)
      {
        load.load_factor = k / 3.;
        load.stretch     = 1. + (scene.prestretch - 1.) * k / 3.;
        if (!model.solve(load).converged)
          return std::nan("");
      }
    load.stage = Stage::dead_load;
    for (unsigned int k = 1; k <= 10; ++k)
      {
        load.load_factor = k / 10.;
        load.mass        = scene.mass * k / 10.;
        load.force       = scene.dead_load() * k / 10.;
        if (!model.solve(load).converged)
          return std::nan("");
      }
    load.stage = Stage::voltage;
    for (unsigned int k = 1; k <= 20; ++k)
      {
        for (unsigned int i = 0; i < M; ++i)
          load.voltages[i] = target[i] * k / 20.;
        load.load_factor = 1. + k / 20.;
        if (!model.solve(load).converged)
          return std::nan("");
      }
    return model.summary().displacement;
  }
} // namespace

CDEA_TEST_MAIN()
{
  std::cout.precision(10);
  const Scene        scene; // the paper's actuator
  const StraightCone cone = straight_cone(scene);
  if (!check(cone.ok, "straight cone: the tension C found"))
    return cdea_test::finish();
  std::cout << "  cone: theta " << cone.theta * 180. / pi << " deg, displacement "
            << cone.displacement * 1e3 << " mm, largest voltage " << cone.max_voltage * 1e-3
            << " kV\n";
  check_rel(std::tan(cone.theta),
            scene.dead_load() / (2. * pi * scene.material.thickness * cone.tension), 1e-14,
            "tan(theta) = F / (2 pi H C)");
  check_rel(cone.displacement, std::tan(cone.theta) * (scene.frame_radius - scene.disk_radius),
            1e-14, "z(A) = tan(theta) (b - a)");
  check_close(cone.theta * 180. / pi, 49.489, 5e-4, "cone angle of doc/optimization.md (deg)");
  check_close(cone.max_voltage * 1e-3, 7.971, 5e-4,
              "largest voltage of doc/optimization.md (kV)");

  // The voltage profile: the samples asked for, each below the largest.
  const std::vector<double> R = ring_samples(scene, 4);
  const StraightCone        sampled = straight_cone(scene, R);
  check(sampled.sample_voltage.size() == R.size(), "a voltage per sample");
  bool within = true;
  for (const double v : sampled.sample_voltage)
    within = within && v > 0. && v <= sampled.max_voltage * (1. + 1e-9);
  check(within, "every sampled voltage in (0, the largest voltage]");
  check(sampled.displacement == cone.displacement, "sampling leaves the cone unchanged");

  // The shooting model of M equal rings approaches the cone from below, at
  // first order in 1/M (each ring's voltage is its smallest cone voltage), so
  // Richardson's 2 z(2M) - z(M) approaches it at second order.
  std::vector<double> gaps;
  double              z_previous = std::nan("");
  for (const unsigned int M : {16u, 32u, 64u, 128u})
    {
      const double z   = graded_displacement(scene, M);
      const double gap = cone.displacement - z;
      const double richardson = 2. * z - z_previous;
      std::cout << "  M = " << M << ": displacement " << z * 1e3 << " mm, below the cone by "
                << gap * 1e3 << " mm; 2 z(M) - z(M/2) below it by "
                << (cone.displacement - richardson) * 1e3 << " mm\n";
      check(std::isfinite(z), "M = " + std::to_string(M) + ": the shooting model solved");
      check(gap > 0. && (gaps.empty() || gap < 0.6 * gaps.back()),
            "M = " + std::to_string(M) + ": below the cone, the gap at least 40 % smaller");
      gaps.push_back(gap);
      z_previous = z;
      if (M == 128)
        check_rel(richardson, cone.displacement, 2e-4,
                  "M = 64, 128: Richardson's extrapolation is the cone's displacement");
    }
  check_rel(gaps[3] / gaps[2], 0.5, 0.05, "M = 64, 128: the gap halves (first order)");
  return cdea_test::finish();
}
