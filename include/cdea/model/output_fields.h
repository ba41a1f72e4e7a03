#pragma once
// The one table of what a run's results hold: every /summary column, the
// /summary attributes and the /steps fields, one row each with the name, the
// unit, the factor from SI to the file's unit, the description, whether it is
// stored as integers, whether it has one value per ring, and which runs write
// it. The results document (HDF5), the journal, the ParaView writer and the
// Python module take names, units, factors and values from here; a material
// law adds the /steps fields of its internal variables by declaring them
// (MembraneLaw::internal_variables()). No HDF5 and no deal.II here.
//
// A new /summary column is one row in namespace summary_column and the
// postprocessor that sets it, summary.columns.set(summary_column::x, SI
// value); readers take it by the same handle, summary.columns.get(...).
// The file's units: lengths in mm, stresses in kPa, voltages in kV, fields in
// MV/m, masses in g, volumes in mm^3, energies in mJ.

#include <cdea/model/records.h>

#include <vector>

namespace cdea
{
  /// Factors from SI to the units of the results file.
  namespace file_units
  {
    constexpr double mm       = 1e3;
    constexpr double kPa      = 1e-3;
    constexpr double kV       = 1e-3;
    constexpr double MV_per_m = 1e-6;
    constexpr double g        = 1e3;
    constexpr double mm3      = 1e9;
    constexpr double mJ       = 1e3;
  } // namespace file_units

  /// The runs that write a quantity (bits): `cdea run` quasi-static, `cdea
  /// shoot`, and `cdea run` in time (Time/Enabled).
  enum RunKind : unsigned int
  {
    quasi_static_run = 1,
    shooting_run     = 2,
    time_run         = 4,
    load_path_runs   = quasi_static_run | shooting_run,
    every_run        = quasi_static_run | shooting_run | time_run
  };

  /// How the file stores a quantity: 64-bit reals or 32-bit integers.
  enum class Storage
  {
    real,
    integer
  };

  /// One value per step (or per attribute), or one per ring.
  enum class Shape
  {
    scalar,
    per_ring
  };

  /// One row of the table.
  struct OutputField
  {
    const char *name; ///< dataset or attribute name (with the unit where it is not 1)
    const char *unit; ///< the dataset's `unit` attribute
    double      factor; ///< from SI to the file's unit
    Storage     storage;
    Shape       shape;
    unsigned int runs; ///< RunKind bits
    const char  *description;
    /// A standard /summary column: its SI values from the StepSummary's
    /// members (one per ring if Shape::per_ring). Null for the
    /// postprocessors' columns (StepSummary::columns) and attributes.
    std::vector<double> (*summary_values)(const StepSummary &) = nullptr;

    /// @p si_value in the file's unit.
    double in_file_units(const double si_value) const { return si_value * factor; }
  };

  /// Every value of @p values times @p factor.
  std::vector<double> scaled(const std::vector<double> &values, double factor);

  /// The /summary columns, one row each. The standard ones come first, in
  /// the file's order; every run has them and they are StepSummary members.
  /// The postprocessors' columns follow, each set by its postprocessor.
  namespace summary_column
  {
    // clang-format off
    // Each row: name, unit, SI -> file factor, storage, shape, runs,
    // description, and for a standard column its SI values in the summary.
    inline constexpr OutputField stage{
      "stage", "1", 1., Storage::integer, Shape::scalar, every_run,
      "stage of the run: 0 pre-stretch, 1 dead load, 2 voltage",
      [](const StepSummary &s) { return std::vector<double>{double(static_cast<int>(s.stage))}; }};
    inline constexpr OutputField load_factor{
      "load_factor", "1", 1., Storage::real, Shape::scalar, every_run,
      "stage parameter (voltage path parameter in stage 2)",
      [](const StepSummary &s) { return std::vector<double>{s.load_factor}; }};
    inline constexpr OutputField voltage{
      "voltage_kV", "kV", file_units::kV, Storage::real, Shape::per_ring, every_run,
      "voltage of each ring (steps x rings)",
      [](const StepSummary &s) { return s.voltages; }};
    inline constexpr OutputField mass{
      "mass_g", "g", file_units::g, Storage::real, Shape::scalar, every_run,
      "dead-load mass on the disk",
      [](const StepSummary &s) { return std::vector<double>{s.mass}; }};
    inline constexpr OutputField displacement{
      "displacement_mm", "mm", file_units::mm, Storage::real, Shape::scalar, every_run,
      "disk deflection from the frame plane |z(disk) - z(frame)|",
      [](const StepSummary &s) { return std::vector<double>{s.displacement}; }};
    inline constexpr OutputField stroke{
      "stroke_mm", "mm", file_units::mm, Storage::real, Shape::scalar, every_run,
      "displacement minus its zero-voltage value under the same load (NaN before the end of "
      "the load stage)",
      [](const StepSummary &s) { return std::vector<double>{s.stroke}; }};
    inline constexpr OutputField s2_min{
      "s2_min_kPa", "kPa", file_units::kPa, Storage::real, Shape::scalar, every_run,
      "smallest nominal hoop stress s2 anywhere",
      [](const StepSummary &s) { return std::vector<double>{s.s2_min}; }};
    inline constexpr OutputField s2_ring_inner{
      "s2_ring_inner_kPa", "kPa", file_units::kPa, Storage::real, Shape::per_ring, every_run,
      "nominal hoop stress s2 at the inner edge of each ring (steps x rings)",
      [](const StepSummary &s) { return s.s2_ring_inner; }};
    inline constexpr OutputField wrinkled{
      "wrinkled", "1", 1., Storage::integer, Shape::scalar, every_run,
      "1 if the hoop stress is negative somewhere (loss of tension)",
      [](const StepSummary &s) { return std::vector<double>{s.wrinkled ? 1. : 0.}; }};
    inline constexpr OutputField newton_iterations{
      "newton_iterations", "1", 1., Storage::integer, Shape::scalar, every_run,
      "Newton iterations of the converged step",
      [](const StepSummary &s) { return std::vector<double>{double(s.newton_iterations)}; }};

