#pragma once
// Rows of the table of quantities of `cdea optimize`, <Base name>_optimum.h5
// (doc/optimization.md): the optimum as root attributes, /history (every
// evaluation), /starts (every start) and /optimum (the optimum's points).
// The root attributes but the provenance and /history are the Python
// result's (OptimizeResult.attributes and .history).

#include <cdea/model/quantity.h>

namespace cdea::optimize_quantity
{
  // clang-format off
  inline constexpr Quantity objective = text_attribute(
    "objective", "what is maximised: stroke or volume (Optimization/Objective)");
  inline constexpr Quantity algorithm = text_attribute(
    "algorithm", "the optimizer (Optimization/Algorithm)");
  inline constexpr Quantity ring_edges = attribute(
    "ring_edges_over_a", units::one, "ring edges of the optimum layout over a", shape::edge);
  inline constexpr Quantity voltages = attribute(
    "voltages_kV", units::kV, "ring voltages of the optimum layout", shape::ring);
  inline constexpr Quantity displacement = attribute(
    "displacement_mm", units::mm, "displacement at the optimum");
  inline constexpr Quantity stroke = attribute(
    "stroke_mm", units::mm, "stroke at the optimum");
  inline constexpr Quantity volume_change = attribute(
    "volume_change_mm3", units::mm3, "enclosed volume change at the optimum");
  inline constexpr Quantity min_s2 = attribute(
    "min_s2_kPa", units::kPa, "smallest hoop stress at the optimum's points (NaN: none)");
  inline constexpr Quantity max_field = attribute(
    "max_field_MV_per_m", units::MV_per_m,
    "largest true electric field at the optimum's points (NaN: none)");
  inline constexpr Quantity active_constraints = text_attribute(
    "active_constraints", "the constraints active at the optimum, separated by '; '");
  inline constexpr Quantity iterations = integer_attribute(
    "iterations", "evaluations of every start");
  inline constexpr Quantity solves = integer_attribute(
    "solves", "equilibrium solves of every start");
  inline constexpr Quantity converged = integer_attribute(
    "converged", "1 if the best start converged");
  inline constexpr Quantity status = text_attribute(
    "status", "how the optimizer of the best start ended");
  inline constexpr Quantity first_order_residual = attribute(
    "first_order_residual", units::one,
    "|grad f + A lambda| / |grad f| of the best start (KKT)");
  inline constexpr Quantity optimum_start = integer_attribute(
    "best_start", "the start of the optimum (from 0)");
  inline constexpr Quantity starts = integer_attribute("starts", "starts of the multistart");
  inline constexpr Quantity min_tangent_eigenvalue = attribute(
    "min_tangent_eigenvalue_N_per_m", units::N_per_m,
    "smallest eigenvalue of the tangent at the optimum");

  // /history: every evaluation of every start.
  inline constexpr Quantity free_variables = text_attribute(
    "free_variables", "the free variables, separated by '; '").file_only();
  inline constexpr Quantity history_start = dataset(
    "start", units::one, "start of the multistart (from 0)",
    shape::evaluation).with(Storage::integer).python_as("int64");
  inline constexpr Quantity history_evaluation = dataset(
    "evaluation", units::one, "evaluation within the start (from 1)",
    shape::evaluation).with(Storage::integer).python_as("int64");
  inline constexpr Quantity history_stroke = dataset(
    "objective", units::objective_mm,
    "stroke (mm) of the layout evaluated; NaN where it could not be reached",
    shape::evaluation);
  inline constexpr Quantity history_volume = dataset(
    "objective", units::objective_thousand_mm3,
    "enclosed volume change (1000 mm^3) of the layout evaluated; NaN where it could not be "
    "reached", shape::evaluation);
  inline constexpr Quantity history_worst_constraint = dataset(
    "worst_constraint", units::one,
    "largest scaled constraint value (s2: (limit - s2)/mu, E: E/E_max - 1, width: "
    "(w_min - width)/(b/a - 1)); <= 0 is feasible", shape::evaluation);
  inline constexpr Quantity history_free_values = dataset(
    "free_values", units::free_variables, "the free variables of each evaluation: ",
    shape::evaluation_free);

  // /starts: every start's outcome (the file's only).
  inline constexpr Quantity start_initial_edges = dataset(
    "initial_ring_edges_over_a", units::one, "ring edges of each starting layout",
    shape::start_edge).file_only();
  inline constexpr Quantity start_initial_voltages = dataset(
    "initial_voltages_kV", units::kV,
    "ring voltages of each starting layout (lowered until a ramp reaches them)",
    shape::start_ring).file_only();
  inline constexpr Quantity start_edges = dataset(
    "ring_edges_over_a", units::one, "ring edges of the best layout of each start",
    shape::start_edge).file_only();
  inline constexpr Quantity start_voltages = dataset(
    "voltages_kV", units::kV, "ring voltages of the best layout of each start",
    shape::start_ring).file_only();
  inline constexpr Quantity start_stroke = dataset(
    "objective", units::objective_mm,
    "stroke (mm) of the best layout of each start, confirmed by a ramp from zero",
    shape::start).file_only();
  inline constexpr Quantity start_volume = dataset(
    "objective", units::objective_thousand_mm3,
    "enclosed volume change (1000 mm^3) of the best layout of each start, confirmed by a ramp "
    "from zero", shape::start).file_only();
  inline constexpr Quantity start_worst_constraint = dataset(
    "worst_constraint", units::one, "largest scaled constraint value there (<= 1e-6: feasible)",
    shape::start).file_only();
  inline constexpr Quantity start_first_order_residual = dataset(
    "first_order_residual", units::one,
    "|grad f + A lambda| / |grad f| over the active constraints and bounds (KKT)",
    shape::start).file_only();
  inline constexpr Quantity start_converged = dataset(
    "converged", units::one, "1 if the optimizer converged to a feasible layout",
    shape::start).with(Storage::integer).file_only();
  inline constexpr Quantity start_evaluations = dataset(
    "evaluations", units::one, "evaluations of the start",
    shape::start).with(Storage::integer).file_only();
  inline constexpr Quantity start_solves = dataset(
    "solves", units::one, "equilibrium solves of the start",
    shape::start).with(Storage::integer).file_only();
  inline constexpr Quantity start_status = dataset(
    "status", units::none, "how the optimizer ended",
    shape::start).with(Storage::text).file_only();

  // /optimum: the optimum's hoop stress and field at every point (the file's only).
  inline constexpr Quantity n_quadrature_points = integer_attribute(
    "n_quadrature_points", "the points that are quadrature points (the rest: ring edges)");
  inline constexpr Quantity point_r_over_a = dataset(
    "r_over_a", units::one,
    "pre-stretched flat radius of each point: the quadrature points cell by cell, then the "
    "inner edge of each ring", shape::point).file_only();
  inline constexpr Quantity point_ring = dataset(
    "ring", units::one, "ring of each point (from 1)", shape::point).file_only();
  inline constexpr Quantity point_s2 = dataset(
    "s2_kPa", units::kPa, "nominal hoop stress at each point", shape::point).file_only();
  inline constexpr Quantity point_field = dataset(
    "field_MV_per_m", units::MV_per_m, "true electric field at each point",
    shape::point).file_only();
  // clang-format on
} // namespace cdea::optimize_quantity
