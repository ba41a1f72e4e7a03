// Where each method fails, and the paper's operating lines (issue 3, items 6
// and 7; doc/validation.md, "Where each method fails" and "Comparison with
// the paper").
//
// Part 1, along the full-electrode path (0 to 7 kV) and the r_v/a = 1.7 path
// (both rings to 5 kV, then the outer ring to 7.5 kV and on to 8 kV):
//  - the voltage where Newton load stepping of the FE model stops (default,
//    coarse and refined meshes) and where single shooting with continuation
//    stops (default driver settings), with the reason each one gives;
//  - the whole solution curve: the stable branch by load stepping with the
//    shooting model, then, past the largest shooting angle theta0 of that
//    branch, the voltage that solves the shooting problem at each fixed
//    theta0 (theta0 parametrizes the curve through the fold), so that folds
//    (limit points) in the voltage are found exactly (golden section on
//    V(theta0)), also the unstable branch behind the fold and the far branch
//    where a global root search in theta0 would land;
//  - cold starts: one solve straight to each voltage (shooting from the
//    weightless pre-stretched film, FE from the weighted 0 V state) against
//    the continued solution;
//  - scans of the shooting residual r(B)/b - 1 over theta0 in (0, pi) at
//    several voltages: how many roots there are and where the integration
//    itself fails;
//  - the wrinkling onset (s2 = 0) from FE meshes from very coarse to fine
//    (p = 1..4, 1 to 16 elements per ring, uniform and graded) against the
//    shooting onset: how far a coarse mesh shifts it, or misses it on a path
//    that ends at the experiment's 5.5 kV.
// Part 2, two-ring layouts r_v/a = 1.3 .. 2.4 with the inner ring held at 5 kV
// or 5.5 kV: starting from both rings at the inner voltage, the outer voltage
// is raised and the paper's lines are located by scalar root solves on it:
//   blue line: s2 at the two rings' inner edges equal;
//   red line:  s2 = 0 at the inner edge of the outer ring (loss of tension).
// The stroke (displacement minus its value at 0 V under the weight) there is
// compared with the stroke with both rings at the inner voltage. FE
// (p = 4, 16 graded elements per ring) and shooting (tolerance 1e-12) each
// do this; their difference is printed.
//
// Writes CSV files into DIR (default results/validation): failure_steps.csv,
// failure_curve.csv, failure_residual.csv, failure_onset_mesh.csv,
// paper_lines.csv.
//
//   build/benchmarks/bench_failure_modes [DIR]

#include <cdea/numerics/bracketed_root.h>
#include <cdea/app/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/meridian.h>
#include <cdea/shooting/shooting_model.h>
#include <cdea/solver/load_stepper.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cdea;

namespace
{
  constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();


  FeDiscretization fe_disc(const unsigned p, const unsigned n, const double grading = 4.,
                           const unsigned refinements = 0)
  {
    FeDiscretization d;
    d.degree            = p;
    d.elements_per_ring = n;
    d.grading           = grading;
    d.refinements       = refinements;
    return d;
  }

  // ---------------------------------------------------------------------
  // Load stepping along a path: every converged voltage step.

  struct PathRun
  {
    RunResult                result;
    std::vector<StepSummary> steps; ///< voltage stage
  };

  PathRun step_path(EquilibriumModel &model, const Scene &scene,
                    const SteppingSettings &settings = SteppingSettings())
  {
    LoadStepper stepper(scene, model, settings);
    PathRun     out;
    stepper.on_step = [&](const StepSummary &s) {
      if (s.stage == Stage::voltage)
        out.steps.push_back(s);
    };
    out.result = stepper.run();
    return out;
  }

  // ---------------------------------------------------------------------
  // The solution set of the shooting problem in the plane (theta0, V), where
  // V is the voltage of ring `varying` and the other rings keep `base`.

  class AngleVoltagePlane
  {
  public:
    AngleVoltagePlane(const Scene &scene, const std::vector<double> &base,
                      const unsigned varying, const double tolerance)
      : scene(scene)
      , base(base)
      , varying(varying)
      , integrator(scene, [&] {
        shooting::ShootingOptions o;
        o.tolerance = tolerance;
        return o;
      }())
    {}

    /// Residual r(B)/b - 1 (nullopt if the integration fails) and the profile.
    std::optional<double> residual(const double theta0, const double V,
                                   shooting::Profile *profile = nullptr)
    {
      shooting::MeridianLoad load{scene.prestretch, scene.dead_load(), base};
      load.voltages[varying] = V;
      const shooting::Profile p = integrator.shoot(load, theta0, l1_guess, false);
      if (!p.ok)
        return std::nullopt;
      l1_guess = p.lambda1_start;
      if (profile)
        *profile = p;
      return p.r_end / (scene.prestretch * scene.outer_reference_radius()) - 1.;
    }

