// The limit of partitioning (doc/optimization.md), on the paper's actuator:
//
//  1. N = 1 .. N_MAX rings, every edge and voltage free (edges in [1, 3],
//     rings at least 1.4 mm wide, voltages in [0, 8] kV, s2 >= 0), without a
//     field limit and with E <= FIELD everywhere: the best of STARTS starts.
//  2. The graded limit directly: M rings of equal width (fixed edges), each
//     ring's voltage such that its most binding constraint (s2 >= 0, E <=
//     E_max) holds with equality, or at the voltage bound: Newton on the
//     voltages with the exact Jacobian, for each M of GRADED, extrapolated to
//     M -> infinity. For the smallest M also the optimizer on the same rings.
//  3. The paper's case (two rings, inner ring 5 kV, edge and outer voltage
//     free) against the red line of `cdea sweep` rows on r_v/a = 1.59, 1.592,
//     ..., 1.65 (prm/sweep-refined-inner5.prm), in percentage points.
//  4. The field question: for r_v/a on a grid and the inner ring at 5 and
//     5.5 kV, the outer voltage where s2 = 0 (red line) and where E = FIELD
//     at the outer ring's inner edge, and the stroke increase there; the
//     field of the states with the paper's 40.5 % (1.8, 5 kV) and 20.3 %
//     (2.0, 5.5 kV).
//
// Checked (exit code 1 otherwise): every stroke of parts 1 and 2 below the
// straight cone (shooting/straight_cone.h), the limit of any partitioning;
// the graded strokes growing with M, their Newton residuals below 1e-10, their
// extrapolation within 2 % of the straight cone, and the optimizer on the
// smallest M's rings at the graded stroke to 1e-6; part 3's optimizer on the
// red line to 0.01 percentage points; part 4's states at the paper's
// increases found, with the fields of doc/optimization.md (59.19 and
// 58.75 MV/m) to 0.01 MV/m.
//
//   build/benchmarks/bench_partitioning [--max-rings N] [--starts S] [--field MV/m]
//        [--graded M,M,...] [--rv-step D] [--out DIR]   (defaults 8 4 59 16,32,64,128 0.05)
//
// Tables on stdout; CSV files in DIR (default results/optimization) for
// postprocess/plot_optimization.py.

#include <cdea/base/mpi_session.h>
#include <cdea/design/optimize.h>
#include <cdea/design/sweep.h>
#include <cdea/numerics/bracketed_root.h>
#include <cdea/shooting/straight_cone.h>

#include "bench_common.h"

#include <Eigen/LU>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace cdea;
using cdea_bench::require;

namespace
{
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  const Scene      base; // the paper's actuator

