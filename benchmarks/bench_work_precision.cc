// Work-precision benchmark: error in the disk displacement against CPU time,
// for the FE model (each polynomial degree p, a sweep of elements per ring)
// and for the shooting model (a sweep of its integration tolerance), in one
// process on one machine (doc/performance.md and doc/validation.md).
//
// What is timed: one complete run as `cdea run` / `cdea shoot` does it, minus
// the file output and the per-step stability eigenvalue that `cdea run` adds
// (its cost is printed separately): model construction, then
// LoadStepper::run() through pre-stretch, dead load and the voltage path with
// the library's default SteppingSettings (0.25 kV steps, onset located to
// 1 mV). Both methods take the same load steps. The time is the CPU time of
// the process, the median over 21 rounds in each of which every
// configuration runs once: the machine is shared and noisy, and interleaving
// spreads its slow phases over all configurations alike. The minimum and the
// wall-clock median are written as well.
//
// Errors are relative to the shooting model at tolerance 1e-12 (whose change
// to 1e-13 is printed): displacement, and the largest relative error of s2 at
// the inner ring edges.
//
// Scenes: the full electrode to 5 kV, and r_v/a = 1.7 with both rings to 5 kV
// and then the outer one to 6 kV.
//
// Prints, per scene, the cheapest configuration of each method that reaches
// every accuracy from 1e-3 to 1e-9 and their time ratio; the cheapest FE
// discretizations that meet 1e-5 in displacement and 1e-3 in s2 on both
// scenes; and the cost of the pieces of a run. Writes DIR/work_precision.csv
// (default DIR: results/validation). With --smoke (ctest, label bench-smoke):
// the full electrode only, p = 1 to 3 on up to 4 elements per ring, shooting
// tolerances 1e-3 to 1e-6, one round, CSV into a temporary folder; it fails
// if a run does not complete, a time is not finite, or the error of an FE
// degree does not fall as its mesh is refined.
//
//   build/benchmarks/bench_work_precision [DIR] [--smoke]

#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/shooting_model.h>

#include "bench_common.h"

#include <iomanip>
#include <map>
#include <memory>
#include <sstream>

using namespace cdea;
using namespace cdea_bench;

namespace
{
  struct Case
  {
    std::string name;
    Scene       scene;
  };

  using Builder = std::function<std::unique_ptr<EquilibriumModel>()>;

  /// One configuration of one method on one scene.
  struct Point
  {
    Builder             build; ///< a fresh model of this configuration
    const Scene        *on = nullptr;
    std::string         scene, method;
    unsigned            degree = 0, elements_per_ring = 0, dofs = 0;
    double              tolerance = 0.;
    std::vector<double> cpu, wall;
    double              cpu_median = 0., cpu_min = 0., wall_median = 0.;
    double              disp_err = 0., s2_err = 0.;
    bool                ok = false;
    std::string         message; ///< why the run stopped (if not ok)

    std::string label() const
    {
      std::ostringstream o;
      if (method == "fe")
        o << "FE p=" << degree << ", " << elements_per_ring << "/ring";
      else
        o << "shooting tol " << std::setprecision(0) << std::scientific << tolerance;
      return o.str();
    }
  };

  Builder shooting_builder(const Scene &scene, const double tolerance)
  {
    shooting::ShootingOptions o;
    o.tolerance = tolerance;
    return [&scene, o] { return std::make_unique<shooting::ShootingModel>(scene, o); };
  }

  FeDiscretization fe(const unsigned p, const unsigned n)
  {
    FeDiscretization d;
    d.degree            = p;
    d.elements_per_ring = n;
    return d;
  }

