#pragma once
// Rows of the table of quantities of the uncertainty of a run's answers
// (Uncertainty/Mode, doc/uncertainty.md): /summary attributes of `cdea run`
// beside the values they are about. Linear propagation sets the _std rows;
// Monte-Carlo sets them too (the samples' standard deviation) with the
// samples' means and 5, 50 and 95 % percentiles.

#include <cdea/model/output_fields.h>

namespace cdea
{
  namespace shape
  {
    inline constexpr Shape percentile{{"percentile"}}; ///< 5, 50, 95 %
    inline constexpr Shape percentile_ring{{"percentile", "ring"}};
  } // namespace shape

  namespace uncertainty_quantity
  {
    /// The percentiles of the percentile rows (%).
    inline constexpr double percentiles[] = {5., 50., 95.};

    // clang-format off
    // Each row: name, unit, storage, shape, runs, description.
    inline constexpr Quantity samples = summary_attribute_row(
      "uncertainty_samples", units::one, Storage::integer, shape::scalar, quasi_static_run,
      "Monte-Carlo runs that reached the end of the voltage path (of Uncertainty/Samples)");
    inline constexpr Quantity onset_samples = summary_attribute_row(
      "uncertainty_onset_samples", units::one, Storage::integer, shape::scalar,
      quasi_static_run, "of those, the runs that found the onset of wrinkling");

    inline constexpr Quantity displacement_std = summary_attribute_row(
      "displacement_std_mm", units::mm, Storage::real, shape::scalar, quasi_static_run,
      "one standard deviation of the final displacement");
    inline constexpr Quantity stroke_std = summary_attribute_row(
      "stroke_std_mm", units::mm, Storage::real, shape::scalar, quasi_static_run,
      "one standard deviation of the final stroke");
    inline constexpr Quantity volume_change_std = summary_attribute_row(
      "volume_change_std_mm3", units::mm3, Storage::real, shape::scalar, quasi_static_run,
      "one standard deviation of the final volume change");
    inline constexpr Quantity onset_voltage_std = summary_attribute_row(
      "onset_voltage_std_kV", units::kV, Storage::real, shape::ring, quasi_static_run,
      "one standard deviation of the ring voltages at the onset of wrinkling (NaN if none)");
    inline constexpr Quantity limit_point_voltage_std = summary_attribute_row(
      "limit_point_voltage_std_kV", units::kV, Storage::real, shape::limit_ring,
      quasi_static_run,
      "one standard deviation of the ring voltages of each limit point (fold), k x rings "
      "(linear only)");

    inline constexpr Quantity displacement_mean = summary_attribute_row(
      "displacement_mean_mm", units::mm, Storage::real, shape::scalar, quasi_static_run,
      "mean final displacement of the Monte-Carlo runs");
    inline constexpr Quantity stroke_mean = summary_attribute_row(
      "stroke_mean_mm", units::mm, Storage::real, shape::scalar, quasi_static_run,
      "mean final stroke of the Monte-Carlo runs");
    inline constexpr Quantity volume_change_mean = summary_attribute_row(
      "volume_change_mean_mm3", units::mm3, Storage::real, shape::scalar, quasi_static_run,
      "mean final volume change of the Monte-Carlo runs");
    inline constexpr Quantity onset_voltage_mean = summary_attribute_row(
      "onset_voltage_mean_kV", units::kV, Storage::real, shape::ring, quasi_static_run,
      "mean onset voltages of the Monte-Carlo runs that found one (NaN if none did)");

    inline constexpr Quantity displacement_percentiles = summary_attribute_row(
      "displacement_percentiles_mm", units::mm, Storage::real, shape::percentile,
      quasi_static_run, "5, 50 and 95 % percentiles of the final displacement");
    inline constexpr Quantity stroke_percentiles = summary_attribute_row(
      "stroke_percentiles_mm", units::mm, Storage::real, shape::percentile, quasi_static_run,
      "5, 50 and 95 % percentiles of the final stroke");
    inline constexpr Quantity volume_change_percentiles = summary_attribute_row(
      "volume_change_percentiles_mm3", units::mm3, Storage::real, shape::percentile,
      quasi_static_run, "5, 50 and 95 % percentiles of the final volume change");
    inline constexpr Quantity onset_voltage_percentiles = summary_attribute_row(
      "onset_voltage_percentiles_kV", units::kV, Storage::real, shape::percentile_ring,
      quasi_static_run, "5, 50 and 95 % percentiles of the onset voltages (percentile x ring)");
    // clang-format on
  } // namespace uncertainty_quantity
} // namespace cdea
