#pragma once
// Rows of the table of quantities of `cdea fit`, <Base name>_fit.h5
// (doc/optimization.md, doc/materials.md "Fits"): the root attributes and
// /correlation of every fit, then /data (and /curve) of each kind of data:
// displacement-voltage points, a DMA table, a creep curve. The fit
// parameters themselves are the free parameters' values in SI.

#include <cdea/model/quantity.h>

namespace cdea::fit_quantity
{
  // clang-format off
  // Every fit (the root attributes are cdea.fit()'s attributes).
  inline constexpr Quantity free_parameters = Quantity{
    "free_parameters", units::none, "the free parameters (Calibration/Free parameters), "
    "separated by '; ' in the file", shape::parameter, Storage::text, Place::attribute};
  inline constexpr Quantity initial_values = attribute(
    "initial_values", units::si, "start value of each free parameter", shape::parameter);
  inline constexpr Quantity fitted_values = attribute(
    "fitted_values", units::si, "fitted value of each free parameter", shape::parameter);
  inline constexpr Quantity standard_errors = attribute(
    "standard_errors", units::si,
    "standard error of each fitted value (NaN: not identifiable)", shape::parameter);
  inline constexpr Quantity rms_residual = attribute(
    "rms_residual_mm", units::mm,
    "weighted rms residual sqrt(sum w r^2 / sum w) (of a DMA fit: its Pa as if m, so MPa)");
  inline constexpr Quantity rms_residual_kPa = attribute(
    "rms_residual_kPa", units::kPa, "weighted rms residual of a DMA fit");
  inline constexpr Quantity condition_number = attribute(
    "condition_number", units::one, "condition number of the column-scaled Jacobian");
  inline constexpr Quantity converged = integer_attribute("converged", "1 if the fit converged");
  inline constexpr Quantity status = text_attribute("status", "how the fit ended");
  inline constexpr Quantity warnings = text_attribute(
    "warnings", "parameters the data do not determine, one a line");
  inline constexpr Quantity iterations = integer_attribute("iterations", "iterations of the fit");
  inline constexpr Quantity evaluations = integer_attribute(
    "evaluations", "evaluations of the model");
  inline constexpr Quantity solves = integer_attribute(
    "solves", "equilibrium solves (0 for the DMA and creep fits)");
  inline constexpr Quantity correlation = dataset(
    "correlation", units::one,
    "correlation matrix of the fitted parameters (order of free_parameters)", shape::parameter2);
  inline constexpr Quantity covariance = dataset(
    "covariance", units::si,
    "covariance s^2 (J^T W J)^-1 of the fitted values (order of free_parameters; NaN: not "
    "identifiable); Uncertainty/Covariance file of a run takes it", shape::parameter2);

  // Displacement-voltage points: /data and /curve.
  inline constexpr Quantity voltage = dataset(
    "voltage_kV", units::kV, "ring voltages of each data point", shape::point_ring);
  inline constexpr Quantity displacement = dataset(
    "displacement_mm", units::mm, "measured displacement", shape::point);
  inline constexpr Quantity weight = dataset(
    "weight", units::one, "weight of each point", shape::point);
  inline constexpr Quantity fitted = dataset(
    "fitted_mm", units::mm,
    "model displacement at the fitted parameters, each point ramped from zero", shape::point);
  inline constexpr Quantity residual = dataset(
    "residual_mm", units::mm, "model minus measured", shape::point);
  inline constexpr Quantity curve_voltage = dataset(
    "voltage_kV", units::kV, "ring voltages along the data in file order (8 steps between points)",
    shape::point_ring);
  inline constexpr Quantity curve_displacement = dataset(
    "displacement_mm", units::mm,
    "model displacement along the data at the fitted parameters, by continuation", shape::point);

  // A DMA table: /data.
  inline constexpr Quantity dma_frequency = dataset(
    "frequency_Hz", units::Hz, "frequency of each row", shape::frequency);
  inline constexpr Quantity dma_storage = dataset(
    "storage_kPa", units::kPa, "measured storage modulus E'", shape::frequency);
  inline constexpr Quantity dma_loss = dataset(
    "loss_kPa", units::kPa, "measured loss modulus E''", shape::frequency);
  inline constexpr Quantity dma_weight = dataset(
    "weight", units::one, "weight of each row (both moduli)", shape::frequency);
  inline constexpr Quantity dma_fitted_storage = dataset(
    "fitted_storage_kPa", units::kPa, "model E' at the fitted parameters", shape::frequency);
  inline constexpr Quantity dma_fitted_loss = dataset(
    "fitted_loss_kPa", units::kPa, "model E'' at the fitted parameters", shape::frequency);
  inline constexpr Quantity dma_residual_storage = dataset(
    "residual_storage_kPa", units::kPa, "model minus measured E'", shape::frequency);
  inline constexpr Quantity dma_residual_loss = dataset(
    "residual_loss_kPa", units::kPa, "model minus measured E''", shape::frequency);

  // A creep curve: /data.
  inline constexpr Quantity creep_time = dataset(
    "time_s", units::s, "sample time of each row", shape::point);
  inline constexpr Quantity creep_voltage = dataset(
    "voltage_kV", units::kV, "ring voltages at each sample time", shape::point_ring).file_only();
  inline constexpr Quantity creep_displacement = dataset(
    "displacement_mm", units::mm, "measured displacement", shape::point);
  inline constexpr Quantity creep_weight = dataset(
    "weight", units::one, "weight of each row", shape::point);
  inline constexpr Quantity creep_fitted = dataset(
    "fitted_mm", units::mm,
    "displacement of the quasi-static time run at the fitted parameters", shape::point);
  inline constexpr Quantity creep_residual = dataset(
    "residual_mm", units::mm, "model minus measured", shape::point);
  // clang-format on
} // namespace cdea::fit_quantity
