// Where each method fails (doc/validation.md, "Where each method fails"),
// along the full-electrode path (0 to 7 kV) and the r_v/a = 1.7 path (both
// rings to 5 kV, then the outer ring to 7.5 kV and on to 8 kV):
//  - where Newton load stepping of the FE model stops (default, coarse and
//    refined meshes) and where single shooting with continuation stops (the
//    default driver settings), with the reason each one gives;
//  - the whole solution curve: the stable branch by load stepping with the
//    shooting model, then, past the largest shooting angle theta0 of that
//    branch, the equilibrium at each fixed theta0 (shooting::AngleTrace:
//    theta0 parametrizes the curve through the fold), its fold located by
//    AngleTrace::limit_point and the turn back to higher voltages (where the
//    far branch begins) by Brent's minimization (Boost), so that the folds are
//    found exactly;
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
//
// Writes into DIR (default results/validation) failure_steps.csv,
// failure_curve.csv, failure_residual.csv and failure_onset_mesh.csv, which
// postprocess/plot_validation.py plots. With --smoke (ctest, label
// bench-smoke): the full electrode only, the default FE mesh and the default
// shooting tolerance, the fold, two cold starts, one residual scan and the
// onset on the default mesh, CSV into a temporary folder; it fails unless
// both runs stop within 0.1 V of the fold, the cold starts land on the
// continued branch and the onset agrees with the shooting one within 0.01 V.
//
//   build/benchmarks/bench_failure_modes [DIR] [--smoke]

#include <cdea/fe/membrane_model.h>
#include <cdea/numerics/step_control.h>
#include <cdea/shooting/angle_trace.h>
#include <cdea/shooting/meridian.h>
#include <cdea/shooting/shooting_model.h>

#include <boost/math/tools/minima.hpp>

#include "bench_common.h"

#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>