    /// V with residual zero at fixed theta0 (secant from V0).
    std::optional<double> voltage_at(const double theta0, const double V0)
    {
      double      a  = V0, b = V0 + 1.;
      const auto  fa = residual(theta0, a);
      auto        fb = residual(theta0, b);
      if (!fa || !fb)
        return std::nullopt;
      double f0 = *fa, f1 = *fb;
      for (int k = 0; k < 60; ++k)
        {
          if (std::abs(f1) < 1e-14)
            return b;
          double step = -f1 * (b - a) / (f1 - f0);
          step        = std::clamp(step, -300., 300.);
          a           = b;
          f0          = f1;
          b += step;
          const auto f = residual(theta0, b);
          if (!f)
            return std::nullopt;
          f1 = *f;
          if (std::abs(b - a) < 1e-9)
            return b;
        }
      return std::nullopt;
    }

    /// Extremum of V(theta0) in [lo, hi] (golden section), from a guess V0.
    std::pair<double, double> extremum(double lo, double hi, const double V0, const bool max)
    {
      const double g  = 0.5 * (std::sqrt(5.) - 1.);
      double       V  = V0;
      const auto   Vf = [&](const double th) {
        const auto v = voltage_at(th, V);
        if (!v)
          throw std::runtime_error("extremum: no solution at theta0 " + std::to_string(th));
        V = *v;
        return max ? V : -V;
      };
      double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
      double f1 = Vf(x1), f2 = Vf(x2);
      while (hi - lo > 1e-9)
        if (f1 > f2)
          {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = Vf(x1);
          }
        else
          {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = Vf(x2);
          }
      const double th = 0.5 * (lo + hi);
      return {th, max ? Vf(th) : -Vf(th)};
    }

    struct CurvePoint
    {
      double theta0, V, displacement, s2_min;
      int    branch; ///< 0 before the first fold in V, then 1, 2, ...
    };

    struct Turn
    {
      double theta0, V, displacement;
      bool   maximum;
    };

    /// The solution curve as V(theta0), walking theta0 down from theta_start
    /// (a solution at V_start, past the largest theta0 of the stable branch,
    /// where theta0 parametrizes the curve) to theta_stop. Folds in V are
    /// located by golden section in theta0.
    std::vector<CurvePoint> walk(const double theta_start, const double V_start,
                                 const double V_previous, const double theta_stop,
                                 std::vector<Turn> &turns)
    {
      std::vector<CurvePoint> curve;
      double th = theta_start, V = V_start, slope = 0.;
      double dth = 0.002;
      int    branch = 0;
      (void)V_previous;
      while (th > theta_stop)
        {
          const auto v = voltage_at(th, V);
          if (!v)
            {
              if (curve.empty() || dth < 1e-7)
                break;
              th += dth;
              V = curve.back().V;
              dth *= 0.5;
              th -= dth;
              V += slope * dth;
              continue;
            }
          shooting::Profile p;
          residual(th, *v, &p);
          if (!curve.empty())
            slope = (*v - curve.back().V) / (curve.back().theta0 - th);
          if (curve.size() >= 2)
            {
              const double d1 = curve[curve.size() - 1].V - curve[curve.size() - 2].V;
              const double d2 = *v - curve.back().V;
              if (d1 * d2 < 0.)
                {
                  const bool max = d1 > 0.;
                  const auto [t, Vt] =
                    extremum(th, curve[curve.size() - 2].theta0, curve.back().V, max);
                  shooting::Profile q;
                  residual(t, Vt, &q);
                  turns.push_back({t, Vt, q.displacement, max});
                  ++branch;
                }
            }
          curve.push_back({th, *v, p.displacement, p.s2_min, branch});
          V = *v + slope * dth;
          th -= dth;
          dth = std::min(0.004, 1.5 * dth);
        }
      return curve;
    }

  private:
    Scene                         scene;
    std::vector<double>           base;
    unsigned                      varying;
    shooting::MeridianIntegrator  integrator;
    double                        l1_guess = -1.;
  };

  // ---------------------------------------------------------------------
  // Paper lines at fixed inner voltage.

  struct LinePoint
  {
    bool                found = false;
    double              Vo = not_a_number, displacement = not_a_number;
    std::vector<double> s2; ///< s2 at the rings' inner edges there (Pa)
  };

  struct Lines
  {
    double              displacement_0V = not_a_number, displacement_base = not_a_number;
    std::vector<double> s2_base; ///< s2 at the rings' inner edges, both rings at Vi (Pa)
    std::vector<LinePoint> points; ///< one per target function
    double              last_Vo = not_a_number;
    std::string         stop; ///< why the outer-voltage walk ended early (empty if not)
  };

  /// A function of the state whose zero marks a line; it may use the base values.
  using Target = std::function<double(const StepSummary &, const Lines &)>;

  const Target blue_line = [](const StepSummary &s, const Lines &) {
    return s.s2_ring_inner[0] - s.s2_ring_inner[1];
  };
  const Target red_line = [](const StepSummary &s, const Lines &) {
    return s.s2_ring_inner[1];
  };