    // The postprocessors' columns (solver/postprocessors.h, solver/state_check.h,
    // the time stepper): reals, one per step, NaN in rows that lack them.
    inline constexpr OutputField wrinkled_zone_inner{
      "wrinkled_zone_inner_mm", "mm", file_units::mm, Storage::real, Shape::scalar, every_run,
      "pre-stretched flat radius lam_pre R where the relaxed law's wrinkled zone starts "
      "(NaN: none, or Wrinkling/Model = check)"};
    inline constexpr OutputField wrinkled_zone_outer{
      "wrinkled_zone_outer_mm", "mm", file_units::mm, Storage::real, Shape::scalar, every_run,
      "pre-stretched flat radius where the wrinkled zone ends"};
    inline constexpr OutputField min_eigenvalue{
      "min_eigenvalue", "N/m", 1., Storage::real, Shape::scalar, every_run,
      "smallest eigenvalue of the tangent with dead load and voltages held (NaN: "
      "Solver/Stability check off)"};
    inline constexpr OutputField stable{
      "stable", "0/1", 1., Storage::real, Shape::scalar, every_run,
      "min_eigenvalue > 0"};
    inline constexpr OutputField max_field{
      "max_field_MV_per_m", "MV/m", file_units::MV_per_m, Storage::real, Shape::scalar, every_run,
      "largest true electric field (NaN: breakdown check off)"};
    inline constexpr OutputField volume{
      "volume_mm3", "mm^3", file_units::mm3, Storage::real, Shape::scalar, every_run,
      "volume enclosed between the frame plane and the deformed membrane with the disk, pi "
      "int r^2 dz"};
    inline constexpr OutputField volume_change{
      "volume_change_mm3", "mm^3", file_units::mm3, Storage::real, Shape::scalar, every_run,
      "enclosed volume minus its value at the end of the load stage (NaN before)"};
    inline constexpr OutputField level_drop{
      "level_drop_mm", "mm", file_units::mm, Storage::real, Shape::scalar, every_run,
      "volume change / cross-section of the Reservoir level tube"};
    inline constexpr OutputField nonphysical{
      "nonphysical", "bits", 1., Storage::real, Shape::scalar, every_run,
      "0: a possible state; 1: the meridian leaves 0 <= r <= b; 2: it crosses itself or the "
      "disk (3: both)"};
    inline constexpr OutputField waveform_time{
      "time_s", "s", 1., Storage::real, Shape::scalar, time_run,
      "time since the voltage waveform started (negative: rest)"};
    inline constexpr OutputField disk_velocity{
      "disk_velocity_mm_per_s", "mm/s", file_units::mm, Storage::real, Shape::scalar, time_run,
      "velocity of the disk dz(A)/dt"};
    inline constexpr OutputField electrical_work{
      "electrical_work_mJ", "mJ", file_units::mJ, Storage::real, Shape::scalar, time_run,
      "electrical work done on the film since the start of the time integration"};
    inline constexpr OutputField stored_energy_change{
      "stored_energy_change_mJ", "mJ", file_units::mJ, Storage::real, Shape::scalar, time_run,
      "change of elastic, weight, water, electrostatic and kinetic energy since then"};
    inline constexpr OutputField dissipated_energy{
      "dissipated_energy_mJ", "mJ", file_units::mJ, Storage::real, Shape::scalar, time_run,
      "energy dissipated by the dashpots since then"};
    // clang-format on
  } // namespace summary_column

  /// The standard /summary columns in the file's order (stage ...
  /// newton_iterations): the rows with summary_values.
  const std::vector<const OutputField *> &standard_summary_columns();

  /// The attributes of each /steps/NNNNNN group, in the file's order: rows of
  /// the standard columns (stage, load_factor, voltage_kV, displacement_mm).
  const std::vector<const OutputField *> &step_attributes();