  double seconds_since(const std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  struct RingsResult
  {
    StartResult  best;
    unsigned int converged = 0, evaluations = 0, solves = 0;
    double       seconds = 0.;
  };

  /// Part 1: the best of the starts for N rings, all free.
  RingsResult optimize_rings(const unsigned int N, const double field, const unsigned int starts)
  {
    OptimizationSettings s;
    s.n_rings  = N;
    s.voltages.assign(N, s.free);
    s.edges.assign(N + 1, s.free);
    s.edges.front() = 1.;
    s.edges.back()  = 3.;
    s.edge_lower    = 1.;
    s.edge_upper    = 3.;
    s.max_field     = field;
    s.starts        = starts;
    LayoutEvaluator evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
    const auto      t = std::chrono::steady_clock::now();
    std::vector<StartResult> results;
    for (const Layout &start : starting_layouts(s))
      results.push_back(optimize_from(base, s, evaluator, unsigned(results.size()), start));
    RingsResult r;
    r.best    = results[best_start(results)];
    r.seconds = seconds_since(t);
    for (const auto &x : results)
      {
        r.converged += x.converged;
        r.evaluations += x.evaluations;
        r.solves += x.solves;
      }
    return r;
  }

  struct Graded
  {
    unsigned int        M = 0, iterations = 0, at_bound = 0;
    double              stroke = none, residual = none;
    std::vector<double> voltages;
  };

  /// Part 2: M equal rings, each ring's most binding constraint zero (or its
  /// voltage at the upper bound), by Newton on the voltages from @p guess(r/a).
  Graded graded(const unsigned int M, const double field,
                const std::function<double(double)> &guess)
  {
    OptimizationSettings s;
    s.n_rings = M;
    s.voltages.assign(M, s.free);
    s.max_field = field;
    Layout layout;
    for (unsigned int k = 0; k <= M; ++k)
      layout.edges.push_back(1. + 2. * k / M);
    s.edges = layout.edges;
    for (unsigned int k = 0; k < M; ++k)
      layout.voltages.push_back(guess(0.5 * (layout.edges[k] + layout.edges[k + 1])));
    LayoutEvaluator evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
    Graded          g;
    g.M                       = M;
    LayoutEvaluation e        = evaluator.ramp(layout);
    Layout           previous = layout;
    for (; g.iterations < 60; ++g.iterations)
      {
        if (!e.ok)
          {
            // Beyond a fold: half way back.
            for (unsigned int k = 0; k < M; ++k)
              layout.voltages[k] = 0.5 * (layout.voltages[k] + previous.voltages[k]);
            e = evaluator.evaluate(layout);
            continue;
          }
        Eigen::VectorXd c;
        Eigen::MatrixXd dc;
        constraints(s, base, layout, e, c, dc);
        // Per ring the most binding of its points' constraints.
        Eigen::VectorXd F = Eigen::VectorXd::Constant(M, -1e300);
        Eigen::MatrixXd G(M, M);
        const unsigned int points = e.points.s2.size();
        for (int i = 0; i < c.size(); ++i)
          {
            const unsigned int ring = e.points.ring[i % points];
            if (c[i] > F[ring])
              {
                F[ring]    = c[i];
                G.row(ring) = dc.row(i);
              }
          }
        // Rings at the upper bound with a slack constraint stay there.
        g.at_bound = 0;
        for (unsigned int k = 0; k < M; ++k)
          if (layout.voltages[k] >= s.voltage_upper - 1e-9 && F[k] < 0.)
            {
              G.row(k)    = Eigen::VectorXd::Unit(M, k).transpose();
              F[k]        = 0.;
              ++g.at_bound;
            }
        g.residual = F.lpNorm<Eigen::Infinity>();
        g.stroke   = e.stroke;
        if (g.residual < 1e-10)
          break;
        const Eigen::VectorXd step = G.partialPivLu().solve(-F);
        previous                   = layout;
        for (unsigned int k = 0; k < M; ++k)
          layout.voltages[k] = std::min(layout.voltages[k] + step[k], s.voltage_upper);
        e = evaluator.evaluate(layout);
      }
    g.voltages = layout.voltages;
    return g;
  }

  /// Part 4: the outer voltage where f(evaluation) changes sign, marching
  /// up from the inner voltage in 50 V steps (NaN if a fold comes first).
  std::pair<double, LayoutEvaluation> line(const double rv, const double inner,
                                           const std::function<double(const LayoutEvaluation &)> &f)
  {
    OptimizationSettings s;
    s.voltages = {inner, s.free};
    s.edges    = {1., rv, 3.};
    LayoutEvaluator evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
    Layout          layout{{1., rv, 3.}, {inner, inner}};
    LayoutEvaluation e  = evaluator.ramp(layout);
    double           v0 = inner, f0 = f(e);
    for (double v = inner + 50.; e.ok && v < 9e3; v += 50.)
      {
        layout.voltages[1]     = v;
        LayoutEvaluation next  = evaluator.evaluate(layout);
        if (!next.ok)
          break;
        const double f1 = f(next);
        if ((f0 >= 0.) != (f1 >= 0.))
          {
            LayoutEvaluation at_root;
            const auto       g = [&](const double x) {
              layout.voltages[1] = x;
              at_root            = evaluator.evaluate(layout);
              return at_root.ok ? f(at_root) : none;
            };
            BracketedRootSettings settings;
            settings.x_tolerance = 1e-4;
            settings.f_tolerance = 1e-12;
            const BracketedRoot root = find_bracketed_root(g, v0, f0, v, f1, settings);
            g(root.x);
            return {root.x, at_root};
          }
        v0 = v;
        f0 = f1;
        e  = next;
      }
    return {none, LayoutEvaluation()};
  }

  double stroke_both_at(const double inner)
  {
    OptimizationSettings s;
    s.n_rings  = 1;
    s.voltages = {s.free};
    s.edges    = {1., 3.};
    LayoutEvaluator evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
    return evaluator.ramp({{1., 3.}, {inner}}).stroke;
  }

  std::string join(const std::vector<double> &v, const double factor, const int digits)
  {
    std::ostringstream o;
    o << std::fixed << std::setprecision(digits);
    for (std::size_t i = 0; i < v.size(); ++i)
      o << (i ? " " : "") << v[i] * factor;
    return o.str();
  }
} // namespace

int run(int argc, char **argv)
{
  const MpiSession         mpi(argc, argv);
  unsigned int             max_rings = 8, starts = 4;
  double                   field_MV = 59., rv_step = 0.05;
  std::vector<unsigned int> graded_M{16, 32, 64, 128};
  std::string              out_dir = "results/optimization";
  for (int k = 1; k + 1 < argc; k += 2)
    {
      const std::string key = argv[k], value = argv[k + 1];
      if (key == "--max-rings")
        max_rings = std::stoi(value);
      else if (key == "--starts")
        starts = std::stoi(value);
      else if (key == "--field")
        field_MV = std::stod(value);
      else if (key == "--rv-step")
        rv_step = std::stod(value);
      else if (key == "--out")
        out_dir = value;
      else if (key == "--graded")
        {
          graded_M.clear();
          std::stringstream items(value);
          for (std::string item; std::getline(items, item, ',');)
            graded_M.push_back(std::stoi(item));
        }
      else
        {
          std::cerr << "bench_partitioning: unknown option " << key << '\n';
          return 1;
        }
    }
  std::filesystem::create_directories(out_dir);
  const double field = field_MV * 1e6;
  std::cout << std::setprecision(7);

  // The continuous graded limit first: part 1 measures the distance to it.
  const shooting::StraightCone cone = shooting::straight_cone(base);
  require(cone.ok, "the straight cone: no tension C found");
  const double    zero_disp = zero_voltage_displacement(base, FeDiscretization(),
                                                     NewtonSettings(), SteppingSettings());
  const double    cone_stroke = (cone.displacement - zero_disp) * 1e3;

  // 1. The N-curve.
  std::cout << "1. N rings, all edges and voltages free (" << starts << " starts); 'below':\n"
               "   the straight-cone limit of part 2 minus the stroke\n";
  std::ofstream rings_csv(out_dir + "/rings.csv");
  rings_csv << "field_limit_MV_per_m,N,stroke_mm,gain_percent,converged_starts,evaluations,"
               "solves,seconds,edges_over_a,voltages_kV\n";
  std::vector<double> best_voltages, best_edges;
  double              one_ring[2] = {none, none}; // N = 1 without and with the field limit
  for (const double limit : {std::numeric_limits<double>::infinity(), field})
    {
      double one = none;
      std::cout << (std::isinf(limit) ? "  no field limit\n" :
                                        "  E <= " + std::to_string(int(field_MV)) + " MV/m\n")
                << "   N  stroke (mm)  gain (%)  below (mm)  conv  evals  solves  time (s)  edges | kV\n";
      for (unsigned int N = 1; N <= max_rings; ++N)
        {
          const RingsResult r = optimize_rings(N, limit, N == 1 ? 1 : starts);
          const double      stroke = r.best.at_best.stroke * 1e3;
          require(stroke < cone_stroke, std::to_string(N) + " rings: stroke " +
                                          std::to_string(stroke) + " mm above the straight cone");
          if (N == 1)
            one = one_ring[std::isinf(limit) ? 0 : 1] = stroke;
          if (std::isinf(limit))
            {
              best_edges    = r.best.best.edges;
              best_voltages = r.best.best.voltages;
            }
          std::cout << std::setw(4) << N << std::setw(13) << stroke << std::setw(10)
                    << std::setprecision(4) << 100. * (stroke / one - 1.) << std::setw(12)
                    << (std::isinf(limit) ? cone_stroke - stroke : none) << std::setw(6)
                    << r.converged << std::setw(7) << r.evaluations << std::setw(8) << r.solves
                    << std::setw(10) << std::setprecision(3) << r.seconds << "  "
                    << join(r.best.best.edges, 1., 4) << " | "
                    << join(r.best.best.voltages, 1e-3, 4) << std::setprecision(7) << '\n';
          rings_csv << (std::isinf(limit) ? 0. : field_MV) << ',' << N << ',' << stroke << ','
                    << 100. * (stroke / one - 1.) << ',' << r.converged << ',' << r.evaluations
                    << ',' << r.solves << ',' << r.seconds << ','
                    << join(r.best.best.edges, 1., 6) << ',' << join(r.best.best.voltages, 1e-3, 6)
                    << '\n';
        }
    }

  // 2. The graded limit.
  std::cout << "\n2. The graded limit: M equal rings, every ring's binding constraint active\n";
  std::ofstream graded_csv(out_dir + "/graded.csv");
  graded_csv << "field_limit_MV_per_m,M,stroke_mm,newton_iterations,rings_at_bound,r_over_a,"
                "voltage_kV\n";
  const auto from_best = [&](const double r) {
    for (std::size_t k = 0; k + 1 < best_edges.size(); ++k)
      if (r <= best_edges[k + 1])
        return best_voltages[k];
    return best_voltages.empty() ? 5e3 : best_voltages.back();
  };
  double graded_front_stroke = none; // the smallest M without the field limit (m)
  for (const double limit : {std::numeric_limits<double>::infinity(), field})
    {
      std::vector<double> strokes;
      for (const unsigned int M : graded_M)
        {
          const auto   t = std::chrono::steady_clock::now();
          const Graded g = graded(M, limit, from_best);
          if (M == graded_M.front() && std::isinf(limit))
            graded_front_stroke = g.stroke;
          require(g.residual < 1e-10 && g.stroke * 1e3 < cone_stroke &&
                    (strokes.empty() || g.stroke * 1e3 > strokes.back()),
                  "graded limit, M = " + std::to_string(M) + ": residual " +
                    std::to_string(g.residual) + ", stroke " + std::to_string(g.stroke * 1e3) +
                    " mm not between the smaller M's and the straight cone");
          strokes.push_back(g.stroke * 1e3);
          std::cout << "  " << (std::isinf(limit) ? "s2 >= 0      " : "s2, E <= lim ") << "M = "
                    << std::setw(3) << M << ": stroke " << g.stroke * 1e3 << " mm, "
                    << g.iterations << " Newton steps, residual " << g.residual << ", "
                    << g.at_bound << " rings at 8 kV, " << std::setprecision(3)
                    << seconds_since(t) << " s" << std::setprecision(7) << '\n';
          for (unsigned int k = 0; k < M; ++k)
            graded_csv << (std::isinf(limit) ? 0. : field_MV) << ',' << M << ','
                       << g.stroke * 1e3 << ',' << g.iterations << ',' << g.at_bound << ','
                       << 1. + 2. * (k + 0.5) / M << ',' << g.voltages[k] * 1e-3 << '\n';
        }
      if (strokes.size() >= 3)
        {
          const std::size_t n = strokes.size();
          const double      a = strokes[n - 3], b = strokes[n - 2], c = strokes[n - 1];
          const double      p = std::log2((b - a) / (c - b));
          const double extrapolated = c + (c - b) / (std::pow(2., p) - 1.);
          std::cout << "  extrapolated (observed order " << p << "): " << extrapolated
                    << " mm, gain over one ring "
                    << 100. * (extrapolated / one_ring[std::isinf(limit) ? 0 : 1] - 1.) << " %\n";
          require(!std::isinf(limit) || std::abs(extrapolated / cone_stroke - 1.) < 0.02,
                  "graded limit: extrapolated " + std::to_string(extrapolated) +
                    " mm, not within 2 % of the straight cone");
        }
      if (std::isinf(limit))
        {
          std::cout << "  continuous profile (straight cone, s2 = 0 everywhere): stroke "
                    << cone_stroke << " mm, cone angle "
                    << cone.theta * 180. / M_PI << " deg, gain over one ring "
                    << 100. * (cone_stroke / one_ring[0] - 1.) << " %, largest voltage needed "
                    << cone.max_voltage * 1e-3 << " kV" << (cone.ok ? "" : " (FAILED)") << '\n';
          graded_csv << "0,inf," << cone_stroke << ",0,0,nan,"
                     << cone.max_voltage * 1e-3 << '\n';
        }
      if (!graded_M.empty() && std::isinf(limit))
        {
          // The optimizer on the same M equal rings, voltages free.
          const unsigned int   M = graded_M.front();
          OptimizationSettings s;
          s.n_rings = M;
          s.voltages.assign(M, s.free);
          Layout start;
          for (unsigned int k = 0; k <= M; ++k)
            start.edges.push_back(1. + 2. * k / M);
          s.edges = start.edges;
          for (unsigned int k = 0; k < M; ++k)
            start.voltages.push_back(from_best(0.5 * (start.edges[k] + start.edges[k + 1])) * 0.95);
          LayoutEvaluator   evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
          const auto        t = std::chrono::steady_clock::now();
          const StartResult r = optimize_from(base, s, evaluator, 0, start);
          require(std::abs(r.at_best.stroke / graded_front_stroke - 1.) < 1e-6,
                  "the optimizer on the " + std::to_string(M) + " equal rings: stroke " +
                    std::to_string(r.at_best.stroke * 1e3) + " mm, graded " +
                    std::to_string(graded_front_stroke * 1e3));
          std::cout << "  optimizer on the " << M << " equal rings: stroke "
                    << r.at_best.stroke * 1e3 << " mm (" << r.status << "), " << r.evaluations
                    << " evaluations, " << std::setprecision(3) << seconds_since(t) << " s"
                    << std::setprecision(7) << '\n';
        }
    }

  // 3. The paper's case against the refined red line.
  std::cout << "\n3. Two rings, inner ring 5 kV: optimizer and the red line of cdea sweep\n";
  {
    OptimizationSettings s;
    s.voltages = {5e3, s.free};
    s.edges    = {1., s.free, 3.};
    LayoutEvaluator   evaluator(base, s, FeDiscretization(), NewtonSettings(), SteppingSettings());
    const StartResult r = optimize_from(base, s, evaluator, 0, starting_layouts(s)[0]);
    const double      both     = stroke_both_at(5e3);
    const double      increase = 100. * (r.at_best.stroke / both - 1.);
    std::cout << "  optimizer: r_v/a = " << r.best.edges[1] << ", outer "
              << r.best.voltages[1] * 1e-3 << " kV, stroke " << r.at_best.stroke * 1e3
              << " mm, increase " << std::setprecision(6) << increase << " % (" << r.status
              << ")\n";
    SweepSettings sweep;
    sweep.inner_voltage = 5e3;
    for (double v = 5e3; v <= 8e3 + 1.; v += 50.)
      sweep.outer_voltages.push_back(v);
    const double zero = zero_voltage_displacement(base, FeDiscretization(), NewtonSettings(),
                                                  SteppingSettings());
    double best_increase = -1., best_rv = none;
    for (int k = 0; k <= 30; ++k)
      {
        const double  rv    = 1.59 + 0.002 * k;
        const Scene   scene = sweep_scene(base, rv, 5e3);
        MembraneModel model(scene, FeDiscretization(), NewtonSettings());
        const SweepRow row = compute_sweep_row(model, scene, sweep, SteppingSettings(), zero);
        if (row.red.stroke_increase > best_increase)
          {
            best_increase = row.red.stroke_increase;
            best_rv       = rv;
          }
      }
    std::cout << "  red line of cdea sweep on r_v/a = 1.59, 1.592, ..., 1.65 (0.1 V): largest "
              << best_increase << " % at r_v/a = " << best_rv << "\n  difference "
              << increase - best_increase << " percentage points\n"
              << std::setprecision(7);
    require(std::abs(increase - best_increase) < 0.01,
            "the paper's case: optimizer and red line differ by " +
              std::to_string(increase - best_increase) + " percentage points");
  }

  // 4. The field question.
  std::cout << "\n4. Field limit at the outer ring's inner edge: E = " << field_MV << " MV/m\n";
  std::ofstream field_csv(out_dir + "/field.csv");
  field_csv << "inner_kV,rv_over_a,red_outer_kV,red_increase_percent,field_outer_kV,"
               "field_increase_percent,field_at_red_MV_per_m\n";
  const auto edge = [](const LayoutEvaluation &e) { return e.points.n_quadrature_points + 1; };
  for (const double inner : {5e3, 5.5e3})
    {
      const double both = stroke_both_at(inner);
      double       top_red = -1., top_field = -1., rv_red = none, rv_field = none;
      std::cout << "  inner " << inner * 1e-3 << " kV\n   r_v/a   red: kV   incr. %  E (MV/m)"
                << "   E-limit: kV   incr. %\n";
      for (double rv = 1.2; rv <= 2.6 + 1e-9; rv += rv_step)
        {
          const auto [v_red, e_red] =
            line(rv, inner, [&](const LayoutEvaluation &e) { return e.points.s2[edge(e)]; });
          const auto [v_field, e_field] = line(rv, inner, [&](const LayoutEvaluation &e) {
            return field - e.points.field[edge(e)];
          });
          const double inc_red   = e_red.ok ? 100. * (e_red.stroke / both - 1.) : none;
          const double inc_field = e_field.ok ? 100. * (e_field.stroke / both - 1.) : none;
          // The field limit applies only where it binds before s2 = 0.
          const bool   binds   = e_field.ok && (!e_red.ok || v_field < v_red);
          const double E_red   = e_red.ok ? e_red.points.field[edge(e_red)] * 1e-6 : none;
          std::cout << std::fixed << std::setprecision(3) << std::setw(8) << rv << std::setw(10)
                    << v_red * 1e-3 << std::setw(10) << inc_red << std::setw(10) << E_red
                    << std::setw(14) << (binds ? v_field * 1e-3 : none) << std::setw(10)
                    << (binds ? inc_field : none) << std::defaultfloat << std::setprecision(7)
                    << '\n';
          field_csv << inner * 1e-3 << ',' << rv << ',' << v_red * 1e-3 << ',' << inc_red << ','
                    << (binds ? v_field * 1e-3 : none) << ',' << (binds ? inc_field : none) << ','
                    << E_red << '\n';
          if (inc_red > top_red)
            top_red = inc_red, rv_red = rv;
          const double limited = binds ? inc_field : inc_red;
          if (limited > top_field)
            top_field = limited, rv_field = rv;
        }
      std::cout << "  largest increase: red line " << top_red << " % at r_v/a = " << rv_red
                << "; with E <= " << field_MV << " MV/m at the edge " << top_field
                << " % at r_v/a = " << rv_field << '\n';
    }
  // The fields of doc/optimization.md (section 3, "The field question").
  for (const auto &[rv, inner, target, field_MV_doc] :
       {std::tuple{1.8, 5e3, 40.5, 59.19}, std::tuple{2.0, 5.5e3, 20.3, 58.75}})
    {
      const double both = stroke_both_at(inner);
      const auto [v, e] = line(rv, inner, [&](const LayoutEvaluation &x) {
        return target - 100. * (x.stroke / both - 1.);
      });
      std::cout << "  the paper's " << target << " % at r_v/a = " << rv << " (inner "
                << inner * 1e-3 << " kV): outer " << v * 1e-3 << " kV, E at the outer ring's "
                << "inner edge " << e.points.field[edge(e)] * 1e-6 << " MV/m, s2 there "
                << e.points.s2[edge(e)] * 1e-3 << " kPa\n";
      require(e.ok && std::abs(e.points.field[edge(e)] * 1e-6 - field_MV_doc) < 0.01,
              "the paper's " + std::to_string(target) + " %: no state, or a field other than " +
                std::to_string(field_MV_doc) + " MV/m");
    }
  std::cout << "CSV files in " << out_dir << "\nchecked: the bounds, the graded limit, the red "
               "line and the paper's fields\n";
  return 0;
}

int main(int argc, char **argv)
{
  return cdea_bench::guarded("bench_partitioning", [&] { return run(argc, argv); });
}
