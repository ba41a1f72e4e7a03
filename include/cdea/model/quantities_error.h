#pragma once
// The estimated numerical error of a quasi-static run's key outputs at its
// final state (fe/error_estimate.h; doc/accuracy.md): /summary attributes
// <name>_error, each the sum of its parts (discretization, Newton's
// remaining residual, the onset search's bracket), and their one assembly.

#include <cdea/model/output_fields.h>

#include <limits>
#include <string>
#include <vector>

namespace cdea
{
  /// An estimated error of a quasi-static run: a real /summary attribute.
  constexpr Quantity error_row(const char *name, const Unit &unit, const Shape &shape,
                               const char *description)
  {
    return summary_attribute_row(name, unit, Storage::real, shape, quasi_static_run, description);
  }

  namespace summary_attribute
  {
    // clang-format off
    inline constexpr Quantity displacement_error = error_row("displacement_error_mm", units::mm,
      shape::scalar, "estimated numerical error of the final displacement: discretization "
      "(degree p + 1 on the same mesh) plus Newton's remaining residual");
    inline constexpr Quantity stroke_error = error_row("stroke_error_mm", units::mm, shape::scalar,
      "estimated numerical error of the final stroke (final and end-of-load states)");
    inline constexpr Quantity volume_change_error = error_row("volume_change_error_mm3",
      units::mm3, shape::scalar,
      "estimated numerical error of the final volume change (final and end-of-load states)");
    inline constexpr Quantity s2_min_error = error_row("s2_min_error_kPa", units::kPa,
      shape::scalar, "estimated numerical error of the final smallest hoop stress s2_min");
    inline constexpr Quantity onset_voltage_error = error_row("onset_voltage_error_kV", units::kV,
      shape::ring, "estimated error of each onset voltage: discretization (the richer model's "
      "root of s2_min = 0) plus the onset search's bracket (NaN per ring if no onset)");
    inline constexpr Quantity error_estimate_method = summary_attribute_row("error_estimate",
      units::none, Storage::text, shape::scalar, quasi_static_run,
      "how the *_error attributes were estimated");
    // clang-format on
  } // namespace summary_attribute

  /// One output's estimated error in its parts (SI, absolute values).
  struct ErrorParts
  {
    double discretization = std::numeric_limits<double>::quiet_NaN();
    double newton         = 0.; ///< Newton's remaining residual
    double search         = 0.; ///< the onset search's bracket
    /// Their sum: NaN without a discretization part.
    double total() const { return discretization + newton + search; }
  };

  /// The estimated errors of a quasi-static run's key outputs.
  struct OutputErrors
  {
    ErrorParts displacement, stroke, volume_change, s2_min;
    /// One per ring; empty if the run found no onset.
    std::vector<ErrorParts> onset_voltages;
    std::string             method; ///< how they were made, for the file and the printout
  };

  /// The _error attributes of @p errors (NaN per ring for an onset not
  /// found) and the method, for the run's product stream.
  ProductGroup error_estimate_attributes(const OutputErrors &errors, unsigned int n_rings);
} // namespace cdea
