// Work-precision benchmark: error in the disk displacement against CPU time,
// for the FE model (each polynomial degree p, a sweep of elements per ring)
// and for the shooting model (a sweep of its integration tolerance), in one
// process on one machine (issue 3, item 5; doc/performance.md and
// doc/validation.md).
//
// What is timed: one complete run as `cdea run` / `cdea shoot` does it, minus
// the file output and the per-step stability eigenvalue that `cdea run` adds
// (its cost is printed separately): model construction, then
// LoadStepper::run() through pre-stretch, dead load and the voltage path with
// the library's default SteppingSettings (0.25 kV steps, onset located to
// 1 mV). Both methods take the same load steps. The time is the CPU
// time of the process (CLOCK_PROCESS_CPUTIME_ID), the median over 21 rounds
// in each of which every configuration runs once (3 with --quick): the
// machine is shared and noisy, and interleaving spreads its slow phases over
// all configurations alike. The minimum and the wall-clock median are
// written as well.
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
// discretization that meets 1e-5 in displacement and 1e-3 in s2 on both
// scenes; candidate default discretizations on all scenes of
// tests/test_validation_agreement.cc (worst errors, onset shift, CPU time);
// and a break-down of where the FE time goes. Writes
// <DIR>/work_precision.csv (default DIR: results/validation).
//
//   build/benchmarks/bench_work_precision [DIR] [--quick]

#include <cdea/app/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/shooting_model.h>
#include <cdea/solver/load_stepper.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cdea;

namespace
{

  /// The scenes of tests/test_validation_agreement.cc (public cases, own
  /// scenes, paper cases past their onset).
  std::vector<std::pair<std::string, Scene>> validation_scenes()
  {
    std::vector<std::pair<std::string, Scene>> v;
    v.push_back({"public full 0 V", paper_scene({1., 3.}, {{0.}})});
    v.push_back({"public full 5 kV", paper_scene({1., 3.}, {{5.}})});
    v.push_back({"public r_v 1.7 5/6 kV", paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 6.}})});
    {
      Scene s        = paper_scene({1., 4.}, {{4.5}});
      s.disk_radius  = 10e-3;
      s.frame_radius = 40e-3;
      s.prestretch   = 3.;
      v.push_back({"geometry b/a 4, lam 3", s});
    }
    {
      Scene s    = paper_scene({1., 3.}, {{2.8}});
      s.material = {50e3, 60., 4.5e-11, 0.5e-3};
      v.push_back({"material", s});
    }
    {
      Scene s = paper_scene({1., 1.5, 3.}, {{4., 4.}, {4., 5.5}});
      s.mass  = 0.1;
      v.push_back({"mass 100 g", s});
    }
    {
      Scene s = paper_scene({1., 3.}, {{6.}});
      s.mass  = 0.5;
      v.push_back({"mass 500 g", s});
    }
    v.push_back({"three rings", paper_scene({1., 1.5, 2.2, 3.}, {{4., 4., 4.}, {4., 5., 6.}})});
    v.push_back({"three rings, onset",
                 paper_scene({1., 1.4, 2., 3.}, {{4.5, 4.5, 4.5}, {4.5, 5.5, 7.}})});
    {
      Scene s      = paper_scene({1., 1.3, 1.8, 2.4, 3.}, {{3., 3., 3., 3.}, {3., 3.5, 4., 4.5}});
      s.prestretch = 2.;
      v.push_back({"four rings, lam 2", s});
    }
    v.push_back({"paper full to 5.5 kV", paper_scene({1., 3.}, {{5.5}})});
    v.push_back({"paper r_v 1.7 to 5/7 kV", paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 7.}})});
    return v;
  }

  double cpu_seconds()
  {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }

  double median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }

  struct Outcome
  {
    StepSummary last;
    RunResult   result;
  };

  /// One complete run of a freshly built model.
  Outcome run_once(const std::function<std::unique_ptr<EquilibriumModel>()> &build,
                   const Scene                                                &scene)
  {
    auto        model = build();
    LoadStepper stepper(scene, *model, SteppingSettings());
    Outcome     out;
    stepper.on_step = [&](const StepSummary &s) { out.last = s; };
    out.result      = stepper.run();
    return out;
  }

  using Builder = std::function<std::unique_ptr<EquilibriumModel>()>;

  struct Timing
  {
    double       cpu = 0., cpu_min = 0., wall = 0.;
    unsigned int repetitions = 0;
    Outcome      outcome;
  };

  struct Point
  {
    Builder     build;        ///< a fresh model of this configuration
    const Scene *on = nullptr; ///< its scene
    std::vector<double> cpu, wall;
    std::string scene, method;
    unsigned    degree = 0, elements_per_ring = 0, dofs = 0;
    double      tolerance = 0.;
    Timing      timing;
    double      disp_err = 0., s2_err = 0.;
    bool        ok = false;

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

  double rel(const double a, const double b) { return std::abs(a - b) / std::abs(b); }

  /// Forwards to a model and accumulates the CPU time and the number of calls
  /// of each interface function, to see where the time of a run goes.
  class Profiled : public EquilibriumModel
  {
  public:
    explicit Profiled(EquilibriumModel &inner)
      : inner(inner)
    {}

    struct Account
    {
      unsigned long calls   = 0;
      double        seconds = 0.;
    };
    mutable std::map<std::string, Account> accounts;

    void set_reference_state() override
    {
      timed("set_reference_state", [&] { inner.set_reference_state(); });
    }
    SolveReport solve(const LoadState &load) override
    {
      SolveReport r;
      timed("solve", [&] { r = inner.solve(load); });
      return r;
    }
    const LoadState &load() const override { return inner.load(); }
    double           displacement() const override { return inner.displacement(); }
    HoopStresses     hoop_stresses() const override
    {
      HoopStresses h;
      timed("summary", [&] { h = inner.hoop_stresses(); });
      return h;
    }
    StepFields fields() const override
    {
      StepFields f;
      timed("fields", [&] { f = inner.fields(); });
      return f;
    }
    void predict(const ModelState &older, double factor) override
    {
      timed("predict", [&] { inner.predict(older, factor); });
    }
    ModelState state() const override
    {
      ModelState s;
      timed("state", [&] { s = inner.state(); });
      return s;
    }
    void set_state(const ModelState &s) override
    {
      timed("set_state", [&] { inner.set_state(s); });
    }

  private:
    EquilibriumModel &inner;

    template <typename F>
    void timed(const std::string &name, F &&f) const
    {
      const double c0 = cpu_seconds();
      f();
      Account &a = accounts[name];
      a.seconds += cpu_seconds() - c0;
      ++a.calls;
    }
  };
} // namespace