  /// Run @p model (a two-ring scene, edges 1, r_v, 3) to both rings at Vi,
  /// then raise the outer voltage in steps of at most 50 V and locate the
  /// first zero of every target by Illinois on the outer voltage (every trial
  /// solved from the converged state below it), to 1e-6 V.
  Lines locate_lines(EquilibriumModel &model, const double r_v, const double Vi,
                     const double Vo_max, const std::vector<Target> &targets)
  {
    Scene       scene = paper_scene({1., r_v, 3.}, {{Vi * 1e-3, Vi * 1e-3}});
    Lines       lines;
    LoadStepper stepper(scene, model, SteppingSettings());
    stepper.on_step = [&](const StepSummary &s) {
      if (s.stage == Stage::dead_load && s.load_factor == 1.)
        lines.displacement_0V = s.displacement;
    };
    const RunResult r = stepper.run();
    if (!r.completed)
      throw std::runtime_error("locate_lines: no equilibrium at the inner voltage: " +
                               r.message);
    lines.displacement_base = model.summary().displacement;
    lines.s2_base           = model.summary().s2_ring_inner;
    lines.points.resize(targets.size());

    LoadState load = stepper.load(Stage::voltage, 1.);
    const auto at  = [&](const double Vo) {
      load.voltages = {Vi, Vo};
      return load;
    };
    const double g_tol = 1e-12 * scene.material.shear_modulus;

    // Root of a line function by the project's bracketed root finder; each
    // solve starts from the nearest converged state on the starting side.
    const auto root = [&](const Target &g, double lo, ModelState state_lo, double g_lo,
                          double hi, double g_hi) {
      LinePoint  p;
      double     best = std::numeric_limits<double>::infinity();
      const auto f    = [&](const double V) {
        model.set_state(state_lo);
        if (!model.solve(at(V)).converged)
          return std::numeric_limits<double>::quiet_NaN();
        const StepSummary s  = model.summary();
        const double      gv = g(s, lines);
        if (std::abs(gv) < best)
          {
            best = std::abs(gv);
            p    = {true, V, s.displacement, s.s2_ring_inner};
          }
        if ((gv > 0.) == (g_lo > 0.))
          state_lo = model.state();
        return gv;
      };
      BracketedRootSettings settings;
      settings.x_tolerance     = 1e-6;
      settings.f_tolerance     = g_tol;
      settings.max_evaluations = 200;
      find_bracketed_root(f, lo, g_lo, hi, g_hi, settings);
      return p;
    };

    const auto all_found = [&] {
      for (const LinePoint &p : lines.points)
        if (!p.found)
          return false;
      return true;
    };
    double              Vo = Vi, dV = 50.;
    ModelState          state = model.state();
    StepSummary         prev  = model.summary();
    while (Vo < Vo_max && !all_found())
      {
        const double Vn = std::min(Vo + dV, Vo_max);
        if (!model.solve(at(Vn)).converged)
          {
            model.set_state(state);
            dV *= 0.5;
            if (dV < 1e-3)
              {
                std::ostringstream m;
                m << "no equilibrium beyond outer " << Vo * 1e-3 << " kV (fold)";
                lines.stop = m.str();
                break;
              }
            continue;
          }
        const StepSummary         s    = model.summary();
        const ModelState next = model.state();
        for (std::size_t i = 0; i < targets.size(); ++i)
          {
            const double g0 = targets[i](prev, lines), g1 = targets[i](s, lines);
            if (!lines.points[i].found && g0 * g1 <= 0. && g0 != g1)
              {
                lines.points[i] = root(targets[i], Vo, state, g0, Vn, g1);
                model.set_state(next);
              }
          }
        Vo    = Vn;
        state = next;
        prev  = s;
        dV    = std::min(50., 2. * dV);
      }
    lines.last_Vo = Vo;
    return lines;
  }