  /// Every configuration of both methods on @p c, each run once (untimed):
  /// its errors, and whether it completes.
  void enumerate(const Case &c, const bool smoke, std::vector<Point> &points)
  {
    const Scene &scene = c.scene;
    // Reference, and its own change from tolerance 1e-12 to 1e-13.
    const StepSummary ref   = [&] {
      auto m = shooting_builder(scene, 1e-12)();
      return run_stages(*m, scene).last;
    }();
    const StepSummary tight = [&] {
      auto m = shooting_builder(scene, 1e-13)();
      return run_stages(*m, scene).last;
    }();
    double ref_s2 = 0.;
    for (unsigned int k = 0; k < scene.n_rings(); ++k)
      ref_s2 = std::max(ref_s2, rel(ref.s2_ring_inner[k], tight.s2_ring_inner[k]));
    std::cout << "\n=== " << c.name << ": reference shooting tol 1e-12, displacement "
              << std::setprecision(12) << ref.displacement * 1e3 << " mm; change to tol "
              << "1e-13: displacement " << std::setprecision(3)
              << rel(ref.displacement, tight.displacement) << ", s2 " << ref_s2 << "\n";

    const auto add = [&](Point pt) {
      pt.on             = &scene;
      pt.scene          = c.name;
      auto       model  = pt.build();
      const Run  run    = run_stages(*model, scene);
      pt.ok             = run.result.completed;
      pt.message        = run.result.message;
      if (pt.ok)
        {
          pt.disp_err = rel(run.last.displacement, ref.displacement);
          for (unsigned int k = 0; k < scene.n_rings(); ++k)
            pt.s2_err =
              std::max(pt.s2_err, rel(run.last.s2_ring_inner[k], ref.s2_ring_inner[k]));
        }
      points.push_back(pt);
      return pt;
    };

    // Shooting: tolerance sweep.
    const double last_tolerance = smoke ? 0.5e-6 : 0.5e-13;
    for (double tol = smoke ? 1e-3 : 1e-2; tol > last_tolerance; tol /= 10.)
      {
        Point pt;
        pt.method    = "shooting";
        pt.tolerance = tol;
        pt.build     = shooting_builder(scene, tol);
        add(pt);
      }

    // FE: for each p, a sweep of elements per ring (grading 4), until the
    // error reaches the reference's level or the mesh gets large.
    const std::vector<unsigned> sweep =
      smoke ? std::vector<unsigned>{1, 2, 4} :
              std::vector<unsigned>{1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256,
                                    384, 512};
    for (unsigned p = 1; p <= (smoke ? 3u : 6u); ++p)
      {
        double previous = 1.;
        for (const unsigned n : sweep)
          {
            if (p * n * scene.n_rings() > 1100)
              break;
            Point pt;
            pt.method            = "fe";
            pt.degree            = p;
            pt.elements_per_ring = n;
            pt.dofs              = 2 * (p * n * scene.n_rings() + 1);
            const FeDiscretization d = fe(p, n);
            pt.build                 = [&scene, d] {
              return std::make_unique<MembraneModel>(scene, d, NewtonSettings());
            };
            const Point done = add(pt);
            if (smoke)
              {
                require(done.ok, done.label() + " did not complete: " + done.message);
                require(done.disp_err < previous, done.label() + ": the displacement error " +
                                                    std::to_string(done.disp_err) +
                                                    " did not fall under refinement");
                previous = done.disp_err;
              }
            if (done.ok && done.disp_err < 1e-12)
              break;
          }
      }
  }

  /// Time every configuration that completes: @p rounds rounds, each running
  /// every configuration once, in the same order.
  void time_points(std::vector<Point> &points, const unsigned int rounds)
  {
    for (unsigned int r = 0; r < rounds; ++r)
      for (Point &pt : points)
        if (pt.ok)
          {
            const double w0 = wall_seconds(), c0 = cpu_seconds();
            auto         model = pt.build();
            run_stages(*model, *pt.on);
            pt.cpu.push_back(cpu_seconds() - c0);
            pt.wall.push_back(wall_seconds() - w0);
          }
    for (Point &pt : points)
      if (pt.ok)
        {
          pt.cpu_median  = median(pt.cpu);
          pt.cpu_min     = *std::min_element(pt.cpu.begin(), pt.cpu.end());
          pt.wall_median = median(pt.wall);
          require_finite(pt.cpu_median, "the CPU time of " + pt.label(), true);
        }
  }

  void print_points(const std::vector<Point> &points, const unsigned int rounds)
  {
    std::cout << "\nCPU time of a whole run: median over " << rounds
              << " rounds (every configuration once per round); minimum and wall-clock median "
                 "in brackets\n";
    std::string scene_name;
    for (const Point &pt : points)
      {
        if (pt.scene != scene_name)
          std::cout << "--- " << (scene_name = pt.scene) << "\n";
        std::cout << std::left << std::setw(30) << pt.label() << std::right << std::setw(6)
                  << pt.dofs << "  cpu " << std::setw(9) << pt.cpu_median * 1e3 << " ms (min "
                  << std::setw(8) << pt.cpu_min * 1e3 << ", wall " << std::setw(8)
                  << pt.wall_median * 1e3 << ")  disp err " << std::setw(9) << pt.disp_err
                  << "  s2 err " << std::setw(9) << pt.s2_err
                  << (pt.ok ? "" : "  FAILED: " + pt.message) << "\n";
      }
  }

