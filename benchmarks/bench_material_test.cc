// Benchmark: the material-test model and its fit (doc/materials.md, "The
// material-test model").
//
// 1. A material point of a three-branch Gent film (network A 25 kPa, Jlim
//    40; branches 30, 15, 8 kPa at 1, 10, 100 s) through 2000 samples of
//    uniaxial cycles at 0.05 /s between stretch 1 and 3 sampled every 0.1 s,
//    default steps (trapezoidal rule, graded after each change of rate):
//    median wall and CPU time of RUNS runs, without and with the
//    derivatives of its 8 constants (mu_A, Jlim, mu_k, tau_k). Checked: both
//    give the same stresses, and those agree with ESDIRK4 at a 64th of the
//    sample interval to 1e-3 of the largest stress.
// 2. A joint fit of HISTORIES (10: about 1e4 samples) synthetic tests of that
//    film with 0.1 kPa of noise (uniaxial loading and unloading at 0.01,
//    0.03, 0.05 /s to stretch 4; relaxation at 1.5, 2.5, 3.5 held 600 s;
//    equibiaxial and pure-shear cycles; a two-step relaxation), all 8
//    constants free, from the data-driven starts: wall and CPU time, starts,
//    evaluations. Checked: converged, every constant within 4 standard
//    errors of the truth.
//
//   build/benchmarks/bench_material_test [RUNS] [HISTORIES]
//
// Smoke run (ctest): bench_material_test 1 2

#include <cdea/base/text.h>
#include <cdea/design/material_fit.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/model/scene.h>

#include "bench_common.h"

#include <iomanip>
#include <iostream>
#include <random>

using namespace cdea;

namespace
{
  Scene film()
  {
    Scene s                  = paper_scene({1., 3.}, {{0.}});
    s.material.shear_modulus = 25e3;
    s.material.jlim          = 40.;
    return spectrum_scene(s, {30., 15., 8.}, {1., 10., 100.}, 100.);
  }

  std::vector<SceneParameter> constants()
  {
    std::vector<SceneParameter> free{{ParameterKind::shear_modulus}, {ParameterKind::jlim}};
    for (const bool time : {false, true})
      for (unsigned int k = 1; k <= 3; ++k)
        free.push_back({ParameterKind::law_constant, 0, branch_constant_entry(k, time)});
    return free;
  }

  /// A piecewise-linear history through (time, stretch) corners, sampled every @p dt.
  StretchHistory corners(const TestKind kind, const std::vector<std::pair<double, double>> &c,
                         const double dt)
  {
    StretchHistory     h;
    const unsigned int n = unsigned(std::lround(c.back().first / dt));
    h.kind               = kind;
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double t = i == n ? c.back().first : i * dt;
        std::size_t  k = 1;
        while (k + 1 < c.size() && c[k].first < t)
          ++k;
        h.time.push_back(t);
        h.stretch.push_back(c[k - 1].second + (c[k].second - c[k - 1].second) *
                                                (t - c[k - 1].first) / (c[k].first - c[k - 1].first));
      }
    return h;
  }

  std::vector<StretchHistory> histories(const unsigned int n)
  {
    const auto u = TestKind::uniaxial;
    std::vector<StretchHistory> h{
      corners(u, {{0., 1.}, {300., 4.}, {600., 1.}}, 0.6),
      corners(u, {{0., 1.}, {100., 4.}, {200., 1.}}, 0.2),
      corners(u, {{0., 1.}, {60., 4.}, {120., 1.}}, 0.12),
      corners(u, {{0., 1.}, {10., 1.5}, {610., 1.5}}, 0.6),
      corners(u, {{0., 1.}, {30., 2.5}, {630., 2.5}}, 0.6),
      corners(u, {{0., 1.}, {50., 3.5}, {650., 3.5}}, 0.6),
      corners(TestKind::equibiaxial, {{0., 1.}, {50., 2.5}, {100., 1.}, {150., 2.5}, {200., 1.}}, 0.2),
      corners(TestKind::pure_shear, {{0., 1.}, {60., 4.}, {120., 1.}, {180., 4.}, {240., 1.}}, 0.24),
      corners(u, {{0., 1.}, {20., 2.}, {320., 2.}, {340., 3.}, {640., 3.}}, 0.64),
      corners(u, {{0., 1.}, {40., 3.}, {240., 3.}, {280., 1.}, {480., 1.}}, 0.48)};
    h.resize(std::min<std::size_t>(n, h.size()));
    return h;
  }

  /// Stresses of @p scene's film along @p h plus Gaussian noise (Pa).
  MaterialTestData synthetic(const Scene &scene, const StretchHistory &h, const double sigma,
                             std::mt19937_64 &engine, const std::string &name)
  {
    const auto          law = scene.law();
    MaterialPoint       point(*law);
    MaterialPointResult r;
    std::string         message;
    if (!point.run(h, {}, r, message))
      throw std::runtime_error(name + ": " + message);
    std::normal_distribution<double> noise(0., sigma);
    MaterialTestData                 d;
    d.name    = name;
    d.history = h;
    for (std::size_t k = 0; k < h.time.size(); ++k)
      {
        d.stress.push_back(r.stress[k] + noise(engine));
        d.weight.push_back(1.);
        d.lines.push_back(unsigned(k + 2));
      }
    return d;
  }

  /// Part 1: the timed history; false if its answer is wrong.
  bool point_history(const int runs)
  {
    const Scene          scene = film();
    const auto           law   = scene.law();
    const StretchHistory h     = corners(TestKind::uniaxial, {{0., 1.}, {40., 3.}, {80., 1.},
                                                              {120., 3.}, {160., 1.}, {199.9, 2.995}},
                                         0.1);
    std::vector<LawParameter> parameters{LawParameter::shear_modulus, LawParameter::jlim};
    for (unsigned int k = 0; k < 6; ++k)
      parameters.push_back(own_constant(k));
    MaterialPoint       point(*law);
    MaterialPointResult plain, derived;
    std::string         message;
    std::vector<double> wall[2], cpu[2];
    for (int r = 0; r < runs; ++r)
      for (const int d : {0, 1})
        {
          const double w0 = cdea_bench::wall_seconds(), c0 = cdea_bench::cpu_seconds();
          if (!point.run(h, d ? parameters : std::vector<LawParameter>{}, d ? derived : plain, message))
            throw std::runtime_error(message);
          wall[d].push_back(cdea_bench::wall_seconds() - w0);
          cpu[d].push_back(cdea_bench::cpu_seconds() - c0);
        }
    MaterialPointSettings fine;
    fine.method           = TimeMethod::esdirk4;
    fine.max_step         = 0.1 / 64.;
    fine.max_stretch_step = HUGE_VAL;
    fine.step_growth      = 0.;
    MaterialPoint       reference(*law, fine);
    MaterialPointResult ref;
    reference.run(h, {}, ref, message);
    double same = 0., error = 0., scale = 0.;
    for (std::size_t k = 0; k < h.time.size(); ++k)
      {
        same  = std::max(same, std::abs(plain.stress[k] - derived.stress[k]));
        error = std::max(error, std::abs(plain.stress[k] - ref.stress[k]));
        scale = std::max(scale, std::abs(ref.stress[k]));
      }
    std::cout << std::setprecision(4) << "material point, 3 branches, " << h.time.size()
              << " samples (" << plain.steps << " steps), " << runs << " run(s), medians:\n"
              << "  stresses:                    " << 1e3 * cdea_bench::median(wall[0]) << " ms wall, "
              << 1e3 * cdea_bench::median(cpu[0]) << " ms CPU\n"
              << "  with 8 derivatives:          " << 1e3 * cdea_bench::median(wall[1]) << " ms wall, "
              << 1e3 * cdea_bench::median(cpu[1]) << " ms CPU\n"
              << "  the same stresses with and without derivatives: largest difference " << same
              << " Pa\n  error against ESDIRK4 at 1/64 the interval: " << error / scale
              << " of the largest stress\n";
    return same == 0. && error <= 1e-3 * scale;
  }
} // namespace

