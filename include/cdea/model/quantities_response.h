#pragma once
// Rows of the table of quantities of `cdea response`, <Base name>_response.h5
// (doc/dynamics.md): the equilibrium as root attributes, /transfer (the
// transfer functions per ring and of the drive) and /modes. The Python
// result (cdea.response()) is one dict of the rows with a Python key, the
// transfer functions complex.

#include <cdea/model/quantity.h>

namespace cdea::response_quantity
{
  // clang-format off
  inline constexpr Quantity bias_voltage = attribute(
    "bias_voltage_kV", units::kV, "ring voltages of the equilibrium", shape::ring);
  inline constexpr Quantity displacement = attribute(
    "displacement_mm", units::mm, "displacement at the equilibrium");
  inline constexpr Quantity volume = attribute(
    "volume_mm3", units::mm3, "enclosed volume at the equilibrium");
  inline constexpr Quantity drive_scale = attribute(
    "drive_scale_kV", units::kV, "the largest bias voltage: the drive's scale");
  inline constexpr Quantity disk_mass = attribute(
    "disk_mass_g", units::g, "the disk's mass (0 without inertia)").file_only();
  inline constexpr Quantity water_mass = attribute(
    "water_column_mass_kg_per_m4", units::kg_per_m4,
    "the water column's rho_w h / S on the enclosed volume").file_only();
  inline constexpr Quantity density = attribute(
    "membrane_density_kg_per_m3", units::kg_per_m3, "the membrane's density").file_only();
  inline constexpr Quantity seconds = attribute(
    "seconds", units::s, "computing time of the transfer functions").file_only();

  // /transfer
  inline constexpr Quantity frequency = dataset(
    "frequency_Hz", units::Hz, "drive frequency", shape::frequency);
  inline constexpr Quantity disk_real = dataset(
    "disk_mm_per_kV_real", units::mm_per_kV,
    "displacement amplitude of the disk per kV on each ring (frequencies x rings) (real part)",
    shape::frequency_ring);
  inline constexpr Quantity disk_imag = dataset(
    "disk_mm_per_kV_imag", units::mm_per_kV,
    "displacement amplitude of the disk per kV on each ring (frequencies x rings) (imaginary "
    "part)", shape::frequency_ring);
  inline constexpr Quantity disk = dataset(
    "disk_mm_per_kV", units::mm_per_kV,
    "displacement amplitude of the disk per kV on each ring (frequencies x rings)",
    shape::frequency_ring).parts(disk_real, disk_imag);
  inline constexpr Quantity volume_real = dataset(
    "volume_mm3_per_kV_real", units::mm3_per_kV,
    "enclosed volume amplitude per kV on each ring (frequencies x rings) (real part)",
    shape::frequency_ring);
  inline constexpr Quantity volume_imag = dataset(
    "volume_mm3_per_kV_imag", units::mm3_per_kV,
    "enclosed volume amplitude per kV on each ring (frequencies x rings) (imaginary part)",
    shape::frequency_ring);
  inline constexpr Quantity volume_per_volt = dataset(
    "volume_mm3_per_kV", units::mm3_per_kV,
    "enclosed volume amplitude per kV on each ring (frequencies x rings)",
    shape::frequency_ring).parts(volume_real, volume_imag);
  inline constexpr Quantity drive_disk_real = dataset(
    "drive_disk_mm_per_kV_real", units::mm_per_kV,
    "displacement amplitude of the disk per kV of the drive (every ring in proportion to its "
    "bias voltage, drive_scale_kV the largest) (real part)", shape::frequency);
  inline constexpr Quantity drive_disk_imag = dataset(
    "drive_disk_mm_per_kV_imag", units::mm_per_kV,
    "displacement amplitude of the disk per kV of the drive (every ring in proportion to its "
    "bias voltage, drive_scale_kV the largest) (imaginary part)", shape::frequency);
  inline constexpr Quantity drive_disk = dataset(
    "drive_disk_mm_per_kV", units::mm_per_kV,
    "displacement amplitude of the disk per kV of the drive (every ring in proportion to its "
    "bias voltage, drive_scale_kV the largest)", shape::frequency).parts(drive_disk_real,
                                                                          drive_disk_imag);
  inline constexpr Quantity drive_volume_real = dataset(
    "drive_volume_mm3_per_kV_real", units::mm3_per_kV,
    "enclosed volume amplitude per kV of the drive (real part)", shape::frequency);
  inline constexpr Quantity drive_volume_imag = dataset(
    "drive_volume_mm3_per_kV_imag", units::mm3_per_kV,
    "enclosed volume amplitude per kV of the drive (imaginary part)", shape::frequency);
  inline constexpr Quantity drive_volume = dataset(
    "drive_volume_mm3_per_kV", units::mm3_per_kV,
    "enclosed volume amplitude per kV of the drive",
    shape::frequency).parts(drive_volume_real, drive_volume_imag);
  inline constexpr Quantity amplitude = dataset(
    "drive_disk_amplitude_mm_per_kV", units::mm_per_kV, "|drive_disk|: the Bode amplitude",
    shape::frequency).file_only();
  inline constexpr Quantity phase = dataset(
    "drive_disk_phase_deg", units::degree,
    "arg(drive_disk): the Bode phase (0: in phase with the voltage)",
    shape::frequency).file_only();

  // /modes
  inline constexpr Quantity mode_frequency = dataset(
    "frequency_Hz", units::Hz,
    "natural frequencies (modes of Re K(omega) and M at their own omega)",
    shape::mode).in_python("mode_frequency_Hz");
  inline constexpr Quantity mode_damping = dataset(
    "damping_ratio", units::one, "modal damping ratio u^T Im K u / (2 u^T Re K u)",
    shape::mode).in_python("mode_damping_ratio");
  inline constexpr Quantity sample_R = dataset(
    "R_mm", units::mm, "reference radius of the shape samples", shape::sample).file_only();
  inline constexpr Quantity shape_r = dataset(
    "shape_r", units::one,
    "radial displacement of each mode per unit disk displacement (modes x samples)",
    shape::mode_sample).file_only();
  inline constexpr Quantity shape_z = dataset(
    "shape_z", units::one,
    "vertical displacement of each mode per unit disk displacement (modes x samples)",
    shape::mode_sample).file_only();
  // clang-format on
} // namespace cdea::response_quantity
