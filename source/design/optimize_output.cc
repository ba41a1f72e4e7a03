// What `cdea optimize` writes: <Base name>_optimum.h5 and the parameter file
// <Base name>_optimum.prm that `cdea run` replays.

#include <cdea/base/format.h>
#include <cdea/design/optimize.h>
#include <cdea/output/hdf5_writer.h>
#include <cdea/model/output_fields.h>

#include <algorithm>
#include <cmath>
#include <limits>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  namespace
  {
    std::string joined(const std::vector<double> &values, const double factor)
    {
      std::string s;
      for (std::size_t i = 0; i < values.size(); ++i)
        s += (i ? ", " : "") + exact_number(values[i] * factor);
      return s;
    }

  } // namespace

  unsigned int best_start(const std::vector<StartResult> &starts)
  {
    // Converged before feasible before the rest.
    const auto rank = [](const StartResult &r) {
      const bool feasible = r.at_best.ok && r.worst_constraint <= 1e-6;
      return r.converged ? 2 : feasible ? 1 : 0;
    };
    int top = 0;
    for (const auto &r : starts)
      top = std::max(top, rank(r));
    if (top == 0)
      {
        // None feasible: the least infeasible of those that could be ramped.
        unsigned int best = 0;
        for (unsigned int k = 1; k < starts.size(); ++k)
          {
            const StartResult &a = starts[k], &b = starts[best];
            if (a.at_best.ok != b.at_best.ok ? a.at_best.ok :
                                               a.worst_constraint < b.worst_constraint)
              best = k;
          }
        return best;
      }
    // Starts that reach the same optimum differ in the last digits of the
    // objective, and the larger one is usually the one a little outside the
    // feasible set (within the feasibility tolerance, 1e-6 mu in s2, worth
    // about 2e-7 of the stroke in the paper's case): objectives within this
    // relative tolerance count as equal, and the smaller constraint
    // violation (max(c, 0)), then the smaller first-order residual, decides.
    constexpr double same_objective = 1e-7;
    double           largest        = -std::numeric_limits<double>::infinity();
    for (const auto &r : starts)
      if (rank(r) == top)
        largest = std::max(largest, r.objective);
    const double tie = same_objective * std::max(std::abs(largest), 1e-300);
    unsigned int best = starts.size();
    for (unsigned int k = 0; k < starts.size(); ++k)
      {
        const StartResult &a = starts[k];
        if (rank(a) != top || a.objective < largest - tie)
          continue;
        if (best == starts.size())
          {
            best = k;
            continue;
          }
        const StartResult &b = starts[best];
        const double violation_a = std::max(a.worst_constraint, 0.),
                     violation_b = std::max(b.worst_constraint, 0.);
        if (violation_a != violation_b ? violation_a < violation_b : a.optimality < b.optimality)
          best = k;
      }
    return best;
  }

  namespace
  {
    /// The root attributes: the best layout, its state and how the run went.
    void write_optimum_attributes(Hdf5Writer &w, const OptimizationRun &run,
                                  const OptimizationSettings &s,
                                  const std::string          &parameter_text)
    {
      const StartResult      &best = run.starts.at(run.best);
      const LayoutEvaluation &e    = best.at_best;
      w.attribute("/", "parameters", parameter_text);
      w.attribute("/", "code_version", std::string(CDEA_VERSION));
      w.attribute("/", "objective", to_string(s.objective));
      w.attribute("/", "algorithm", to_string(s.algorithm));
      w.attribute("/", "ring_edges_over_a", best.best.edges);
      w.attribute("/", "voltages_kV", scaled(best.best.voltages, 1e-3));
      w.attribute("/", "displacement_mm", e.displacement * 1e3);
      w.attribute("/", "stroke_mm", e.stroke * 1e3);
      w.attribute("/", "volume_change_mm3", e.volume_change * 1e9);
      const bool has_points = e.ok && e.points.s2.size() > 0;
      w.attribute("/", "min_s2_kPa", has_points ? e.points.s2.minCoeff() * 1e-3 : NAN);
      w.attribute("/", "max_field_MV_per_m", has_points ? e.points.field.maxCoeff() * 1e-6 : NAN);
      std::string active;
      for (const auto &a : best.active)
        active += (active.empty() ? "" : "; ") + a;
      w.attribute("/", "active_constraints", active);
      unsigned int evaluations = 0, solves = 0;
      for (const auto &r : run.starts)
        {
          evaluations += r.evaluations;
          solves += r.solves;
        }
      w.attribute("/", "iterations", int(evaluations));
      w.attribute("/", "solves", int(solves));
      w.attribute("/", "converged", int(best.converged));
      w.attribute("/", "status", best.status);
      w.attribute("/", "first_order_residual", best.optimality);
      w.attribute("/", "best_start", int(best.start));
      w.attribute("/", "starts", int(run.starts.size()));
      w.attribute("/", "min_tangent_eigenvalue_N_per_m", e.min_eigenvalue);
    }

    /// "stroke (mm)" or "enclosed volume change (1000 mm^3)".
    std::string objective_name(const OptimizationSettings &s)
    {
      return s.objective == DesignObjective::stroke ? "stroke (mm)" :
                                                      "enclosed volume change (1000 mm^3)";
    }

    std::string objective_unit(const OptimizationSettings &s)
    {
      return s.objective == DesignObjective::stroke ? "mm" : "1000 mm^3";
    }

    /// /history: every evaluation of every start.
    void write_history(Hdf5Writer &w, const OptimizationRun &run, const OptimizationSettings &s)
    {
      const auto  free = s.free_parameters();
      std::string names;
      for (const auto &p : free)
        names += (names.empty() ? "" : "; ") +
                 (p.kind == ParameterKind::voltage ?
                    "voltage of ring " + std::to_string(p.index + 1) + " (kV)" :
                    p.name());
      w.group("/history");
      std::vector<int>    start, evaluation;
      std::vector<double> objective, worst, values;
      for (const auto &r : run.starts)
        for (const auto &h : r.history)
          {
            start.push_back(int(h.start));
            evaluation.push_back(int(h.evaluation));
            objective.push_back(h.objective);
            worst.push_back(h.worst_constraint);
            values.insert(values.end(), h.free_values.begin(), h.free_values.end());
          }
      w.dataset("/history/start", start, "start of the multistart (from 0)");
      w.dataset("/history/evaluation", evaluation, "evaluation within the start (from 1)");
      w.dataset("/history/objective", {objective.size()}, objective, objective_unit(s),
                objective_name(s) + " of the layout evaluated; NaN where it could not be reached");
      w.dataset("/history/worst_constraint", {worst.size()}, worst, "1",
                "largest scaled constraint value (s2: (limit - s2)/mu, E: E/E_max - 1, width: "
                "(w_min - width)/(b/a - 1)); <= 0 is feasible");
      w.dataset("/history/free_values", {objective.size(), free.size()}, values, "kV, r/a",
                "the free variables of each evaluation: " + names);
      w.attribute("/history", "free_variables", names);
    }

    /// /starts: every start's outcome.
    void write_starts(Hdf5Writer &w, const OptimizationRun &run, const OptimizationSettings &s)
    {
      w.group("/starts");
      std::vector<double> initial_edges, initial_volts, best_edges, best_volts, objectives,
        worsts, optimality;
      std::vector<int>         converged, counts, solve_counts;
      std::vector<std::string> status;
      for (const auto &r : run.starts)
        {
          initial_edges.insert(initial_edges.end(), r.initial.edges.begin(), r.initial.edges.end());
          best_edges.insert(best_edges.end(), r.best.edges.begin(), r.best.edges.end());
          for (const double v : r.initial.voltages)
            initial_volts.push_back(v * 1e-3);
          for (const double v : r.best.voltages)
            best_volts.push_back(v * 1e-3);
          objectives.push_back(r.objective);
          worsts.push_back(r.worst_constraint);
          optimality.push_back(r.optimality);
          converged.push_back(int(r.converged));
          counts.push_back(int(r.evaluations));
          solve_counts.push_back(int(r.solves));
          status.push_back(r.status);
        }
      const std::size_t S = run.starts.size(), N = s.n_rings;
      w.dataset("/starts/initial_ring_edges_over_a", {S, N + 1}, initial_edges, "1",
                "ring edges of each starting layout");
      w.dataset("/starts/initial_voltages_kV", {S, N}, initial_volts, "kV",
                "ring voltages of each starting layout (lowered until a ramp reaches them)");
      w.dataset("/starts/ring_edges_over_a", {S, N + 1}, best_edges, "1",
                "ring edges of the best layout of each start");
      w.dataset("/starts/voltages_kV", {S, N}, best_volts, "kV",
                "ring voltages of the best layout of each start");
      w.dataset("/starts/objective", {S}, objectives, objective_unit(s),
                objective_name(s) + " of the best layout of each start, confirmed by a ramp "
                                    "from zero");
      w.dataset("/starts/worst_constraint", {S}, worsts, "1",
                "largest scaled constraint value there (<= 1e-6: feasible)");
      w.dataset("/starts/first_order_residual", {S}, optimality, "1",
                "|grad f + A lambda| / |grad f| over the active constraints and bounds (KKT)");
      w.dataset("/starts/converged", converged, "1 if the optimizer converged to a feasible layout");
      w.dataset("/starts/evaluations", counts, "evaluations of the start");
      w.dataset("/starts/solves", solve_counts, "equilibrium solves of the start");
      w.dataset("/starts/status", status, "how the optimizer ended");
    }

    /// /optimum: the optimum's hoop stress and field at every point.
    void write_optimum_points(Hdf5Writer &w, const LayoutEvaluation &e, const Scene &base)
    {
      w.group("/optimum");
      std::vector<double> r_over_a, ring;
      for (std::size_t k = 0; k < e.points.R.size(); ++k)
        {
          r_over_a.push_back(base.prestretch * e.points.R[k] / base.disk_radius);
          ring.push_back(e.points.ring[k] + 1.);
        }
      const std::size_t P = r_over_a.size();
      w.dataset("/optimum/r_over_a", {P}, r_over_a, "1",
                "pre-stretched flat radius of each point: the quadrature points cell by "
                "cell, then the inner edge of each ring");
      w.dataset("/optimum/ring", {P}, ring, "1", "ring of each point (from 1)");
      w.dataset("/optimum/s2_kPa", {P},
                scaled({e.points.s2.data(), e.points.s2.data() + P}, 1e-3), "kPa",
                "nominal hoop stress at each point");
      w.dataset("/optimum/field_MV_per_m", {P},
                scaled({e.points.field.data(), e.points.field.data() + P}, 1e-6), "MV/m",
                "true electric field at each point");
      w.attribute("/optimum", "n_quadrature_points", int(e.points.n_quadrature_points));
    }
  } // namespace

  void write_optimum_file(const std::string &path, const OptimizationRun &run,
                          const OptimizationSettings &s, const Scene &base,
                          const std::string &parameter_text)
  {
    const LayoutEvaluation &e = run.starts.at(run.best).at_best;
    Hdf5Writer              w(path);
    write_optimum_attributes(w, run, s, parameter_text);
    write_history(w, run, s);
    write_starts(w, run, s);
    if (e.ok && e.points.s2.size() > 0)
      write_optimum_points(w, e, base);
    w.commit();
  }

  void write_replay_parameters(const ParameterInput &input, const std::string &path,
                               const Layout &layout, const std::string &base_name,
                               const double max_field)
  {
    std::vector<ParameterChange> changes = {
      {"Electrodes", "Ring edges (r/a)", joined(layout.edges, 1.)},
      {"Electrodes", "Voltage path (kV)", joined(layout.voltages, 1e-3)},
      {"Solver", "Continuation", "load stepping"},
      {"Output", "Base name", base_name + "_optimum_run"}};
    // The replay then reports the largest field of every step.
    if (std::isfinite(max_field))
      changes.push_back({"Solver", "Breakdown field (MV/m)", exact_number(max_field * 1e-6)});
    write_changed_parameters(
      input, path, changes,
      "# Written by cdea optimize: `cdea run` on this file ramps the voltages of the\n"
      "# optimum layout proportionally from zero and reaches the optimum state.\n");
  }
} // namespace cdea
