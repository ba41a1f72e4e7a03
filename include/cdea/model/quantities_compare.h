#pragma once
// Rows of the table of quantities of `cdea compare`: the last converged
// state of each model (groups /finite_elements and /shooting) and how far
// apart their meridians are. Printed as a table; no file, no Python result.

#include <cdea/model/quantity.h>

namespace cdea::compare_quantity
{
  // clang-format off
  // Each model's group.
  inline constexpr Quantity displacement = attribute(
    "displacement_mm", units::mm, "displacement of the last converged step");
  inline constexpr Quantity stroke = attribute(
    "stroke_mm", units::mm, "stroke of the last converged step");
  inline constexpr Quantity volume = attribute(
    "volume_mm3", units::mm3, "enclosed volume of the last converged state");
  inline constexpr Quantity s2_over_mu = attribute(
    "s2_ring_inner_over_mu", units::one,
    "nominal hoop stress over the shear modulus at the inner edge of each ring", shape::ring);
  inline constexpr Quantity onset_voltage = attribute(
    "onset_voltage_kV", units::kV, "ring voltages of the loss of tension (if found)",
    shape::ring);
  inline constexpr Quantity onset_radius = attribute(
    "onset_radius_mm", units::mm, "pre-stretched flat radius of the loss of tension (if found)");

  // The root group: the meridians of both models compared.
  inline constexpr Quantity r_difference = attribute(
    "max_r_difference_mm", units::mm,
    "max |r_FE - r_sh| over the meridian, at the shooting solver's sample radii");
  inline constexpr Quantity z_difference = attribute(
    "max_z_difference_mm", units::mm, "max |z_FE - z_sh| over the meridian");
  inline constexpr Quantity r_difference_over_a = attribute(
    "max_r_difference_over_a", units::one, "max |r_FE - r_sh| over the disk radius a");
  inline constexpr Quantity z_difference_over_a = attribute(
    "max_z_difference_over_a", units::one, "max |z_FE - z_sh| over the disk radius a");
  // clang-format on
} // namespace cdea::compare_quantity