namespace
{
  /// Part 2: the timed joint fit; false if its answer is wrong.
  bool joint_fit(const unsigned int n)
  {
    const Scene                       truth = film();
    const std::vector<SceneParameter> free  = constants();
    std::mt19937_64                   engine(2025);
    std::vector<MaterialTestData>     tests;
    std::size_t                       samples = 0;
    for (const StretchHistory &h : histories(n))
      {
        tests.push_back(synthetic(truth, h, 100., engine, "test " + std::to_string(tests.size() + 1)));
        samples += h.time.size();
      }
    // The prm's constants are not the truth: the start is the data's.
    Scene base = truth;
    base.material.jlim = 270.;
    MaterialFitSettings settings;
    settings.fit.free = free;
    const double            w0 = cdea_bench::wall_seconds(), c0 = cdea_bench::cpu_seconds();
    const MaterialFitResult r  = fit_material_tests(base, tests, settings);
    const double            wall = cdea_bench::wall_seconds() - w0, cpu = cdea_bench::cpu_seconds() - c0;
    std::cout << "joint fit of " << tests.size() << " tests, " << samples << " samples, "
              << free.size() << " constants, " << r.starts.size() << " starts: " << wall
              << " s wall, " << cpu << " s CPU, " << r.evaluations << " evaluations, best start "
              << r.best << " (" << r.fit.iterations << " iterations), " << r.fit.status << '\n';
    bool inside = r.fit.converged;
    for (std::size_t j = 0; j < free.size(); ++j)
      {
        const double t = parameter_value(truth, free[j]), v = r.fit.values[j],
                     se = r.fit.standard_errors[j];
        inside = inside && std::abs(v - t) <= 4. * se;
        std::cout << "  " << std::setw(30) << std::left << label(free[j]) << std::right
                  << std::setw(12) << t << std::setw(14) << v << " +- " << std::setw(10) << se
                  << "  (" << std::setprecision(2) << (v - t) / se << " s.e.)" << std::setprecision(4)
                  << '\n';
      }
    for (const TestMeasures &m : r.tests)
      std::cout << "  " << m.name << ": rms " << m.rms * 1e-3 << " kPa (" << m.relative
                << " of its largest)\n";
    return inside;
  }
} // namespace

int main(int argc, char **argv)
{
  const int          runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
  const unsigned int n    = argc > 2 ? unsigned(std::max(1, std::atoi(argv[2]))) : 10;
  const bool         ok   = point_history(runs) & joint_fit(n);
  if (!ok)
    std::cout << "FAIL: the answer is wrong\n";
  return ok ? 0 : 1;
}
