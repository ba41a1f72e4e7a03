#pragma once
// Rows of the table of quantities of `cdea frequency-sweep`,
// <Base name>_frequency_sweep.h5 (doc/dynamics.md): the quasi-static
// amplitude and the usable band as root attributes, /sweep a value per
// frequency. The Python result (cdea.frequency_sweep()) is one dict of the
// rows with a Python key, the first harmonic complex.

#include <cdea/model/quantity.h>

namespace cdea::frequency_sweep_quantity
{
  // clang-format off
  inline constexpr Quantity quasi_static_amplitude = attribute(
    "quasi_static_amplitude_mm", units::mm, "stroke amplitude of the film relaxed");
  inline constexpr Quantity usable_factor = attribute(
    "usable_stroke_factor", units::one,
    "Frequency sweep/Usable stroke factor: the usable strokes' range about the quasi-static "
    "one").file_only();
  inline constexpr Quantity band_low = attribute(
    "usable_band_low_Hz", units::Hz, "lowest frequency of the usable band (NaN: none)");
  inline constexpr Quantity band_high = attribute(
    "usable_band_high_Hz", units::Hz, "highest frequency of the usable band (NaN: none)");
  inline constexpr Quantity seconds = attribute(
    "seconds", units::s, "computing time of the sweep").file_only();

  // /sweep: one value per frequency.
  inline constexpr Quantity frequency = dataset(
    "frequency_Hz", units::Hz, "drive frequency", shape::frequency);
  inline constexpr Quantity stroke_amplitude = dataset(
    "stroke_amplitude_mm", units::mm, "half the peak-to-peak of z(A) over the steady period",
    shape::frequency);
  inline constexpr Quantity mean_displacement = dataset(
    "mean_displacement_mm", units::mm, "z(A) averaged over the steady period", shape::frequency);
  inline constexpr Quantity harmonic_real = dataset(
    "harmonic_real_mm", units::mm, "z(A)'s first harmonic c: z = mean + Re(c exp(i w t)) + ...",
    shape::frequency);
  inline constexpr Quantity harmonic_imag = dataset(
    "harmonic_imag_mm", units::mm, "imaginary part of c", shape::frequency);
  inline constexpr Quantity harmonic = dataset(
    "harmonic_mm", units::mm, "z(A)'s first harmonic c (complex)",
    shape::frequency).parts(harmonic_real, harmonic_imag);
  inline constexpr Quantity swept_volume = dataset(
    "swept_volume_mm3", units::mm3,
    "peak-to-peak of the enclosed volume: the volume pumped per cycle with the water load, the "
    "swept volume without", shape::frequency);
  inline constexpr Quantity dissipated = dataset(
    "dissipated_energy_mJ", units::mJ, "the branches' dissipation over the period",
    shape::frequency);
  inline constexpr Quantity electrical_work = dataset(
    "electrical_work_mJ", units::mJ, "the voltage source's work over the period",
    shape::frequency);
  inline constexpr Quantity energy_defect = dataset(
    "energy_defect", units::one, "|electrical work - dissipated - stored change| / dissipated",
    shape::frequency).file_only();
  inline constexpr Quantity s2_min = dataset(
    "s2_min_kPa", units::kPa, "smallest hoop stress over the period", shape::frequency);
  inline constexpr Quantity periodicity_defect = dataset(
    "periodicity_defect", units::one, "weighted periodicity defect (Steady state/Tolerance)",
    shape::frequency);
  inline constexpr Quantity frequency_seconds = dataset(
    "seconds", units::s, "computing time of the frequency", shape::frequency).file_only();
  inline constexpr Quantity loss_of_tension = dataset(
    "loss_of_tension", units::one, "1: the swing reaches loss of tension (s2 < 0)",
    shape::frequency).with(Storage::integer);
  inline constexpr Quantity usable = dataset(
    "usable", units::one, "1: taut and the stroke within the usable factor",
    shape::frequency).with(Storage::integer);
  inline constexpr Quantity converged = dataset(
    "converged", units::one, "1: the periodic steady state converged",
    shape::frequency).with(Storage::integer);
  inline constexpr Quantity newton_iterations = dataset(
    "newton_iterations", units::one, "Newton iterations",
    shape::frequency).with(Storage::integer).file_only();
  inline constexpr Quantity period_maps = dataset(
    "period_maps", units::one, "periods integrated (GMRES, checks, start)",
    shape::frequency).with(Storage::integer).file_only();
  // clang-format on
} // namespace cdea::frequency_sweep_quantity
