#pragma once
// Rows of the table of quantities of `cdea fit` on material tests,
// <Base name>_fit.h5 (doc/materials.md, "Fitting material tests"): besides
// the root attributes and /correlation of every fit (model/quantities_fit.h),
// (the covariance is every fit's, model/quantities_fit.h), one row per file in /tests (fitted or predicted) and every
// sample of every file in /samples, measured and modelled side by side.

#include <cdea/model/quantity.h>

namespace cdea::material_fit_quantity
{
  namespace shape
  {
    inline constexpr Shape test{{"test"}};     ///< one per data file
    inline constexpr Shape sample{{"sample"}}; ///< every file's samples, file after file
  } // namespace shape

  // clang-format off
  inline constexpr Quantity rms_residual_kPa = attribute(
    "rms_residual_kPa", units::kPa, "weighted rms residual of all fitted samples");

  // /tests: one row per file, the fitted ones first, then the predicted.
  inline constexpr Quantity file = dataset(
    "file", units::none, "the data file as given on the command line", shape::test)
    .with(Storage::text);
  inline constexpr Quantity kind = dataset(
    "kind", units::none, "uniaxial, equibiaxial or pure shear", shape::test)
    .with(Storage::text);
  inline constexpr Quantity fitted = dataset(
    "fitted", units::one, "1: fitted, 0: predicted with the fitted values (--predict)",
    shape::test).with(Storage::integer);
  inline constexpr Quantity file_weight = dataset(
    "weight", units::one, "the file's weight (its '# weight' line; 1 without)", shape::test);
  inline constexpr Quantity samples = dataset(
    "samples", units::one, "samples of the file", shape::test).with(Storage::integer);
  inline constexpr Quantity rms = dataset(
    "rms_kPa", units::kPa, "rms residual sqrt(sum w r^2 / sum w) over the file's samples",
    shape::test);
  inline constexpr Quantity largest = dataset(
    "largest_stress_kPa", units::kPa, "the file's largest |measured nominal stress|", shape::test);
  inline constexpr Quantity relative_rms = dataset(
    "relative_rms", units::one, "rms residual over the file's largest |stress|", shape::test);

  // /samples: every file's history, in the order of /tests.
  inline constexpr Quantity test = dataset(
    "test", units::one, "the sample's row of /tests (from 0)", shape::sample)
    .with(Storage::integer);
  inline constexpr Quantity time = dataset("time_s", units::s, "sample time", shape::sample);
  inline constexpr Quantity stretch = dataset(
    "stretch", units::one, "stretch of the loaded direction from the unstressed state",
    shape::sample);
  inline constexpr Quantity measured = dataset(
    "measured_stress_kPa", units::kPa, "measured nominal stress", shape::sample);
  inline constexpr Quantity model = dataset(
    "model_stress_kPa", units::kPa,
    "the material point's nominal stress at the fitted values", shape::sample);
  inline constexpr Quantity residual = dataset(
    "residual_kPa", units::kPa, "model minus measured", shape::sample);
  inline constexpr Quantity sample_weight = dataset(
    "weight", units::one, "the row's weight (its weight column; 1 without)", shape::sample);
  // clang-format on
} // namespace cdea::material_fit_quantity
