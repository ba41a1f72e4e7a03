#pragma once
// Rows of the table of quantities of `cdea chart` (<Base name>_chart.h5,
// doc/materials.md, "Material charts"): the root attributes, a group per
// loading path and /dma.

#include <cdea/model/quantity.h>

namespace cdea::chart_quantity
{
  // clang-format off
  inline constexpr Quantity material_model = text_attribute(
    "material_model", "Material/Model of the parameters: the law charted");
  inline constexpr Quantity voltage = attribute(
    "voltage_V", units::V, "the voltage of the charts (0: mechanical charts)");
  inline constexpr Quantity dma = text_attribute(
    "dma", "what the DMA chart is, or why there is none");

  // /uniaxial and /equibiaxial
  inline constexpr Quantity locking_stretch = attribute(
    "locking_stretch", units::one,
    "where the path leaves the law's range (infinity if not below the largest stretch)");
  inline constexpr Quantity stretch = dataset(
    "stretch", units::one, "stretch l1 along the load", shape::stretch);
  inline constexpr Quantity uniaxial_transverse_stretch = dataset(
    "transverse_stretch", units::one, "stretch l2 across the load (s2 = 0)", shape::stretch);
  inline constexpr Quantity equibiaxial_transverse_stretch = dataset(
    "transverse_stretch", units::one, "stretch l2 = l1", shape::stretch);
  inline constexpr Quantity nominal_stress = dataset(
    "nominal_stress_kPa", units::kPa,
    "nominal stress s1 = dW/dl1 (force per undeformed area), relaxed", shape::stretch);
  inline constexpr Quantity instantaneous_stress = dataset(
    "instantaneous_stress_kPa", units::kPa,
    "nominal stress s1 with the internal variables at the undeformed state", shape::stretch);
  inline constexpr Quantity instantaneous_transverse_stretch = dataset(
    "instantaneous_transverse_stretch", units::one, "l2 of the instantaneous curve",
    shape::stretch);

  // /dma
  inline constexpr Quantity relaxed_modulus = attribute(
    "relaxed_modulus_kPa", units::kPa, "small-strain uniaxial modulus E_A after relaxation");
  inline constexpr Quantity instantaneous_modulus = attribute(
    "instantaneous_modulus_kPa", units::kPa, "small-strain uniaxial modulus E_A + E_B at once");
  inline constexpr Quantity relaxation_time = attribute(
    "relaxation_time_s", units::s,
    "relaxation time tau of the standard linear solid (0: a relaxation spectrum)");
  inline constexpr Quantity frequency = dataset(
    "frequency_Hz", units::Hz, "frequency f (w = 2 pi f)", shape::frequency);
  inline constexpr Quantity storage_modulus = dataset(
    "storage_modulus_kPa", units::kPa, "storage modulus E' of small-strain uniaxial tension",
    shape::frequency);
  inline constexpr Quantity loss_modulus = dataset(
    "loss_modulus_kPa", units::kPa, "loss modulus E'' of small-strain uniaxial tension",
    shape::frequency);
  inline constexpr Quantity loss_factor = dataset(
    "loss_factor", units::one, "tan delta = E'' / E'", shape::frequency);
  // clang-format on
} // namespace cdea::chart_quantity
