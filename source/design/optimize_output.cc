// What `cdea optimize` returns and writes: its product (<Base name>_optimum.h5)
// and the parameter file <Base name>_optimum.prm that `cdea run` replays.

#include <cdea/base/format.h>
#include <cdea/design/optimize.h>
#include <cdea/model/quantities_common.h>
#include <cdea/model/quantities_optimize.h>

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
    /// @p values (SI) in @p unit, exactly, as a prm list.
    std::string joined(const std::vector<double> &values, const Unit &unit)
    {
      std::string s;
      for (std::size_t i = 0; i < values.size(); ++i)
        s += (i ? ", " : "") + exact_number(unit.from_si(values[i]));
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
    using namespace optimize_quantity;

    /// The root attributes: the best layout, its state and how the run went.
    void add_optimum(ProductGroup &root, const OptimizationRun &run, const OptimizationSettings &s,
                     const std::string &parameter_text)
    {
      const StartResult      &best       = run.starts.at(run.best);
      const LayoutEvaluation &e          = best.at_best;
      const bool              has_points = e.ok && e.points.s2.size() > 0;
      std::string             active;
      for (const auto &a : best.active)
        active += (active.empty() ? "" : "; ") + a;
      unsigned int evaluations = 0, solve_count = 0;
      for (const auto &r : run.starts)
        {
          evaluations += r.evaluations;
          solve_count += r.solves;
        }
      root.set(common_quantity::parameters, parameter_text)
        .set(common_quantity::code_version, CDEA_VERSION)
        .set(objective, to_string(s.objective))
        .set(algorithm, to_string(s.algorithm))
        .set(ring_edges, best.best.edges)
        .set(voltages, best.best.voltages)
        .set(displacement, e.displacement)
        .set(stroke, e.stroke)
        .set(volume_change, e.volume_change)
        .set(min_s2, has_points ? e.points.s2.minCoeff() : NAN)
        .set(max_field, has_points ? e.points.field.maxCoeff() : NAN)
        .set(active_constraints, active)
        .set(iterations, evaluations)
        .set(solves, solve_count)
        .set(converged, best.converged)
        .set(status, best.status)
        .set(first_order_residual, best.optimality)
        .set(optimum_start, best.start)
        .set(starts, run.starts.size())
        .set(min_tangent_eigenvalue, e.min_eigenvalue);
    }

    bool stroke_objective(const OptimizationSettings &s)
    {
      return s.objective == DesignObjective::stroke;
    }

    /// /history: every evaluation of every start.
    void add_history(Product &product, const OptimizationRun &run, const OptimizationSettings &s)
    {
      const auto  free = s.free_parameters();
      std::string names;
      for (const auto &p : free)
        names += (names.empty() ? "" : "; ") +
                 (p.kind == ParameterKind::voltage ?
                    "voltage of ring " + std::to_string(p.index + 1) + " (kV)" :
                    p.name());
      std::vector<double> start, evaluation, objective_values, worst, values;
      for (const auto &r : run.starts)
        for (const auto &h : r.history)
          {
            start.push_back(h.start);
            evaluation.push_back(h.evaluation);
            objective_values.push_back(h.objective);
            worst.push_back(h.worst_constraint);
            values.insert(values.end(), h.free_values.begin(), h.free_values.end());
          }
      const std::size_t n = objective_values.size();
      product.group("/history")
        .set(free_variables, names)
        .set(history_start, start)
        .set(history_evaluation, evaluation)
        .set(stroke_objective(s) ? history_stroke : history_volume, objective_values)
        .set(history_worst_constraint, worst)
        .set_detailed(history_free_values, values, {n, free.size()}, names);
    }

    /// /starts: every start's outcome.
    void add_starts(Product &product, const OptimizationRun &run, const OptimizationSettings &s)
    {
      std::vector<double> initial_edges, initial_volts, best_edges, best_volts, objectives,
        worsts, optimality, converged_flags, counts, solve_counts;
      std::vector<std::string> status_texts;
      for (const auto &r : run.starts)
        {
          initial_edges.insert(initial_edges.end(), r.initial.edges.begin(), r.initial.edges.end());
          best_edges.insert(best_edges.end(), r.best.edges.begin(), r.best.edges.end());
          initial_volts.insert(initial_volts.end(), r.initial.voltages.begin(),
                               r.initial.voltages.end());
          best_volts.insert(best_volts.end(), r.best.voltages.begin(), r.best.voltages.end());
          objectives.push_back(r.objective);
          worsts.push_back(r.worst_constraint);
          optimality.push_back(r.optimality);
          converged_flags.push_back(r.converged);
          counts.push_back(r.evaluations);
          solve_counts.push_back(r.solves);
          status_texts.push_back(r.status);
        }
      const std::size_t S = run.starts.size(), N = s.n_rings;
      product.group("/starts")
        .set(start_initial_edges, initial_edges, {S, N + 1})
        .set(start_initial_voltages, initial_volts, {S, N})
        .set(start_edges, best_edges, {S, N + 1})
        .set(start_voltages, best_volts, {S, N})
        .set(stroke_objective(s) ? start_stroke : start_volume, objectives)
        .set(start_worst_constraint, worsts)
        .set(start_first_order_residual, optimality)
        .set(start_converged, converged_flags)
        .set(start_evaluations, counts)
        .set(start_solves, solve_counts)
        .set(start_status, status_texts);
    }

    /// /optimum: the optimum's hoop stress and field at every point.
    void add_points(Product &product, const LayoutEvaluation &e, const Scene &base)
    {
      std::vector<double> r_over_a, ring;
      for (std::size_t k = 0; k < e.points.R.size(); ++k)
        {
          r_over_a.push_back(base.prestretch * e.points.R[k] / base.disk_radius);
          ring.push_back(e.points.ring[k] + 1.);
        }
      const std::size_t P = r_over_a.size();
      product.group("/optimum")
        .set(point_r_over_a, r_over_a)
        .set(point_ring, ring)
        .set(point_s2, std::vector<double>(e.points.s2.data(), e.points.s2.data() + P))
        .set(point_field, std::vector<double>(e.points.field.data(), e.points.field.data() + P))
        .set(n_quadrature_points, e.points.n_quadrature_points);
    }
  } // namespace

  Product optimum_product(const OptimizationRun &run, const OptimizationSettings &s,
                          const Scene &base, const std::string &parameter_text)
  {
    const LayoutEvaluation &e = run.starts.at(run.best).at_best;
    Product                 product;
    add_optimum(product.root(), run, s, parameter_text);
    add_history(product, run, s);
    add_starts(product, run, s);
    if (e.ok && e.points.s2.size() > 0)
      add_points(product, e, base);
    return product;
  }

  void write_replay_parameters(const ParameterInput &input, const std::string &path,
                               const Layout &layout, const std::string &base_name,
                               const double max_field)
  {
    std::vector<ParameterChange> changes = {
      {"Electrodes", "Ring edges (r/a)", joined(layout.edges, units::one)},
      {"Electrodes", "Voltage path (kV)", joined(layout.voltages, units::kV)},
      {"Solver", "Continuation", "load stepping"},
      {"Output", "Base name", base_name + "_optimum_run"}};
    // The replay then reports the largest field of every step.
    if (std::isfinite(max_field))
      changes.push_back({"Solver", "Breakdown field (MV/m)", exact_number(units::MV_per_m.from_si(max_field))});
    write_changed_parameters(
      input, path, changes,
      "# Written by cdea optimize: `cdea run` on this file ramps the voltages of the\n"
      "# optimum layout proportionally from zero and reaches the optimum state.\n");
  }
} // namespace cdea