  /// The /summary attributes: the loss of tension (onset), limit points and
  /// breakdown. Written as attributes (no unit or description in the file).
  namespace summary_attribute
  {
    // clang-format off
    // Each row: name, unit, SI -> file factor, storage, shape, runs, description.
    inline constexpr OutputField onset_found{
      "onset_found", "1", 1., Storage::integer, Shape::scalar, every_run,
      "1 if the hoop stress reached zero along the path"};
    inline constexpr OutputField onset_voltage{
      "onset_voltage_kV", "kV", file_units::kV, Storage::real, Shape::per_ring, every_run,
      "ring voltages where the hoop stress first reaches zero (NaN per ring if never)"};
    inline constexpr OutputField onset_radius{
      "onset_radius_mm", "mm", file_units::mm, Storage::real, Shape::scalar, every_run,
      "pre-stretched flat radius lam_pre R where it does (NaN if never)"};
    inline constexpr OutputField onset_load_factor{
      "onset_load_factor", "1", 1., Storage::real, Shape::scalar, every_run,
      "the stage parameter t there (NaN if never)"};
    inline constexpr OutputField limit_point_voltage{
      "limit_point_voltage_kV", "kV", file_units::kV, Storage::real, Shape::per_ring,
      load_path_runs,
      "ring voltages of each limit point (fold) of the path, k x rings"};
    inline constexpr OutputField limit_point_displacement{
      "limit_point_displacement_mm", "mm", file_units::mm, Storage::real, Shape::scalar,
      load_path_runs,
      "displacement at each limit point (k values)"};
    inline constexpr OutputField breakdown_voltage{
      "breakdown_voltage_kV", "kV", file_units::kV, Storage::real, Shape::per_ring, every_run,
      "ring voltages where the breakdown field is first reached (only if it is)"};
    inline constexpr OutputField breakdown_radius{
      "breakdown_radius_mm", "mm", file_units::mm, Storage::real, Shape::scalar, every_run,
      "pre-stretched flat radius where it is reached"};
    inline constexpr OutputField time_steps{
      "time_steps", "1", 1., Storage::real, Shape::scalar, time_run,
      "accepted steps of the time integration"};
    inline constexpr OutputField time_steps_rejected{
      "time_steps_rejected", "1", 1., Storage::real, Shape::scalar, time_run,
      "steps the error control (or a failed Newton solve) rejected and took again shorter"};
    inline constexpr OutputField time_error_estimate{
      "time_error_estimate_mm", "mm", file_units::mm, Storage::real, Shape::scalar, time_run,
      "estimated global error of the disk's position: the sum of the steps' local error "
      "estimates (NaN for the fixed-step schemes, which have none)"};
    // clang-format on
  } // namespace summary_attribute

  /// An attribute of /summary as the file holds it: a scalar, a 1D array
  /// (rows == 0) or rows x columns doubles; onset_found is the one integer.
  struct SummaryAttribute
  {
    std::string         name;
    std::vector<double> values;
    unsigned int        rows    = 0, columns = 0;
    bool                scalar  = false;
    bool                integer = false;
  };

  /// onset_found, onset_voltage_kV (NaN per ring if none), onset_radius_mm
  /// and onset_load_factor (NaN if none).
  std::vector<SummaryAttribute> onset_attributes(const OnsetRecord &onset, unsigned int n_rings);

  /// limit_point_voltage_kV (k x rings; empty 1D if k = 0) and
  /// limit_point_displacement_mm (k).
  std::vector<SummaryAttribute> limit_point_attributes(const std::vector<LimitPoint> &limits,
                                                       unsigned int n_rings);

  /// breakdown_voltage_kV (one per ring) and breakdown_radius_mm (one value);
  /// none if the breakdown field was not reached.
  std::vector<SummaryAttribute> breakdown_attributes(const OnsetRecord &breakdown);

  /// time_steps, time_steps_rejected and time_error_estimate_mm (@p error_estimate in m).
  std::vector<SummaryAttribute> time_integration_attributes(unsigned int steps,
                                                            unsigned int rejected,
                                                            double       error_estimate);

  /// Every /summary attribute a run of kind @p run (a RunKind) has, for its
  /// onset, limit points and breakdown.
  std::vector<SummaryAttribute> run_attributes(unsigned int run, const OnsetRecord &onset,
                                               const std::vector<LimitPoint> &limits,
                                               const OnsetRecord             &breakdown,
                                               unsigned int                   n_rings);

  /// A dataset of /steps/NNNNNN, or a point array of the ParaView output.
  struct StepField
  {
    OutputField field;
    /// The field in StepFields; null for `ring` (the integer ring index) and
    /// for the fields derived from others (ParaView's true stresses).
    std::vector<double> StepFields::*values;
    /// A field derived from the others, in SI (null if stored).
    std::vector<double> (*derived)(const StepFields &);
    bool in_file;     ///< a /steps dataset
    bool in_paraview; ///< a point array of the ParaView output (film piece)
  };

  /// The /steps fields and ParaView's point arrays, in their order; the
  /// law's internal variables follow in the file (StepFields::internal).
  const std::vector<StepField> &step_fields();

  /// The SI values of @p row in @p fields (the ring index as doubles).
  std::vector<double> step_field_values(const StepField &row, const StepFields &fields);
} // namespace cdea
