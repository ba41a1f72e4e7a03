#pragma once
// Rows of the table of quantities of `cdea fit` with Calibration/Candidate
// models, <Base name>_models.h5 (doc/materials.md, "Choosing a model"): the
// verdict at the root, one row per candidate in /models (with per-file
// columns over the test dimension), the files in /tests (the rows of
// model/quantities_material_fit.h) and every model's constants in
// /constants.

#include <cdea/model/quantity.h>

namespace cdea::model_selection_quantity
{
  namespace shape
  {
    inline constexpr Shape model{{"model"}};
    inline constexpr Shape model_test{{"model", "test"}};
    inline constexpr Shape constant{{"constant"}}; ///< every model's constants, model after model
  } // namespace shape

  // clang-format off
  inline constexpr Quantity recommended = text_attribute(
    "recommended", "the model with the lowest held-out error (the lowest BIC where there is none)");
  inline constexpr Quantity decided = integer_attribute(
    "decided", "1: the second best's held-out error is above the best's by more than the spread");
  inline constexpr Quantity verdict = text_attribute("verdict", "the recommendation in words");
  inline constexpr Quantity spread = attribute(
    "spread", units::one, "of the two best models' held-out errors: their sampling errors "
    "combined, or the standard error of their differences over the files if larger (NaN: not "
    "computed)");

  // /models: one row per candidate.
  inline constexpr Quantity model = dataset(
    "model", units::none, "the candidate as Calibration/Candidate models names it", shape::model)
    .with(Storage::text);
  inline constexpr Quantity law = dataset(
    "law", units::none, "the elastic law (Material/Model)", shape::model).with(Storage::text);
  inline constexpr Quantity branches = dataset(
    "branches", units::one, "viscous branches beside it", shape::model).with(Storage::integer);
  inline constexpr Quantity constants = dataset(
    "constants", units::one, "free constants k", shape::model).with(Storage::integer);
  inline constexpr Quantity samples = dataset(
    "samples", units::one, "fitted samples n (every file)", shape::model).with(Storage::integer);
  inline constexpr Quantity converged = dataset(
    "converged", units::one, "1 if the fit on every file converged", shape::model)
    .with(Storage::integer);
  inline constexpr Quantity rss = dataset(
    "rss_kPa2", units::kPa2, "weighted residual sum of squares sum w r^2 of the fit on every file",
    shape::model);
  inline constexpr Quantity aic = dataset(
    "aic", units::one, "n ln(RSS / n) + 2 k, RSS in kPa^2", shape::model);
  inline constexpr Quantity bic = dataset(
    "bic", units::one, "n ln(RSS / n) + k ln n, RSS in kPa^2", shape::model);
  inline constexpr Quantity held_out_error = dataset(
    "held_out_error", units::one, "mean over the files of the held-out relative rms (NaN: one "
    "file, not computed)", shape::model);
  inline constexpr Quantity rms = dataset(
    "rms_kPa", units::kPa, "rms residual of each file in the fit on every file", shape::model_test);
  inline constexpr Quantity relative_rms = dataset(
    "relative_rms", units::one, "that over the file's largest |stress|", shape::model_test);
  inline constexpr Quantity held_out_rms = dataset(
    "held_out_rms_kPa", units::kPa,
    "rms residual of each file predicted by the model fitted to the other files", shape::model_test);
  inline constexpr Quantity held_out_relative_rms = dataset(
    "held_out_relative_rms", units::one, "that over the file's largest |stress|",
    shape::model_test);

  // /constants: every model's free constants.
  inline constexpr Quantity constant_model = dataset(
    "model", units::one, "the constant's row of /models (from 0)", shape::constant)
    .with(Storage::integer);
  inline constexpr Quantity constant_name = dataset(
    "constant", units::none, "the free constant (its name in Calibration/Free parameters)",
    shape::constant).with(Storage::text);
  inline constexpr Quantity value = dataset(
    "value", units::si, "fitted value (SI: Pa, s or 1)", shape::constant);
  inline constexpr Quantity standard_error = dataset(
    "standard_error", units::si, "standard error of the fitted value (NaN: not identifiable)",
    shape::constant);
  // clang-format on
} // namespace cdea::model_selection_quantity