  /// Cheapest configuration per accuracy level, per scene and method.
  void print_cheapest(const std::vector<Point> &points, const std::vector<Case> &cases)
  {
    std::cout << "\nCheapest run reaching each accuracy in displacement (CPU-time medians):\n";
    for (const Case &c : cases)
      {
        std::cout << c.name << "\n"
                  << std::setw(8) << "target" << std::setw(34) << "FE" << std::setw(10) << "ms"
                  << std::setw(30) << "shooting" << std::setw(10) << "ms" << std::setw(10)
                  << "FE/shoot" << "\n";
        for (int e = 3; e <= 9; ++e)
          {
            const double target  = std::pow(10., -e);
            const Point *best[2] = {nullptr, nullptr};
            for (const Point &pt : points)
              if (pt.scene == c.name && pt.ok && pt.disp_err <= target)
                {
                  const int m = pt.method == "fe" ? 0 : 1;
                  if (!best[m] || pt.cpu_median < best[m]->cpu_median)
                    best[m] = &pt;
                }
            std::cout << std::setw(8) << target;
            for (int m = 0; m < 2; ++m)
              if (best[m])
                std::cout << std::setw(34 - 4 * m) << best[m]->label() << std::setw(10)
                          << best[m]->cpu_median * 1e3;
              else
                std::cout << std::setw(34 - 4 * m) << "none" << std::setw(10) << "-";
            if (best[0] && best[1])
              std::cout << std::setw(10) << best[0]->cpu_median / best[1]->cpu_median;
            std::cout << "\n";
          }
      }
  }

  /// Cheapest FE configurations with displacement error <= 1e-5 and s2 error
  /// <= 1e-3 on every scene (time summed over the scenes).
  void print_cheapest_meeting_targets(const std::vector<Point> &points, const std::size_t n_cases)
  {
    using Key = std::pair<unsigned, unsigned>;
    std::map<Key, std::pair<double, unsigned>> fe_time;
    std::map<Key, double>                      worst_disp, worst_s2;
    for (const Point &pt : points)
      if (pt.method == "fe")
        {
          const Key key{pt.degree, pt.elements_per_ring};
          if (pt.ok && pt.disp_err <= 1e-5 && pt.s2_err <= 1e-3)
            {
              fe_time[key].first += pt.cpu_median;
              fe_time[key].second += 1;
            }
          worst_disp[key] = std::max(worst_disp[key], pt.ok ? pt.disp_err : 1.);
          worst_s2[key]   = std::max(worst_s2[key], pt.ok ? pt.s2_err : 1.);
        }
    std::vector<std::pair<double, Key>> ok;
    for (const auto &[key, v] : fe_time)
      if (v.second == n_cases)
        ok.push_back({v.first, key});
    std::sort(ok.begin(), ok.end());
    std::cout << "\nFE discretizations meeting 1e-5 in displacement and 1e-3 in s2 on every "
                 "scene, cheapest first (CPU ms summed over the scenes):\n";
    for (std::size_t i = 0; i < std::min<std::size_t>(ok.size(), 12); ++i)
      {
        const Key key = ok[i].second;
        std::cout << "  p=" << key.first << ", " << std::setw(3) << key.second
                  << "/ring: " << std::setw(8) << ok[i].first * 1e3 << " ms, worst disp err "
                  << worst_disp[key] << ", worst s2 err " << worst_s2[key] << "\n";
      }
    const FeDiscretization defaults;
    const Key              def{defaults.degree, defaults.elements_per_ring};
    if (fe_time.count(def))
      std::cout << "  (the default p=" << def.first << ", " << def.second
                << "/ring: " << fe_time[def].first * 1e3 << " ms, worst disp err "
                << worst_disp[def] << ", worst s2 err " << worst_s2[def] << ")\n";
  }