int main(int argc, char **argv)
{
  const MpiSession            mpi(argc, argv);
  std::filesystem::path       dir   = "results/validation";
  bool                        quick = false;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--quick")
      quick = true;
    else
      dir = argv[i];
  std::filesystem::create_directories(dir);
  // Every configuration is timed once per round, in the same order, so that
  // slow phases of the shared machine hit all of them alike.
  const unsigned int rounds = quick ? 3 : 21;

  struct Case
  {
    std::string name;
    Scene       scene;
  };
  const std::vector<Case> cases{
    {"full", paper_scene({1., 3.}, {{5.}})},
    {"partitioned", paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 6.}})}};

  std::vector<Point> points;
  std::cout << std::setprecision(3);
  for (const Case &c : cases)
    {
      const Scene &scene = c.scene;
      // Reference, and its own change from tolerance 1e-12 to 1e-13.
      StepSummary ref, tight;
      for (const double tol : {1e-12, 1e-13})
        {
          shooting::ShootingOptions o;
          o.tolerance = tol;
          const Outcome out = run_once(
            [&] { return std::make_unique<shooting::ShootingModel>(scene, o); }, scene);
          (tol == 1e-12 ? ref : tight) = out.last;
        }
      double ref_s2 = 0.;
      for (unsigned int k = 0; k < scene.n_rings(); ++k)
        ref_s2 = std::max(ref_s2, rel(ref.s2_ring_inner[k], tight.s2_ring_inner[k]));
      std::cout << "\n=== " << c.name << ": reference shooting tol 1e-12, displacement "
                << std::setprecision(12) << ref.displacement * 1e3 << " mm; change to tol "
                << "1e-13: displacement " << std::setprecision(3)
                << rel(ref.displacement, tight.displacement) << ", s2 " << ref_s2 << "\n";

      // One untimed run: the errors, and whether the run completes.
      const auto enumerate = [&](Point &pt) {
        pt.on                = &scene;
        pt.timing.outcome    = run_once(pt.build, scene);
        const StepSummary &s = pt.timing.outcome.last;
        pt.ok                = pt.timing.outcome.result.completed;
        if (pt.ok)
          {
            pt.disp_err = rel(s.displacement, ref.displacement);
            for (unsigned int k = 0; k < scene.n_rings(); ++k)
              pt.s2_err = std::max(pt.s2_err, rel(s.s2_ring_inner[k], ref.s2_ring_inner[k]));
          }
        points.push_back(pt);
      };

      // Shooting: tolerance sweep.
      for (double tol = 1e-2; tol > 0.5e-13; tol /= 10.)
        {
          shooting::ShootingOptions o;
          o.tolerance = tol;
          Point pt;
          pt.scene     = c.name;
          pt.method    = "shooting";
          pt.tolerance = tol;
          pt.build     = [&scene, o] {
            return std::make_unique<shooting::ShootingModel>(scene, o);
          };
          enumerate(pt);
        }

      // FE: for each p, a sweep of elements per ring (grading 4), until the
      // error reaches the reference's level or the mesh gets large.
      const std::vector<unsigned> sweep{1,  2,  3,  4,  6,   8,   12,  16,  24,
                                        32, 48, 64, 96, 128, 192, 256, 384, 512};
      for (unsigned p = 1; p <= 6; ++p)
        for (const unsigned n : sweep)
          {
            if (p * n * scene.n_rings() > 1100)
              break;
            FeDiscretization d;
            d.degree            = p;
            d.elements_per_ring = n;
            Point pt;
            pt.scene             = c.name;
            pt.method            = "fe";
            pt.degree            = p;
            pt.elements_per_ring = n;
            pt.dofs              = 2 * (p * n * scene.n_rings() + 1);
            pt.build             = [&scene, d] {
              return std::make_unique<MembraneModel>(scene, d, NewtonSettings());
            };
            enumerate(pt);
            if (pt.ok && pt.disp_err < 1e-12)
              break;
          }
    }

  // Timing rounds.
  for (unsigned int r = 0; r < rounds; ++r)
    for (Point &pt : points)
      if (pt.ok)
        {
          const auto   w0 = std::chrono::steady_clock::now();
          const double c0 = cpu_seconds();
          run_once(pt.build, *pt.on);
          pt.cpu.push_back(cpu_seconds() - c0);
          pt.wall.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
        }
  std::cout << "\nCPU time of a whole run: median over " << rounds
            << " rounds (every configuration once per round); minimum and wall-clock median "
               "in brackets\n";
  std::string scene_name;
  for (Point &pt : points)
    {
      if (pt.ok)
        {
          pt.timing.cpu         = median(pt.cpu);
          pt.timing.cpu_min     = *std::min_element(pt.cpu.begin(), pt.cpu.end());
          pt.timing.wall        = median(pt.wall);
          pt.timing.repetitions = pt.cpu.size();
        }
      if (pt.scene != scene_name)
        std::cout << "--- " << (scene_name = pt.scene) << "\n";
      std::cout << std::left << std::setw(30) << pt.label() << std::right << std::setw(6)
                << pt.dofs << "  cpu " << std::setw(9) << pt.timing.cpu * 1e3 << " ms (min "
                << std::setw(8) << pt.timing.cpu_min * 1e3 << ", wall " << std::setw(8)
                << pt.timing.wall * 1e3 << ")  disp err " << std::setw(9) << pt.disp_err
                << "  s2 err " << std::setw(9) << pt.s2_err << (pt.ok ? "" : "  FAILED: ")
                << (pt.ok ? "" : pt.timing.outcome.result.message) << "\n";
    }

  // Cheapest configuration per accuracy level, per scene and method.
  std::cout << "\nCheapest run reaching each accuracy in displacement (CPU-time medians):\n";
  for (const Case &c : cases)
    {
      std::cout << c.name << "\n"
                << std::setw(8) << "target" << std::setw(34) << "FE" << std::setw(10) << "ms"
                << std::setw(30) << "shooting" << std::setw(10) << "ms" << std::setw(10)
                << "FE/shoot" << "\n";
      for (int e = 3; e <= 9; ++e)
        {
          const double target = std::pow(10., -e);
          const Point *best[2] = {nullptr, nullptr};
          for (const Point &pt : points)
            if (pt.scene == c.name && pt.ok && pt.disp_err <= target)
              {
                const int m = pt.method == "fe" ? 0 : 1;
                if (!best[m] || pt.timing.cpu < best[m]->timing.cpu)
                  best[m] = &pt;
              }
          std::cout << std::setw(8) << target;
          for (const Point *b : best)
            if (b)
              std::cout << std::setw(34 - 4 * (b == best[1])) << b->label() << std::setw(10)
                        << b->timing.cpu * 1e3;
            else
              std::cout << std::setw(34 - 4 * (b == best[1])) << "none" << std::setw(10) << "-";
          if (best[0] && best[1])
            std::cout << std::setw(10) << best[0]->timing.cpu / best[1]->timing.cpu;
          std::cout << "\n";
        }
    }

  // Default discretization: cheapest FE configuration with displacement error
  // <= 1e-5 and s2 error <= 1e-3 on every scene (time summed over the scenes).
  {
    std::map<std::pair<unsigned, unsigned>, std::pair<double, unsigned>> fe;
    std::map<std::pair<unsigned, unsigned>, double>                      worst_disp, worst_s2;
    for (const Point &pt : points)
      if (pt.method == "fe")
        {
          const auto key = std::make_pair(pt.degree, pt.elements_per_ring);
          if (pt.ok && pt.disp_err <= 1e-5 && pt.s2_err <= 1e-3)
            {
              fe[key].first += pt.timing.cpu;
              fe[key].second += 1;
            }
          worst_disp[key] = std::max(worst_disp[key], pt.ok ? pt.disp_err : 1.);
          worst_s2[key]   = std::max(worst_s2[key], pt.ok ? pt.s2_err : 1.);
        }
    std::vector<std::pair<double, std::pair<unsigned, unsigned>>> ok;
    for (const auto &[key, v] : fe)
      if (v.second == cases.size())
        ok.push_back({v.first, key});
    std::sort(ok.begin(), ok.end());
    std::cout << "\nFE discretizations meeting 1e-5 in displacement and 1e-3 in s2 on both "
                 "scenes, cheapest first (CPU ms summed over the two scenes):\n";
    for (std::size_t i = 0; i < std::min<std::size_t>(ok.size(), 12); ++i)
      {
        const auto key = ok[i].second;
        std::cout << "  p=" << key.first << ", " << std::setw(3) << key.second
                  << "/ring: " << std::setw(8) << ok[i].first * 1e3 << " ms, worst disp err "
                  << worst_disp[key] << ", worst s2 err " << worst_s2[key] << "\n";
      }
    const FeDiscretization defaults;
    const auto def = std::make_pair(defaults.degree, defaults.elements_per_ring);
    if (fe.count(def))
      std::cout << "  (the default p=" << def.first << ", " << def.second
                << "/ring: " << fe[def].first * 1e3
                << " ms, worst disp err " << worst_disp[def] << ", worst s2 err "
                << worst_s2[def] << ")\n";
  }

  // Candidate default discretizations on every validation scene: worst
  // errors against the shooting model (tolerance 1e-12), onsets included.
  {
    std::cout << "\nCandidate defaults on the " << validation_scenes().size()
              << " scenes of tests/test_validation_agreement.cc (worst over the scenes; s2 "
                 "error relative, or absolute in s2/mu where |s2/mu| < 0.01):\n";
    SteppingSettings st;
    st.onset_tolerance = 1e-4;
    std::vector<Outcome> refs;
    for (const auto &[name, scene] : validation_scenes())
      {
        shooting::ShootingOptions o;
        o.tolerance = 1e-12;
        shooting::ShootingModel m(scene, o);
        LoadStepper             stepper(scene, m, st);
        Outcome                 out;
        stepper.on_step = [&](const StepSummary &s) { out.last = s; };
        out.result      = stepper.run();
        refs.push_back(out);
      }
    struct Candidate
    {
      FeDiscretization    d;
      double              disp = 0., s2 = 0., onset = 0.;
      std::string         worst_s2_scene, failures;
      std::vector<double> cpu; ///< all twelve runs, one entry per round
    };
    std::vector<Candidate> candidates;
    for (const auto &[p, n, grading] : std::vector<std::tuple<unsigned, unsigned, double>>{
           {3, 8, 4.}, {2, 8, 4.}, {3, 4, 4.}, {3, 6, 4.}, {4, 2, 4.}, {4, 3, 4.}, {4, 4, 4.},
           {5, 2, 4.}, {5, 3, 4.}, {4, 2, 8.}, {4, 3, 8.}, {3, 4, 8.}, {3, 6, 8.}})
      {
        Candidate c;
        c.d.degree            = p;
        c.d.elements_per_ring = n;
        c.d.grading           = grading;
        unsigned int i        = 0;
        for (const auto &[name, scene] : validation_scenes())
          {
            MembraneModel m(scene, c.d, NewtonSettings());
            LoadStepper   stepper(scene, m, st);
            Outcome       out;
            stepper.on_step    = [&](const StepSummary &s) { out.last = s; };
            out.result         = stepper.run();
            const Outcome &ref = refs[i++];
            if (!out.result.completed || out.result.onset.found != ref.result.onset.found)
              {
                c.failures += " " + name;
                continue;
              }
            c.disp = std::max(c.disp, rel(out.last.displacement, ref.last.displacement));
            for (unsigned int k = 0; k < scene.n_rings(); ++k)
              {
                const double mu = scene.material.shear_modulus;
                const double a  = out.last.s2_ring_inner[k] / mu;
                const double b  = ref.last.s2_ring_inner[k] / mu;
                const double e =
                  std::abs(b) >= 0.01 ? std::abs(a - b) / std::abs(b) : std::abs(a - b);
                if (e > c.s2)
                  {
                    c.s2             = e;
                    c.worst_s2_scene = name;
                  }
              }
            if (ref.result.onset.found)
              for (unsigned int k = 0; k < scene.n_rings(); ++k)
                c.onset = std::max(c.onset, std::abs(out.result.onset.voltages[k] -
                                                     ref.result.onset.voltages[k]));
          }
        candidates.push_back(c);
      }
    // Timing: the twelve runs of every candidate once per round, interleaved.
    const unsigned int candidate_rounds = quick ? 1 : 9;
    for (unsigned int r = 0; r < candidate_rounds; ++r)
      for (Candidate &c : candidates)
        {
          const double c0 = cpu_seconds();
          for (const auto &[name, scene] : validation_scenes())
            {
              MembraneModel m(scene, c.d, NewtonSettings());
              LoadStepper   stepper(scene, m, st);
              stepper.run();
            }
          c.cpu.push_back(cpu_seconds() - c0);
        }
    for (const Candidate &c : candidates)
      std::cout << "  p=" << c.d.degree << ", " << c.d.elements_per_ring << "/ring, grading "
                << c.d.grading << ": all " << validation_scenes().size() << " runs "
                << median(c.cpu) * 1e3 << " ms (CPU, median of " << candidate_rounds
                << " rounds); worst disp " << c.disp << ", s2 " << c.s2 << " ("
                << c.worst_s2_scene << "), onset voltage " << c.onset << " V"
                << (c.failures.empty() ? "" : "; run or onset differs on:" + c.failures)
                << "\n";
  }

  // Where the FE time goes: per-call costs at the end state of the default
  // discretization and of the smallest one, and of one shooting solve.
  {
    const Scene &scene = cases.front().scene;
    std::cout << "\nCost break-down on '" << cases.front().name << "' (CPU-time medians of "
              << "101 calls):\n";
    const auto per_call = [](const std::function<void()> &f) {
      std::vector<double> v;
      for (int i = 0; i < 101; ++i)
        {
          const double c0 = cpu_seconds();
          f();
          v.push_back(cpu_seconds() - c0);
        }
      return median(v);
    };
    LoadState load;
    load.stage    = Stage::voltage;
    load.stretch  = scene.prestretch;
    load.force    = scene.dead_load();
    load.mass     = scene.mass;
    load.voltages = {scene.path.voltages(scene.path.n_segments())[0] + 1.};
    for (const auto &[p, n] : std::vector<std::pair<unsigned, unsigned>>{{1, 1}, {3, 8}})
      {
        FeDiscretization d;
        d.degree            = p;
        d.elements_per_ring = n;
        const double t_build =
          per_call([&] { MembraneModel m(scene, d, NewtonSettings()); });
        MembraneModel m(scene, d, NewtonSettings());
        const Outcome out = [&] {
          LoadStepper stepper(scene, m, SteppingSettings());
          Outcome     o;
          stepper.on_step = [&](const StepSummary &s) { o.last = s; };
          o.result        = stepper.run();
          return o;
        }();
        const auto        state = m.state();
        unsigned int      its   = 0;
        const double      t_solve = per_call([&] {
          m.set_state(state);
          its = m.solve(load).iterations;
        });
        const double t_summary  = per_call([&] { (void)m.summary(); });
        const double t_residual = per_call([&] { (void)m.residual_vector(); });
        double       eigenvalue = 0.;
        const double t_eigen    = per_call([&] { eigenvalue = m.min_tangent_eigenvalue(); });
        std::cout << "  FE p=" << p << ", " << n << "/ring (" << m.n_dofs()
                  << " unknowns): build " << t_build * 1e6 << " us; a solve 1 V away "
                  << t_solve * 1e6 << " us (" << its << " Newton iterations, i.e. "
                  << t_solve / std::max(1u, its) * 1e6 << " us each); summary() "
                  << t_summary * 1e6 << " us; a residual " << t_residual * 1e6
                  << " us; the stability eigenvalue (cdea run: every step) " << t_eigen * 1e6
                  << " us (" << eigenvalue << " N/m); a whole run: " << out.result.solves
                  << " solves, "
                  << out.result.newton_iterations << " Newton iterations, "
                  << out.result.steps << " steps\n";
      }
    // A whole run through the profiling wrapper (medians would need many
    // runs; this is one run after a warm-up, to show the proportions).
    std::cout << "  where the time of one whole run goes (CPU time, one run after a warm-up):\n";
    for (int which = 0; which < 3; ++which)
      {
        std::unique_ptr<EquilibriumModel> model;
        std::string                       name;
        if (which < 2)
          {
            const unsigned p = which == 0 ? 3 : 5, n = which == 0 ? 8 : 1;
            model = std::make_unique<MembraneModel>(scene, [&] {
              FeDiscretization d;
              d.degree            = p;
              d.elements_per_ring = n;
              return d;
            }(), NewtonSettings());
            name  = "FE p=" + std::to_string(p) + ", " + std::to_string(n) + "/ring";
          }
        else
          {
            shooting::ShootingOptions o;
            o.tolerance = 1e-9;
            model       = std::make_unique<shooting::ShootingModel>(scene, o);
            name        = "shooting tol 1e-9";
          }
        for (int warm = 0; warm < 2; ++warm)
          {
            Profiled    profiled(*model);
            LoadStepper stepper(scene, profiled, SteppingSettings());
            const double c0    = cpu_seconds();
            stepper.run();
            const double total = cpu_seconds() - c0;
            if (warm == 0)
              continue;
            double accounted = 0.;
            std::cout << "    " << name << ": " << total * 1e3 << " ms;";
            for (const auto &[fn, a] : profiled.accounts)
              {
                accounted += a.seconds;
                std::cout << ' ' << fn << ' ' << a.calls << "x " << a.seconds * 1e3 << " ms ("
                          << std::setprecision(2) << 100. * a.seconds / total << " %)"
                          << std::setprecision(3) << ';';
              }
            std::cout << " driver and the rest " << (total - accounted) * 1e3 << " ms\n";
          }
      }
    for (const double tol : {1e-5, 1e-9})
      {
        shooting::ShootingOptions o;
        o.tolerance = tol;
        shooting::ShootingModel m(scene, o);
        LoadStepper             stepper(scene, m, SteppingSettings());
        const RunResult         r     = stepper.run();
        const auto              state = m.state();
        const double            t     = per_call([&] {
          m.set_state(state);
          m.solve(load);
        });
        std::cout << "  shooting tol " << tol << ": a solve 1 V away " << t * 1e6 << " us ("
                  << m.statistics().root_iterations << " integrations, "
                  << m.statistics().rhs_evaluations << " right-hand sides); a whole run: "
                  << r.solves << " solves\n";
      }
  }

  std::ofstream csv(dir / "work_precision.csv");
  csv << "scene,method,degree,elements_per_ring,tolerance,dofs,cpu_median_s,cpu_min_s,"
         "wall_median_s,repetitions,disp_err,s2_err,completed\n";
  csv << std::setprecision(6) << std::scientific;
  for (const Point &pt : points)
    csv << pt.scene << ',' << pt.method << ',' << pt.degree << ',' << pt.elements_per_ring
        << ',' << pt.tolerance << ',' << pt.dofs << ',' << pt.timing.cpu << ','
        << pt.timing.cpu_min << ',' << pt.timing.wall << ',' << pt.timing.repetitions << ','
        << pt.disp_err << ',' << pt.s2_err << ',' << int(pt.ok) << '\n';
  std::cout << "\nwrote " << (dir / "work_precision.csv").string() << "\n";
  return 0;
}