using namespace cdea;
using namespace cdea_bench;

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

  std::string label(const FeDiscretization &d, const std::string &what)
  {
    return "FE p=" + std::to_string(d.degree) + ", " +
           std::to_string(d.elements_per_ring << d.refinements) + "/ring (" + what + ")";
  }

  std::unique_ptr<EquilibriumModel> shooting_model(const Scene &scene, const double tolerance)
  {
    shooting::ShootingOptions o;
    o.tolerance = tolerance;
    return std::make_unique<shooting::ShootingModel>(scene, o);
  }

  /// One path of the study.
  struct PathCase
  {
    std::string         name;
    Scene               scene;      ///< the path to the end of the issue's range
    Scene               extended;   ///< continued to find the fold
    Scene               onset_path; ///< for the mesh study of the onset
    Scene               trace;      ///< the same rings, the varied voltage on to 20 kV
    unsigned int        varying;    ///< the ring whose voltage varies
    double              V_start;    ///< V where the varying ring starts on its last segment
    std::vector<double> cold_voltages, scan_voltages;
    /// The scene of a cold start: the path straight to voltage V of `varying`.
    std::function<Scene(double)> target;
  };

  /// The voltage of the varying ring at path parameter t of the trace scene.
  double voltage_at(const PathCase &pc, const double t)
  {
    return pc.trace.path.voltages(t)[pc.varying];
  }

  // ---------------------------------------------------------------------
  // The solution curve at fixed shooting angles.

  struct CurvePoint
  {
    double theta0, V, displacement, s2_min;
    int    branch; ///< 0 before the fold, 1 behind it, 2 past the turn back
  };

  struct Fold
  {
    double theta0, V, displacement;
    bool   maximum;
  };

  /// s2_min of the equilibrium @p a (one more integration with its start values).
  double s2_min_of(const shooting::MeridianIntegrator &integrator, const PathCase &pc,
                   const shooting::AnglePoint &a)
  {
    const shooting::MeridianLoad load{pc.trace.prestretch, pc.trace.dead_load(),
                                      pc.trace.path.voltages(a.t)};
    return integrator.integrate(load, a.theta0, a.lambda1_start, false).s2_min;
  }

  /// The extremum of t(theta0) between the curve points @p a and @p c (the
  /// point between them is higher, for a maximum, or lower): a fold by
  /// AngleTrace::limit_point, a turn back to higher voltages by Brent's
  /// minimization of t(theta0).
  shooting::AnglePoint locate_turn(const shooting::AngleTrace &trace, const shooting::AnglePoint &a,
                                   const shooting::AnglePoint &c, const bool maximum)
  {
    if (maximum)
      {
        std::string why;
        const auto  fold = trace.limit_point(a, 0.1 * std::abs(c.theta0 - a.theta0), 1e-10, &why);
        shooting::AnglePoint failed;
        failed.message = why;
        return fold ? *fold : failed;
      }
    shooting::AnglePoint best = a;
    const auto           t    = [&](const double th) {
      const shooting::AnglePoint p = trace.solve(th, best.t, best.lambda1_start);
      if (!p.ok)
        return std::numeric_limits<double>::infinity();
      if (p.t < best.t)
        best = p;
      return p.t;
    };
    boost::math::tools::brent_find_minima(t, std::min(a.theta0, c.theta0),
                                          std::max(a.theta0, c.theta0), 40);
    return trace.solve(best.theta0, best.t, best.lambda1_start);
  }

  /// Walk theta0 down from @p start (past the largest theta0 of the stable
  /// branch, where theta0 parametrizes the curve) to @p theta_stop; every
  /// sign change of dV/dtheta0 is a fold, located exactly.
  std::vector<CurvePoint> walk(const PathCase &pc, const shooting::AngleTrace &trace,
                               const shooting::MeridianIntegrator &integrator,
                               shooting::AnglePoint start, const double theta_stop,
                               std::vector<Fold> &folds)
  {
    std::vector<CurvePoint>           curve;
    std::vector<shooting::AnglePoint> done;
    double th = start.theta0, t_guess = start.t, slope = 0.;
    double l1 = start.lambda1_start;
    // Steps in theta0 of at most 0.004, halved on a failure down to 5e-8,
    // growing by half after every point reached.
    StepControlSettings step_settings;
    step_settings.max_step        = 0.004;
    step_settings.min_step        = 5e-8;
    step_settings.growth          = 1.5;
    step_settings.easy_iterations = StepControlSettings::unlimited;
    StepController control(step_settings, 0.002);
    while (th > theta_stop)
      {
        const shooting::AnglePoint a = trace.solve(th, t_guess, l1);
        if (!a.ok)
          {
            if (done.empty() || !control.reject(control.step()))
              break;
            th      = done.back().theta0 - control.step();
            t_guess = done.back().t + slope * control.step();
            continue;
          }
        if (!done.empty())
          slope = (a.t - done.back().t) / (done.back().theta0 - a.theta0);
        if (done.size() >= 2)
          {
            const double d1 = done[done.size() - 1].t - done[done.size() - 2].t;
            const double d2 = a.t - done.back().t;
            if (d1 * d2 < 0.)
              {
                const shooting::AnglePoint f = locate_turn(trace, done[done.size() - 2], a,
                                                           d1 > 0.);
                require(f.ok, "a fold of the curve was not located: " + f.message);
                folds.push_back({f.theta0, voltage_at(pc, f.t), f.displacement, d1 > 0.});
              }
          }
        curve.push_back({a.theta0, voltage_at(pc, a.t), a.displacement,
                         s2_min_of(integrator, pc, a), int(folds.size())});
        done.push_back(a);
        l1      = a.lambda1_start;
        t_guess = a.t + slope * control.step();
        th -= control.step();
        control.accept(control.step(), 0);
      }
    return curve;
  }

  // ---------------------------------------------------------------------

  /// Load stepping of each method to the end of @p scene's path.
  void load_stepping(const PathCase &pc, const Scene &scene, const bool smoke, const bool record,
                     std::ofstream &steps_csv, double &fe_stop, double &shooting_stop)
  {
    const double mu    = scene.material.shear_modulus;
    const double V_end = scene.path.voltages(scene.path.n_segments()).back();
    std::cout << "-- load stepping to " << V_end * 1e-3 << " kV (default stepping)\n";
    std::vector<std::pair<std::string, std::unique_ptr<EquilibriumModel>>> methods;
    const FeDiscretization defaults;
    methods.emplace_back(label(defaults, "default"),
                         std::make_unique<MembraneModel>(scene, defaults, NewtonSettings()));
    if (!smoke)
      for (const auto &[d, what] : {std::make_pair(fe_disc(2, 2), "coarse"),
                                    std::make_pair(fe_disc(4, 16, 4., 1), "refined")})
        methods.emplace_back(label(d, what),
                             std::make_unique<MembraneModel>(scene, d, NewtonSettings()));
    for (const double tol : smoke ? std::vector<double>{1e-10} : std::vector<double>{1e-10, 1e-12})
      {
        std::ostringstream name;
        name << "shooting tol " << tol << (tol == 1e-10 ? " (default)" : "");
        methods.emplace_back(name.str(), shooting_model(scene, tol));
      }
    for (auto &[name, model] : methods)
      {
        const Run    r    = run_stages(*model, scene, SteppingSettings(), true);
        const double last = r.voltage_steps.empty() ? not_a_number :
                                                      r.voltage_steps.back().voltages.back();
        std::cout << "  " << std::left << std::setw(30) << name << std::right
                  << (r.result.completed ? "completed" : "STOPPED") << " at "
                  << std::setprecision(10) << last << " V, displacement "
                  << (r.voltage_steps.empty() ? not_a_number :
                                                r.voltage_steps.back().displacement * 1e3)
                  << " mm" << std::setprecision(7);
        if (r.result.onset.found)
          std::cout << "; onset " << std::setprecision(10) << r.result.onset.voltages.back()
                    << " V" << std::setprecision(7);
        std::cout << "\n";
        if (!r.result.completed)
          std::cout << "      reason: " << r.result.message << "\n";
        if (name.find("(default)") != std::string::npos)
          (name.rfind("FE", 0) == 0 ? fe_stop : shooting_stop) = last;
        if (record)
          {
            std::string csv_label = name; // no commas inside a CSV field
            std::replace(csv_label.begin(), csv_label.end(), ',', ';');
            for (const StepSummary &s : r.voltage_steps)
              steps_csv << pc.name << ',' << csv_label << ',' << s.voltages.back() * 1e-3 << ','
                        << s.displacement * 1e3 << ',' << s.s2_min / mu << '\n';
          }
      }
  }

  /// The stable branch by load stepping in 20 V steps with the shooting
  /// model, then the curve at fixed angles; returns the fold voltage.
  double solution_curve(const PathCase &pc, const bool smoke, std::ofstream &curve_csv)
  {
    std::cout << "-- solution curve: stable branch by load stepping ("
              << (smoke ? "250" : "20") << " V steps), then the equilibria at fixed shooting "
              << "angles; shooting tolerance 1e-12\n";
    const double              mu = pc.scene.material.shear_modulus;
    shooting::ShootingOptions o;
    o.tolerance = 1e-12;
    shooting::ShootingModel sm(pc.extended, o);
    SteppingSettings        stepping;
    stepping.voltage_increment = smoke ? 250. : 20.;
    std::vector<CurvePoint> stable;
    {
      LoadStepper stepper(pc.extended, sm, stepping);
      stepper.on_step = [&](const StepSummary &s) {
        if (s.stage == Stage::voltage && s.voltages.back() >= pc.V_start)
          stable.push_back({sm.shooting_angle(), s.voltages.back(), s.displacement, s.s2_min, 0});
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
    require(start > 0, "the stable branch has no point past its largest angle");

    const shooting::AngleTrace         trace(pc.trace, o);
    const shooting::MeridianIntegrator integrator(pc.trace, o);
    // The equilibrium at the start angle, near the stable branch's voltage there.
    const double V0 = stable[start].V;
    double       t0 = 0.;
    for (unsigned int k = 0; k < pc.trace.path.n_segments(); ++k)
      {
        const double a = pc.trace.path.voltages(k)[pc.varying];
        const double b = pc.trace.path.voltages(k + 1)[pc.varying];
        if (b > a && V0 >= a && V0 <= b)
          t0 = k + (V0 - a) / (b - a);
      }
    const shooting::AnglePoint first = trace.solve(stable[start].theta0, t0, -1.);
    require(first.ok, "no equilibrium at the start angle: " + first.message);
    std::vector<Fold> folds;
    const auto curve = smoke ? std::vector<CurvePoint>{} : walk(pc, trace, integrator, first, 0.03, folds);
    if (smoke)
      {
        // Only the fold: from the start angle towards higher voltages.
        const auto fold = trace.limit_point(first, 0.002, 1e-10);
        require(fold.has_value(), "the fold was not found");
        folds.push_back({fold->theta0, voltage_at(pc, fold->t), fold->displacement, true});
      }
    for (std::size_t i = 0; i < start; ++i)
      curve_csv << pc.name << ',' << stable[i].theta0 << ',' << stable[i].V * 1e-3 << ','
                << stable[i].displacement * 1e3 << ',' << stable[i].s2_min / mu << ",0\n";
    for (const auto &p : curve)
      curve_csv << pc.name << ',' << p.theta0 << ',' << p.V * 1e-3 << ',' << p.displacement * 1e3
                << ',' << p.s2_min / mu << ',' << p.branch << '\n';
    std::cout << "  stable branch by stepping: " << start << " points to " << stable[start].V
              << " V (largest theta0 " << stable[top].theta0 << " at " << stable[top].V
              << " V)";
    if (!curve.empty())
      std::cout << "; then " << curve.size() << " points at fixed angles down to theta0 = "
                << curve.back().theta0 << " (V = " << curve.back().V << ")";
    std::cout << "\n";
    for (const auto &f : folds)
      std::cout << "  fold (" << (f.maximum ? "largest" : "smallest")
                << " voltage on its branch): V = " << std::setprecision(10) << f.V
                << " V at theta0 = " << f.theta0 << ", displacement " << f.displacement * 1e3
                << " mm" << std::setprecision(7) << "\n";
    require(!folds.empty() && folds.front().maximum, "the curve has no fold");
    return folds.front().V;
  }

  /// One solve straight to each voltage, without continuation in the
  /// voltage, against the continued solution.
  void cold_starts(const PathCase &pc, const std::vector<double> &Vs)
  {
    std::cout << "-- cold starts (one solve from the weightless pre-stretched film for "
                 "shooting, from the weighted 0 V state for FE) against continuation\n";
    for (const bool fe : {false, true})
      {
        unsigned int n_ok  = 0;
        double       worst = 0.;
        std::string  failures;
        for (const double V : Vs)
          {
            const Scene target = pc.target(V);
            const auto  build  = [&] {
              return fe ? std::unique_ptr<EquilibriumModel>(
                            std::make_unique<MembraneModel>(target, FeDiscretization(),
                                                            NewtonSettings())) :
                          shooting_model(target, 1e-10);
            };
            const auto  cont = build(), cold = build();
            const Run   r    = run_stages(*cont, target);
            LoadStepper driver(target, *cold, SteppingSettings());
            cold->set_reference_state();
            bool ok = cold->solve(driver.load(Stage::dead_load, 0.)).converged;
            if (fe)
              ok = ok && cold->solve(driver.load(Stage::dead_load, 1.)).converged;
            ok = ok && cold->solve(driver.load(Stage::voltage, target.path.n_segments())).converged &&
                 r.result.completed;
            if (ok)
              {
                ++n_ok;
                worst = std::max(worst, std::abs(cold->displacement() - r.last.displacement));
              }
            else
              failures += " " + std::to_string(int(V));
          }
        std::cout << "  " << (fe ? label(FeDiscretization(), "default") : "shooting (tolerance 1e-10)")
                  << ": " << n_ok << " of " << Vs.size() << " voltages from " << Vs.front()
                  << " to " << Vs.back() << " V converged, largest |displacement - continued| "
                  << worst * 1e3 << " mm"
                  << (failures.empty() ? "" : "; no convergence at" + failures + " V") << "\n";
        require(n_ok == Vs.size() && worst < 1e-9, "a cold start missed the continued branch");
      }
  }

  /// The single-shooting residual over theta0 in (0, pi) at each voltage.
  void residual_scans(const PathCase &pc, const int n, std::ofstream &residual_csv)
  {
    std::cout << "-- shooting residual r(B)/b - 1 over theta0 in (0, pi), tolerance 1e-10\n";
    shooting::ShootingOptions o;
    o.tolerance = 1e-10;
    const shooting::MeridianIntegrator integrator(pc.scene, o);
    const double mu = pc.scene.material.shear_modulus;
    const double b  = pc.scene.prestretch * pc.scene.outer_reference_radius();
    for (const double V : pc.scan_voltages)
      {
        // The other rings at the voltage the varying one starts from.
        shooting::MeridianLoad load{pc.scene.prestretch, pc.scene.dead_load(),
                                    std::vector<double>(pc.scene.n_rings(), pc.V_start)};
        load.voltages[pc.varying] = V;
        std::ostringstream    roots;
        int                   n_roots = 0;
        std::optional<double> prev;
        double                prev_th = 0., first_fail = not_a_number, l1 = -1.;
        for (int i = 1; i < n; ++i)
          {
            const double            th = M_PI * i / n;
            const shooting::Profile p  = integrator.shoot(load, th, l1, false);
            std::optional<double>   f;
            if (p.ok)
              {
                f  = p.r_end / b - 1.;
                l1 = p.lambda1_start;
              }
            const bool change = f && prev && (*f > 0.) != (*prev > 0.);
            if (i % 4 == 0 || change)
              residual_csv << pc.name << ',' << V * 1e-3 << ',' << th << ','
                           << (f ? *f : not_a_number) << ',' << int(bool(f)) << '\n';
            if (!f && std::isnan(first_fail))
              first_fail = th;
            if (change)
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
        require(n_roots >= 1, "no root of the shooting residual at " + std::to_string(V) + " V");
      }
  }

  /// The onset on FE meshes from coarse to fine against the shooting onset;
  /// returns the latter.
  double onset_against_mesh(const PathCase &pc, const bool smoke, std::ofstream &onset_csv)
  {
    const Scene &path = pc.onset_path;
    std::cout << "-- wrinkling onset (s2 = 0) against the mesh, path to "
              << path.path.voltages(path.path.n_segments()).back() * 1e-3 << " kV\n";
    SteppingSettings fine;
    fine.onset_tolerance = 1e-4;
    const auto sm        = shooting_model(path, 1e-12);
    const Run  ref       = run_stages(*sm, path, fine);
    require(ref.result.onset.found, "the shooting model finds no onset");
    const double V_ref = ref.result.onset.voltages.back();
    std::cout << "  shooting (tol 1e-12): onset at " << std::setprecision(10) << V_ref
              << " V, r/a = " << ref.result.onset.radius / path.disk_radius
              << std::setprecision(7) << "\n"
              << "   p  n/ring  grading  dofs    onset (V)   FE - shooting (V)\n";
    const FeDiscretization defaults;
    for (unsigned p = 1; p <= 4; ++p)
      for (const unsigned n : {1u, 2u, 4u, 8u, 16u})
        for (const double g : {1., 4.})
          {
            const bool is_default =
              p == defaults.degree && n == defaults.elements_per_ring && g == defaults.grading;
            if ((n == 1 && g == 4.) || (smoke && !is_default))
              continue; // one element: no grading
            MembraneModel fe(path, fe_disc(p, n, g), NewtonSettings());
            const Run     r = run_stages(fe, path, fine);
            const double  V = r.result.onset.found ? r.result.onset.voltages.back() : not_a_number;
            onset_csv << pc.name << ',' << p << ',' << n << ',' << g << ',' << fe.n_dofs() << ','
                      << V * 1e-3 << ',' << V_ref * 1e-3 << '\n';
            std::cout << std::setw(4) << p << std::setw(8) << n << std::setw(9) << g << std::setw(6)
                      << fe.n_dofs() << std::setw(13) << std::setprecision(8) << V << std::setw(14)
                      << std::setprecision(3) << V - V_ref
                      << (r.result.completed ? "" : "  (run stopped early)") << std::setprecision(7)
                      << "\n";
            if (is_default)
              require(std::abs(V - V_ref) < 0.01, "the default mesh's onset is off by " +
                                                    std::to_string(V - V_ref) + " V");
          }
    return V_ref;
  }

  std::vector<PathCase> path_cases(const bool smoke)
  {
    std::vector<PathCase> paths;
    PathCase full{"full", paper_scene({1., 3.}, {{7.}}), paper_scene({1., 3.}, {{7.}}),
                  paper_scene({1., 3.}, {{6.6}}), paper_scene({1., 3.}, {{20.}}), 0, 0.,
                  {}, {0., 5000., 5500., 5600., 5700., 6000., 6500., 6630.},
                  [](const double V) { return paper_scene({1., 3.}, {{V * 1e-3}}); }};
    for (double V = 500.; V < 6629.; V += 250.)
      full.cold_voltages.push_back(V);
    full.cold_voltages.push_back(6630.);
    PathCase rv{"rv1.7", paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 7.5}}),
                paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 8.}}),
                paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 7.5}}),
                paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 20.}}), 1, 5000.,
                {}, {5000., 6000., 6500., 7000., 7500., 7560.},
                [](const double V) { return paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., V * 1e-3}}); }};
    for (double V = 5250.; V < 7564.; V += 250.)
      rv.cold_voltages.push_back(V);
    rv.cold_voltages.push_back(7565.);
    if (smoke)
      {
        full.cold_voltages = {5000., 6630.};
        full.scan_voltages = {6000.};
        return {full};
      }
    return {full, rv};
  }

  int benchmark(const OutputFolder &dir, const bool smoke)
  {
    std::cout << std::setprecision(7);
    std::ofstream steps_csv(dir / "failure_steps.csv");
    steps_csv << "case,method,V_kV,displacement_mm,s2_min_over_mu\n" << std::setprecision(10);
    std::ofstream curve_csv(dir / "failure_curve.csv");
    curve_csv << "case,theta0,V_kV,displacement_mm,s2_min_over_mu,branch\n"
              << std::setprecision(10);
    std::ofstream residual_csv(dir / "failure_residual.csv");
    residual_csv << "case,V_kV,theta0,residual,ok\n" << std::setprecision(8);
    std::ofstream onset_csv(dir / "failure_onset_mesh.csv");
    onset_csv << "case,degree,elements_per_ring,grading,dofs,onset_kV,reference_kV\n"
              << std::setprecision(10);

    for (const PathCase &pc : path_cases(smoke))
      {
        std::cout << "\n=============== path '" << pc.name << "' ===============\n";
        double fe_stop = not_a_number, shooting_stop = not_a_number;
        load_stepping(pc, pc.scene, smoke, pc.name == "full", steps_csv, fe_stop, shooting_stop);
        if (pc.name != "full")
          load_stepping(pc, pc.extended, smoke, true, steps_csv, fe_stop, shooting_stop);
        const double fold = solution_curve(pc, smoke, curve_csv);
        for (const double stop : {fe_stop, shooting_stop})
          require(std::abs(stop - fold) < 0.1, "load stepping stopped at " + std::to_string(stop) +
                                                 " V, not within 0.1 V of the fold at " +
                                                 std::to_string(fold) + " V");
        cold_starts(pc, pc.cold_voltages);
        residual_scans(pc, smoke ? 400 : 4000, residual_csv);
        onset_against_mesh(pc, smoke, onset_csv);
      }
    for (const auto *csv : {&steps_csv, &curve_csv, &residual_csv, &onset_csv})
      require(bool(*csv), "could not write the CSV files into " + dir.path().string());
    std::cout << "\nwrote the CSV files into " << dir.path().string() << "\n";
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  return study_main(argc, argv, "bench_failure_modes", benchmark);
}