  /// Where the FE time goes: per-call costs at the end state of the smallest
  /// discretization, of the default and of p = 3 with 8 per ring, and of a
  /// shooting solve.
  void print_costs(const Case &c, const int calls)
  {
    const Scene &scene = c.scene;
    std::cout << "\nCost break-down on '" << c.name << "' (CPU-time medians of " << calls
              << " calls):\n";
    for (const auto &[p, n] : std::vector<std::pair<unsigned, unsigned>>{{1, 1}, {4, 4}, {3, 8}})
      {
        const FeDiscretization d = fe(p, n);
        const double t_build =
          median_time([&] { MembraneModel m(scene, d, NewtonSettings()); }, calls);
        MembraneModel m(scene, d, NewtonSettings());
        const Run     run = run_stages(m, scene);
        require(run.result.completed, "the run of FE p=" + std::to_string(p) + " stopped");
        // A solve 1 V above the end of the path, from the end state.
        LoadState load = m.load();
        load.voltages  = {load.voltages[0] + 1.};
        const ModelState state = m.state();
        unsigned int     its   = 0;
        const double     t_solve = median_time(
          [&] {
            m.set_state(state);
            its = m.solve(load).iterations;
          },
          calls);
        const double t_summary  = median_time([&] { (void)m.summary(); }, calls);
        const double t_residual = median_time([&] { (void)m.residual_vector(); }, calls);
        double       eigenvalue = 0.;
        const double t_eigen =
          median_time([&] { eigenvalue = m.min_tangent_eigenvalue(); }, calls);
        require(its > 0 && std::isfinite(eigenvalue), "a solve or the eigenvalue failed");
        std::cout << "  FE p=" << p << ", " << n << "/ring (" << m.n_dofs()
                  << " unknowns): build " << t_build * 1e6 << " us; a solve 1 V away "
                  << t_solve * 1e6 << " us (" << its << " Newton iterations, i.e. "
                  << t_solve / its * 1e6 << " us each); summary() " << t_summary * 1e6
                  << " us; a residual " << t_residual * 1e6
                  << " us; the stability eigenvalue (cdea run: every step) " << t_eigen * 1e6
                  << " us (" << eigenvalue << " N/m); a whole run: " << run.result.solves
                  << " solves, " << run.result.newton_iterations << " Newton iterations, "
                  << run.result.steps << " steps\n";
      }
    for (const double tol : {1e-5, 1e-9})
      {
        shooting::ShootingOptions o;
        o.tolerance = tol;
        shooting::ShootingModel m(scene, o);
        const Run               run = run_stages(m, scene);
        LoadState               load = m.load();
        load.voltages                = {load.voltages[0] + 1.};
        const ModelState state       = m.state();
        const double     t           = median_time(
          [&] {
            m.set_state(state);
            m.solve(load);
          },
          calls);
        std::cout << "  shooting tol " << tol << ": a solve 1 V away " << t * 1e6 << " us ("
                  << m.statistics().root_iterations << " integrations, "
                  << m.statistics().rhs_evaluations << " right-hand sides); a whole run: "
                  << run.result.solves << " solves\n";
      }
  }

  int benchmark(const OutputFolder &dir, const bool smoke)
  {
    std::vector<Case> cases{{"full", paper_scene({1., 3.}, {{5.}})},
                            {"partitioned", paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 6.}})}};
    if (smoke)
      cases.pop_back();
    const unsigned int rounds = smoke ? 1 : 21;

    std::vector<Point> points;
    std::cout << std::setprecision(3);
    for (const Case &c : cases)
      enumerate(c, smoke, points);
    time_points(points, rounds);
    print_points(points, rounds);
    print_cheapest(points, cases);
    print_cheapest_meeting_targets(points, cases.size());
    print_costs(cases.front(), smoke ? 5 : 101);

    std::ofstream csv(dir / "work_precision.csv");
    csv << "scene,method,degree,elements_per_ring,tolerance,dofs,cpu_median_s,cpu_min_s,"
           "wall_median_s,repetitions,disp_err,s2_err,completed\n";
    csv << std::setprecision(6) << std::scientific;
    for (const Point &pt : points)
      csv << pt.scene << ',' << pt.method << ',' << pt.degree << ',' << pt.elements_per_ring
          << ',' << pt.tolerance << ',' << pt.dofs << ',' << pt.cpu_median << ','
          << pt.cpu_min << ',' << pt.wall_median << ',' << pt.cpu.size() << ','
          << pt.disp_err << ',' << pt.s2_err << ',' << int(pt.ok) << '\n';
    require(bool(csv), "could not write " + (dir / "work_precision.csv").string());
    std::cout << "\nwrote " << (dir / "work_precision.csv").string() << "\n";
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  return study_main(argc, argv, "bench_work_precision", benchmark);
}