  double pct(const double stroke, const double stroke_base)
  {
    return 100. * (stroke / stroke_base - 1.);
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession            mpi(argc, argv);
  const std::filesystem::path dir = argc > 1 ? argv[1] : "results/validation";
  std::filesystem::create_directories(dir);
  std::cout << std::setprecision(7);

  std::ofstream steps_csv(dir / "failure_steps.csv");
  steps_csv << "case,method,V_kV,displacement_mm,s2_min_over_mu\n" << std::setprecision(10);
  std::ofstream curve_csv(dir / "failure_curve.csv");
  curve_csv << "case,theta0,V_kV,displacement_mm,s2_min_over_mu,branch\n" << std::setprecision(10);
  std::ofstream residual_csv(dir / "failure_residual.csv");
  residual_csv << "case,V_kV,theta0,residual,ok\n" << std::setprecision(8);
  std::ofstream onset_csv(dir / "failure_onset_mesh.csv");
  onset_csv << "case,degree,elements_per_ring,grading,dofs,onset_kV,reference_kV\n"
            << std::setprecision(10);

  struct PathCase
  {
    std::string name;
    Scene       scene;     ///< the path to the end of the issue's range
    Scene       extended;  ///< continued to find the fold
    Scene       onset_path; ///< for the mesh study of the onset
    std::vector<double> base; ///< ring voltages of the angle-voltage plane (V)
    unsigned            varying;
    double              V_start;
  };
  const std::vector<PathCase> paths{
    {"full", paper_scene({1., 3.}, {{7.}}), paper_scene({1., 3.}, {{7.}}),
     paper_scene({1., 3.}, {{6.6}}), {0.}, 0, 0.},
    {"rv1.7", paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 7.5}}),
     paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 8.}}),
     paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 7.5}}), {5000., 5000.}, 1, 5000.}};

  double           full_onset_V = not_a_number;
  SteppingSettings fine_stepping;
  fine_stepping.onset_tolerance = 1e-4;
  const double mu = Scene().material.shear_modulus;

  for (const PathCase &pc : paths)
    {
      std::cout << "\n=============== path '" << pc.name << "' ===============\n";
      const auto last_V = [&](const PathRun &r) {
        return r.steps.empty() ? not_a_number : r.steps.back().voltages.back();
      };
      // Load stepping, each method, to the end of the range and on.
      for (const Scene *scene : {&pc.scene, &pc.extended})
        {
          if (scene == &pc.extended && pc.name == "full")
            continue;
          const double V_end = scene->path.voltages(scene->path.n_segments()).back();
          std::cout << "-- load stepping to " << V_end * 1e-3 << " kV (default stepping)\n";
          struct Method
          {
            std::string                       name;
            std::unique_ptr<EquilibriumModel> model;
          };
          std::vector<Method> methods;
          methods.push_back(
            {"FE p=3, 8/ring (default)",
             std::make_unique<MembraneModel>(*scene, fe_disc(3, 8), NewtonSettings())});
          methods.push_back(
            {"FE p=2, 2/ring (coarse)",
             std::make_unique<MembraneModel>(*scene, fe_disc(2, 2), NewtonSettings())});
          methods.push_back(
            {"FE p=4, 32/ring (refined)",
             std::make_unique<MembraneModel>(*scene, fe_disc(4, 16, 4., 1), NewtonSettings())});
          for (const double tol : {1e-10, 1e-12})
            {
              shooting::ShootingOptions o;
              o.tolerance = tol;
              std::ostringstream name;
              name << "shooting tol " << tol << (tol == 1e-10 ? " (default)" : "");
              methods.push_back({name.str(), std::make_unique<shooting::ShootingModel>(*scene, o)});
            }
          for (Method &m : methods)
            {
              const PathRun r = step_path(*m.model, *scene);
              std::cout << "  " << std::left << std::setw(30) << m.name << std::right
                        << (r.result.completed ? "completed" : "STOPPED") << " at "
                        << std::setprecision(10) << last_V(r) << " V, displacement "
                        << (r.steps.empty() ? not_a_number : r.steps.back().displacement * 1e3)
                        << " mm" << std::setprecision(7);
              if (r.result.onset.found)
                std::cout << "; onset " << std::setprecision(10)
                          << r.result.onset.voltages.back() << " V" << std::setprecision(7);
              std::cout << "\n";
              if (!r.result.completed)
                std::cout << "      reason: " << r.result.message << "\n";
              if (scene == &pc.extended || pc.name == "full")
                {
                  std::string label = m.name; // no commas inside a CSV field
                  std::replace(label.begin(), label.end(), ',', ';');
                  for (const StepSummary &s : r.steps)
                    steps_csv << pc.name << ',' << label << ',' << s.voltages.back() * 1e-3
                              << ',' << s.displacement * 1e3 << ',' << s.s2_min / mu << '\n';
                }
            }
        }

      // The solution curve in the (theta0, V) plane, from the start state.
      std::cout << "-- solution curve: stable branch by load stepping (20 V steps), then "
                   "V(theta0) at fixed shooting angles; shooting tolerance 1e-12\n";
      {
        // The stable branch by load stepping in small voltage steps, then
        // V(theta0) from a point past the largest theta0 of that branch.
        shooting::ShootingOptions o;
        o.tolerance = 1e-12;
        shooting::ShootingModel sm(pc.extended, o);
        SteppingSettings        small;
        small.voltage_increment = 20.;
        struct Sample
        {
          double theta0, V, displacement, s2_min;
        };
        std::vector<Sample> stable;
        {
          LoadStepper stepper(pc.extended, sm, small);
          stepper.on_step = [&](const StepSummary &s) {
            if (s.stage == Stage::voltage && s.voltages.back() >= pc.V_start)
              stable.push_back(
                {sm.shooting_angle(), s.voltages.back(), s.displacement, s.s2_min});
          };
          stepper.run();
        }
        std::size_t top = 0;
        for (std::size_t i = 0; i < stable.size(); ++i)
          if (stable[i].theta0 > stable[top].theta0)
            top = i;
        std::size_t start = top;
        while (start + 1 < stable.size() && stable[start].theta0 > stable[top].theta0 - 0.01)
          ++start;
        AngleVoltagePlane plane(pc.scene, pc.base, pc.varying, 1e-12);
        std::vector<AngleVoltagePlane::Turn> turns;
        const auto curve = plane.walk(stable[start].theta0, stable[start].V,
                                      stable[start - 1].V, 0.03, turns);
        for (std::size_t i = 0; i < start; ++i)
          curve_csv << pc.name << ',' << stable[i].theta0 << ',' << stable[i].V * 1e-3 << ','
                    << stable[i].displacement * 1e3 << ',' << stable[i].s2_min / mu << ",0\n";
        for (const auto &p : curve)
          curve_csv << pc.name << ',' << p.theta0 << ',' << p.V * 1e-3 << ','
                    << p.displacement * 1e3 << ',' << p.s2_min / mu << ',' << p.branch << '\n';
        std::cout << "  stable branch by stepping: " << start << " points to " << stable[start].V
                  << " V (largest theta0 " << stable[top].theta0 << " at " << stable[top].V
                  << " V); then " << curve.size() << " points of V(theta0) down to theta0 = "
                  << curve.back().theta0 << " (V = " << curve.back().V << ")\n";
        for (const auto &t : turns)
          std::cout << "  fold (" << (t.maximum ? "largest" : "smallest")
                    << " voltage on its branch): V = " << std::setprecision(10) << t.V
                    << " V at theta0 = " << t.theta0 << ", displacement "
                    << t.displacement * 1e3 << " mm" << std::setprecision(7) << "\n";
      }

      // Cold starts: one solve straight to the target load, without
      // continuation in the voltage, against the continued solution.
      {
        std::cout << "-- cold starts (one solve from the weightless pre-stretched film for "
                     "shooting, from the weighted 0 V state for FE) against continuation\n";
        std::vector<double> Vs;
        const double        V_first = pc.name == "full" ? 500. : 5250.;
        const double        V_last  = pc.name == "full" ? 6630. : 7565.;
        for (double V = V_first; V < V_last - 1.; V += 250.)
          Vs.push_back(V);
        Vs.push_back(V_last);
        for (int method = 0; method < 2; ++method)
          {
            unsigned int n_ok = 0;
            double       worst = 0.;
            std::string  failures;
            for (const double V : Vs)
              {
                Scene target = pc.name == "full" ? paper_scene({1., 3.}, {{V * 1e-3}}) :
                                                   paper_scene({1., 1.7, 3.},
                                                              {{5., 5.}, {5., V * 1e-3}});
                std::unique_ptr<EquilibriumModel> cont, cold;
                if (method == 0)
                  {
                    shooting::ShootingOptions o;
                    o.tolerance = 1e-10;
                    cont        = std::make_unique<shooting::ShootingModel>(target, o);
                    cold        = std::make_unique<shooting::ShootingModel>(target, o);
                  }
                else
                  {
                    cont = std::make_unique<MembraneModel>(target, fe_disc(3, 8), NewtonSettings());
                    cold = std::make_unique<MembraneModel>(target, fe_disc(3, 8), NewtonSettings());
                  }
                const PathRun r = step_path(*cont, target);
                LoadStepper   driver(target, *cold, SteppingSettings());
                LoadState     flat = driver.load(Stage::dead_load, 0.);
                LoadState     weighted = driver.load(Stage::dead_load, 1.);
                const LoadState goal   = driver.load(Stage::voltage, target.path.n_segments());
                cold->set_reference_state();
                bool ok = cold->solve(flat).converged;
                if (method == 1)
                  ok = ok && cold->solve(weighted).converged;
                ok = ok && cold->solve(goal).converged && r.result.completed;
                if (ok)
                  {
                    ++n_ok;
                    worst = std::max(worst, std::abs(cold->summary().displacement -
                                                     r.steps.back().displacement));
                  }
                else
                  failures += " " + std::to_string(int(V));
              }
            std::cout << "  " << (method == 0 ? "shooting (tolerance 1e-10)" : "FE p=3, 8/ring")
                      << ": " << n_ok << " of " << Vs.size() << " voltages from " << V_first
                      << " to " << V_last << " V converged, largest |displacement - continued| "
                      << worst * 1e3 << " mm"
                      << (failures.empty() ? "" : "; no convergence at" + failures + " V")
                      << "\n";
          }
      }

      // Residual scans over theta0.
      std::cout << "-- shooting residual r(B)/b - 1 over theta0 in (0, pi), tolerance 1e-10\n";
      {
        const std::vector<double> Vs =
          pc.name == "full" ?
            std::vector<double>{0., 5000., 5500., 5600., 5700., 6000., 6500., 6630.} :
            std::vector<double>{5000., 6000., 6500., 7000., 7500., 7560.};
        AngleVoltagePlane plane(pc.scene, pc.base, pc.varying, 1e-10);
        for (const double V : Vs)
          {
            std::ostringstream roots;
            int                n_roots = 0;
            std::optional<double> prev;
            double                prev_th = 0., first_fail = not_a_number;
            const int             n       = 4000;
            for (int i = 1; i < n; ++i)
              {
                const double      th = M_PI * i / n;
                shooting::Profile p;
                const auto        f = plane.residual(th, V, &p);
                if (i % 4 == 0 || (f && prev && (*f > 0.) != (*prev > 0.)))
                  residual_csv << pc.name << ',' << V * 1e-3 << ',' << th << ','
                               << (f ? *f : not_a_number) << ',' << int(bool(f)) << '\n';
                if (!f && std::isnan(first_fail))
                  first_fail = th;
                if (f && prev && (*f > 0.) != (*prev > 0.))
                  {
                    ++n_roots;
                    roots << "  [theta0 ~ " << std::setprecision(4) << 0.5 * (th + prev_th)
                          << ": displacement " << p.displacement * 1e3 << " mm, min s2/mu "
                          << p.s2_min / mu << "]";
                  }
                prev    = f;
                prev_th = th;
              }
            std::cout << "  V = " << std::setprecision(6) << V * 1e-3 << " kV: " << n_roots
                      << " root(s)" << roots.str() << "; integration fails from theta0 = "
                      << first_fail << std::setprecision(7) << "\n";
          }
      }

      // Onset from coarse to fine meshes.
      std::cout << "-- wrinkling onset (s2 = 0) against the mesh, path to "
                << pc.onset_path.path.voltages(pc.onset_path.path.n_segments()).back() * 1e-3
                << " kV\n";
      {
        shooting::ShootingOptions o;
        o.tolerance = 1e-12;
        shooting::ShootingModel sm(pc.onset_path, o);
        const PathRun           ref = step_path(sm, pc.onset_path, fine_stepping);
        const double            V_ref = ref.result.onset.voltages.back();
        if (pc.name == "full")
          full_onset_V = V_ref;
        std::cout << "  shooting (tol 1e-12): onset at " << std::setprecision(10) << V_ref
                  << " V, r/a = " << ref.result.onset.radius / pc.onset_path.disk_radius
                  << std::setprecision(7) << "\n";
        std::cout << "   p  n/ring  grading  dofs    onset (V)   FE - shooting (V)\n";
        for (unsigned p = 1; p <= 4; ++p)
          for (const unsigned n : {1u, 2u, 4u, 8u, 16u})
            for (const double g : {1., 4.})
              {
                if (n == 1 && g == 4.)
                  continue; // one element: no grading
                MembraneModel fe(pc.onset_path, fe_disc(p, n, g), NewtonSettings());
                const PathRun r = step_path(fe, pc.onset_path, fine_stepping);
                const double  V =
                  r.result.onset.found ? r.result.onset.voltages.back() : not_a_number;
                onset_csv << pc.name << ',' << p << ',' << n << ',' << g << ',' << fe.n_dofs()
                          << ',' << V * 1e-3 << ',' << V_ref * 1e-3 << '\n';
                std::cout << std::setw(4) << p << std::setw(8) << n << std::setw(9) << g
                          << std::setw(6) << fe.n_dofs() << std::setw(13) << std::setprecision(8)
                          << V << std::setw(14) << std::setprecision(3) << V - V_ref
                          << (r.result.completed ? "" : "  (run stopped early)")
                          << std::setprecision(7) << "\n";
              }
      }
    }

  // -------------------------------------------------------------------
  // Part 2: the paper's lines.
  std::cout << "\n=============== paper lines (inner ring fixed, outer raised) ===============\n"
            << "stroke = displacement - displacement at 0 V under the weight; increases are "
               "relative to both rings at the inner voltage\n";
  std::ofstream lines_csv(dir / "paper_lines.csv");
  lines_csv << "method,Vi_kV,r_v,disp0_mm,disp_base_mm,blue_Vo_kV,blue_disp_mm,red_Vo_kV,"
               "red_disp_mm,last_Vo_kV,stop\n"
            << std::setprecision(10);
  struct LineResult
  {
    double Vi, r_v;
    Lines  fe, sh;
  };
  std::vector<LineResult> all_lines;
  for (const double Vi : {5000., 5500.})
    {
      std::cout << "\ninner " << Vi * 1e-3 << " kV\n"
                << "  r_v/a | blue: Vo (kV)  stroke +%  disp +% | red: Vo (kV)  stroke +%  "
                   "disp +% | FE - shooting: blue Vo, red Vo (V), red stroke (pts)\n";
      for (int i = 0; i <= 22; ++i)
        {
          const double r_v = 1.3 + 0.05 * i;
          Lines        result[2];
          for (int m = 0; m < 2; ++m)
            {
              const Scene scene = paper_scene({1., r_v, 3.}, {{Vi * 1e-3, Vi * 1e-3}});
              std::unique_ptr<EquilibriumModel> model;
              if (m == 0)
                model = std::make_unique<MembraneModel>(scene, fe_disc(4, 16), NewtonSettings());
              else
                {
                  shooting::ShootingOptions o;
                  o.tolerance = 1e-12;
                  model       = std::make_unique<shooting::ShootingModel>(scene, o);
                }
              result[m] = locate_lines(*model, r_v, Vi, 9000., {blue_line, red_line});
              const Lines &l = result[m];
              lines_csv << (m == 0 ? "fe" : "shooting") << ',' << Vi * 1e-3 << ',' << r_v << ','
                        << l.displacement_0V * 1e3 << ',' << l.displacement_base * 1e3 << ','
                        << l.points[0].Vo * 1e-3 << ',' << l.points[0].displacement * 1e3
                        << ',' << l.points[1].Vo * 1e-3 << ','
                        << l.points[1].displacement * 1e3 << ','
                        << l.last_Vo * 1e-3 << ',' << '"' << l.stop << '"' << '\n';
            }
          all_lines.push_back({Vi, r_v, result[0], result[1]});
          const Lines &l          = result[0];
          const double stroke_b   = l.displacement_base - l.displacement_0V;
          const auto   increase   = [&](const LinePoint &p) {
            return pct(p.displacement - l.displacement_0V, stroke_b);
          };
          const auto disp_increase = [&](const LinePoint &p) {
            return pct(p.displacement, l.displacement_base);
          };
          const Lines &s = result[1];
          std::cout << std::fixed << std::setprecision(2) << std::setw(7) << r_v << " | "
                    << std::setprecision(4) << std::setw(12) << l.points[0].Vo * 1e-3
                    << std::setprecision(2) << std::setw(10) << increase(l.points[0])
                    << std::setw(8) << disp_increase(l.points[0]) << " | "
                    << std::setprecision(4) << std::setw(11) << l.points[1].Vo * 1e-3
                    << std::setprecision(2) << std::setw(10) << increase(l.points[1])
                    << std::setw(8) << disp_increase(l.points[1]) << " | " << std::scientific
                    << std::setprecision(1) << std::setw(8) << l.points[0].Vo - s.points[0].Vo
                    << std::setw(9) << l.points[1].Vo - s.points[1].Vo << std::setw(9)
                    << increase(l.points[1]) -
                         pct(s.points[1].displacement - s.displacement_0V,
                             s.displacement_base - s.displacement_0V)
                    << std::defaultfloat << std::setprecision(7)
                    << (l.stop.empty() ? "" : "  " + l.stop) << "\n";
        }
    }

  // -------------------------------------------------------------------
  // The paper's claims, side by side (FE values; shooting in brackets).
  std::cout << "\n=============== comparison with the paper (FE p=4, 16/ring; shooting in "
               "brackets) ===============\n"
            << std::fixed << std::setprecision(2);
  const auto find = [&](const double Vi, const double r_v) -> const LineResult & {
    for (const LineResult &l : all_lines)
      if (l.Vi == Vi && std::abs(l.r_v - r_v) < 1e-9)
        return l;
    throw std::runtime_error("no line result");
  };
  const auto stroke_increase = [](const Lines &l, const LinePoint &p) {
    return pct(p.displacement - l.displacement_0V, l.displacement_base - l.displacement_0V);
  };
  const auto line_point = [](const Lines &l, const bool red) -> const LinePoint & {
    return l.points[red ? 1 : 0];
  };
  // Largest stroke increase along a line over r_v: parabola through the best
  // grid point and its neighbours.
  const auto best_on_line = [&](const double Vi, const bool red, const bool fe) {
    std::vector<std::pair<double, double>> v;
    for (const LineResult &l : all_lines)
      if (l.Vi == Vi)
        {
          const Lines &x = fe ? l.fe : l.sh;
          if (line_point(x, red).found)
            v.push_back({l.r_v, stroke_increase(x, line_point(x, red))});
        }
    std::size_t k = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (v[i].second > v[k].second)
        k = i;
    if (k == 0 || k + 1 == v.size())
      return v[k];
    const double h = v[k + 1].first - v[k].first;
    const double a = v[k - 1].second, b = v[k].second, c = v[k + 1].second;
    const double d = 0.5 * (a - c) / (a - 2 * b + c);
    return std::make_pair(v[k].first + d * h, b - 0.25 * (a - c) * d);
  };
  {
    const Lines &b50 = find(5000., 1.7).fe, &b55 = find(5500., 1.7).fe;
    std::cout << std::setprecision(5) << "displacement at 0 V under the weight "
              << b50.displacement_0V * 1e3 << " mm; stroke with both rings at 5 kV "
              << (b50.displacement_base - b50.displacement_0V) * 1e3 << " mm, at 5.5 kV "
              << (b55.displacement_base - b55.displacement_0V) * 1e3 << " mm\n"
              << std::setprecision(2);
    const Lines &l18 = find(5000., 1.8).fe;
    std::cout << "red line, inner 5 kV, r_v/a = 1.8, other baselines: displacement +"
              << pct(l18.points[1].displacement, l18.displacement_base)
              << " % over both at 5 kV; stroke +"
              << pct(l18.points[1].displacement - l18.displacement_0V,
                     b55.displacement_base - b55.displacement_0V)
              << " % over both at 5.5 kV\n";
  }
  const double s2_50 = find(5000., 1.7).fe.s2_base[0] / mu;
  const double s2_55 = find(5500., 1.7).fe.s2_base[0] / mu;
  std::cout << "full electrode: s2/mu at the disk edge " << std::setprecision(4) << s2_50
            << " at 5.0 kV, " << s2_55 << " at 5.5 kV; onset (s2 = 0) at "
            << std::setprecision(2) << full_onset_V << " V (paper: wrinkles at 5.5 kV, not at "
            << "5.0 kV)\n";
  for (const auto &[Vi, red, r_v, paper] :
       std::vector<std::tuple<double, bool, double, double>>{{5000., false, 1.7, 32.9},
                                                             {5000., true, 1.8, 40.5},
                                                             {5500., true, 2.0, 20.3}})
    {
      const LineResult &l  = find(Vi, r_v);
      const auto        bf = best_on_line(Vi, red, true), bs = best_on_line(Vi, red, false);
      std::cout << (red ? "red" : "blue") << " line, inner " << Vi * 1e-3 << " kV, r_v/a = "
                << r_v << ": outer " << std::setprecision(4)
                << line_point(l.fe, red).Vo * 1e-3 << " kV, stroke +" << std::setprecision(2)
                << stroke_increase(l.fe, line_point(l.fe, red)) << " % ["
                << stroke_increase(l.sh, line_point(l.sh, red)) << " %], displacement +"
                << pct(line_point(l.fe, red).displacement, l.fe.displacement_base)
                << " %; largest on the line: +" << bf.second << " % [" << bs.second
                << " %] at r_v/a = " << bf.first << " [" << bs.first << "]; paper +" << paper
                << " % at r_v/a = " << r_v << "\n";
    }
  {
    const LineResult &l14 = find(5000., 1.4), &l17 = find(5000., 1.7);
    const LineResult &b55 = find(5500., 1.7);
    std::cout << "experiment, r_v/a = 1.4, inner 5 kV, outer raised to wrinkling: model red "
                 "line outer "
              << std::setprecision(4) << l14.fe.points[1].Vo * 1e-3 << " kV, stroke +"
              << std::setprecision(2) << stroke_increase(l14.fe, l14.fe.points[1])
              << " %, displacement +"
              << pct(l14.fe.points[1].displacement, l14.fe.displacement_base)
              << " % (paper, measured: +58.2 %)\n";
    const double stroke_red17 = l17.fe.points[1].displacement - l17.fe.displacement_0V;
    const double stroke_55    = b55.fe.displacement_base - b55.fe.displacement_0V;
    std::cout << "experiment, r_v/a = 1.7, inner 5 kV at wrinkling vs both rings at 5.5 kV: "
                 "model stroke "
              << std::setprecision(4) << stroke_red17 * 1e3 << " mm vs " << stroke_55 * 1e3
              << " mm: +" << std::setprecision(2) << pct(stroke_red17, stroke_55)
              << " %, displacement +"
              << pct(l17.fe.points[1].displacement, b55.fe.displacement_base)
              << " % (paper, measured: +19.4 %)\n";
    std::cout << "experiment, r_v/a = 1.7, inner 5 kV: wrinkles seen at outer 6.3 kV (paper "
                 "figure 5); model red line at outer "
              << std::setprecision(4) << l17.fe.points[1].Vo * 1e-3 << " kV\n";
  }

  // Where this model reproduces the paper's computed increases: the outer
  // voltage at which the stroke increase equals the paper's value, and s2/mu
  // at both inner edges there.
  std::cout << "outer voltage at which the model's stroke increase equals the paper's value "
               "(FE):\n";
  for (const auto &[Vi, r_v, paper] : std::vector<std::tuple<double, double, double>>{
         {5000., 1.7, 32.9}, {5000., 1.8, 40.5}, {5500., 2.0, 20.3}, {5000., 1.4, 58.2}})
    {
      const double target = paper;
      const Target g      = [target](const StepSummary &s, const Lines &l) {
        return pct(s.displacement - l.displacement_0V, l.displacement_base - l.displacement_0V) -
               target;
      };
      const Scene   scene = paper_scene({1., r_v, 3.}, {{Vi * 1e-3, Vi * 1e-3}});
      MembraneModel fe(scene, fe_disc(4, 16), NewtonSettings());
      const Lines   l = locate_lines(fe, r_v, Vi, 9000., {g, red_line});
      std::cout << std::setprecision(2) << "  inner " << Vi * 1e-3 << " kV, r_v/a = " << r_v
                << ": +" << paper
                << " % at outer " << std::setprecision(4) << l.points[0].Vo * 1e-3
                << " kV, s2/mu there " << l.points[0].s2[0] / mu << " (disk edge), "
                << l.points[0].s2[1] / mu << " (outer ring's inner edge); red line at "
                << l.points[1].Vo * 1e-3 << " kV" << std::setprecision(2) << "\n";
    }
  std::cout << std::defaultfloat << std::setprecision(7);
  std::cout << "\nwrote the CSV files into " << dir.string() << "\n";
  return 0;
}
