#pragma once
// Rows of the table of quantities of `cdea sweep`, the design map
// <Base name>_map.h5 (doc/design-maps.md): root attributes, then datasets
// per layout (r_v/a), per outer voltage, or both. Voltages and stresses of
// the map convert by a division (units::kV_divided, kPa_divided).

#include <cdea/model/quantity.h>

namespace cdea::sweep_quantity
{
  // clang-format off
  // Root attributes (all of them in the Python result's attributes).
  inline constexpr Quantity parameters = text_attribute(
    "parameters", "every parameter of the map, as a parameter file");
  inline constexpr Quantity code_version = text_attribute(
    "code_version", "the version of cdea that wrote the map");
  inline constexpr Quantity method = text_attribute(
    "method", "the model of the map (finite elements)");
  inline constexpr Quantity run_status = text_attribute(
    "run_status", "complete, or why the map stopped");
  inline constexpr Quantity inner_voltage = attribute(
    "inner_voltage_kV", units::kV_divided, "voltage of the inner ring");
  inline constexpr Quantity outer_from = attribute(
    "outer_voltage_from_kV", units::kV_divided, "first outer voltage of the grid");
  inline constexpr Quantity outer_to = attribute(
    "outer_voltage_to_kV", units::kV_divided, "last outer voltage of the grid");
  inline constexpr Quantity outer_step = attribute(
    "outer_voltage_step_kV", units::kV_divided, "step of the outer voltages");
  inline constexpr Quantity line_tolerance = attribute(
    "line_tolerance_V", units::V, "tolerance of the root finding of the two lines");
  inline constexpr Quantity zero_voltage_displacement = attribute(
    "zero_voltage_displacement_mm", units::mm,
    "displacement with all voltages zero under the dead load (the zero of the stroke)");
  inline constexpr Quantity n_rv = integer_attribute("n_rv", "layouts (rows) of the map");
  inline constexpr Quantity n_outer = integer_attribute("n_outer", "outer voltages of the grid");
  inline constexpr Quantity ring_edge_values = text_attribute(
    "ring_edge_values", "the layouts' r_v/a as Sweep/Ring edge values lists them");

  // The grid: the layouts, the outer voltages and the fields over both.
  inline constexpr Quantity rv_over_a = dataset(
    "rv_over_a", units::one,
    "inner ring's outer edge r_v over the disk radius a (pre-stretched flat film)",
    shape::layout);
  inline constexpr Quantity outer_voltage = dataset(
    "outer_voltage_kV", units::kV_divided,
    "voltage of the outer ring; the inner ring is held at inner_voltage_kV",
    shape::outer_voltage);
  inline constexpr Quantity displacement = dataset(
    "displacement_mm", units::mm,
    "disk deflection |z(disk) - z(frame)|, rv x outer voltage; NaN where the continuation did "
    "not reach the point", shape::layout_outer);
  inline constexpr Quantity stroke = dataset(
    "stroke_mm", units::mm, "displacement minus zero_voltage_displacement_mm",
    shape::layout_outer);
  inline constexpr Quantity stroke_increase = dataset(
    "stroke_increase_percent", units::percent,
    "100 (stroke / stroke with both rings at the inner voltage - 1)", shape::layout_outer);
  inline constexpr Quantity s2_inner_edge = dataset(
    "s2_inner_edge_kPa", units::kPa_divided,
    "nominal hoop stress s2 at the inner edge of ring 1 (disk edge) and ring 2 (r_v, on the "
    "outer ring's side), rv x outer voltage x 2", shape::layout_outer_edge2);

  // The red and the blue line: one point per layout each.
  inline constexpr Quantity red_outer = dataset(
    "red_line_outer_kV", units::kV_divided,
    "outer voltage on the red line (s2 = 0 at the outer ring's inner edge), by root finding "
    "to line_tolerance_V; NaN where absent in the range", shape::layout);
  inline constexpr Quantity red_increase = dataset(
    "red_line_increase_percent", units::percent,
    "stroke increase on the red line (s2 = 0 at the outer ring's inner edge)", shape::layout);
  inline constexpr Quantity red_displacement = dataset(
    "red_line_displacement_mm", units::mm,
    "displacement on the red line (s2 = 0 at the outer ring's inner edge)", shape::layout);
  inline constexpr Quantity red_s2 = dataset(
    "red_line_s2_inner_edge_kPa", units::kPa_divided,
    "s2 at the inner edges of rings 1 and 2 on the red line (s2 = 0 at the outer ring's inner "
    "edge)", shape::layout_edge2);
  inline constexpr Quantity blue_outer = dataset(
    "blue_line_outer_kV", units::kV_divided,
    "outer voltage on the blue line (equal s2 at the inner edges of both rings), by root "
    "finding to line_tolerance_V; NaN where absent in the range", shape::layout);
  inline constexpr Quantity blue_increase = dataset(
    "blue_line_increase_percent", units::percent,
    "stroke increase on the blue line (equal s2 at the inner edges of both rings)",
    shape::layout);
  inline constexpr Quantity blue_displacement = dataset(
    "blue_line_displacement_mm", units::mm,
    "displacement on the blue line (equal s2 at the inner edges of both rings)", shape::layout);
  inline constexpr Quantity blue_s2 = dataset(
    "blue_line_s2_inner_edge_kPa", units::kPa_divided,
    "s2 at the inner edges of rings 1 and 2 on the blue line (equal s2 at the inner edges of "
    "both rings)", shape::layout_edge2);

  // Per layout: its base state, how far it got, its cost and why it stopped.
  inline constexpr Quantity base_displacement = dataset(
    "base_displacement_mm", units::mm,
    "displacement with both rings at the inner voltage (the reference of the stroke increase)",
    shape::layout);
  inline constexpr Quantity base_s2 = dataset(
    "base_s2_inner_edge_kPa", units::kPa_divided,
    "s2 at the inner edges of rings 1 and 2 with both rings at the inner voltage",
    shape::layout_edge2);
  inline constexpr Quantity lowest_outer = dataset(
    "lowest_outer_kV", units::kV_divided,
    "lowest outer voltage of the grid reached by the continuation", shape::layout);
  inline constexpr Quantity highest_outer = dataset(
    "highest_outer_kV", units::kV_divided,
    "highest outer voltage of the grid reached by the continuation", shape::layout);
  inline constexpr Quantity solves = dataset(
    "solves", units::one,
    "equilibrium solves of the row (load stages, continuation, root finding)",
    shape::layout).with(Storage::integer);
  inline constexpr Quantity newton_iterations = dataset(
    "newton_iterations", units::one, "Newton iterations of the row",
    shape::layout).with(Storage::integer);
  inline constexpr Quantity stop_message = dataset(
    "stop_message", units::none,
    "why the continuation of the row stopped before the end of the grid (empty if it did "
    "not)", shape::layout).with(Storage::text);
  // clang-format on
} // namespace cdea::sweep_quantity
