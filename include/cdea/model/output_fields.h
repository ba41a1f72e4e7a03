#pragma once
// The table of quantities of a run (`cdea run`, `cdea shoot`, a time run):
// every /summary column, the /summary attributes and the /steps fields, one
// row (model/quantity.h) each with the name, the unit and its conversion
// from SI, the description, the storage, the shape per step, and which runs
// write it. The results document (HDF5), the journal, the ParaView writer
// and the Python module take names, units, conversions and values from here;
// a material law adds the /steps fields of its internal variables by
// declaring them (MembraneLaw::internal_variables()). No HDF5, no deal.II.
//
// A new /summary column is one row in namespace summary_column and the
// postprocessor that sets it, summary.columns.set(summary_column::x, SI
// value); readers take it by the same handle, summary.columns.get(...).
// The file's units: lengths in mm, stresses in kPa, voltages in kV, fields in
// MV/m, masses in g, volumes in mm^3, energies in mJ.

#include <cdea/model/product.h>
#include <cdea/model/quantity.h>
#include <cdea/model/records.h>

#include <vector>

namespace cdea
{
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

  namespace shape
  {
    inline constexpr Shape step{{"step"}};              ///< a /summary column
    inline constexpr Shape step_ring{{"step", "ring"}}; ///< a /summary column per ring
  } // namespace shape

  /// A /summary column: a dataset with a value (or one per ring) per step.
  constexpr Quantity summary_column_row(const char *name, const Unit &unit, const Storage storage,
                                        const Shape &shape, const unsigned int runs,
                                        const char *description,
                                        std::vector<double> (*values)(const StepSummary &) = nullptr)
  {
    Quantity q{name, unit, description, shape, storage};
    q.runs           = runs;
    q.summary_values = values;
    return q;
  }

  /// A /summary attribute: @p dims its dimensions, 0: one value.
  constexpr Quantity summary_attribute_row(const char *name, const Unit &unit,
                                           const Storage storage, const Shape &shape,
                                           const unsigned int runs, const char *description)
  {
    Quantity q{name, unit, description, shape, storage, Place::attribute};
    q.runs = runs;
    return q;
  }

  /// Every value of @p values (SI) in @p unit.
  std::vector<double> in_unit(const std::vector<double> &values, const Unit &unit);

  /// The /summary columns, one row each. The standard ones come first, in
  /// the file's order; every run has them and they are StepSummary members.
  /// The postprocessors' columns follow, each set by its postprocessor.
  namespace summary_column
  {
    // clang-format off
    // Each row: name, unit, storage, shape, runs, description, and for a
    // standard column its SI values in the summary.
    inline constexpr Quantity stage = summary_column_row(
      "stage", units::one, Storage::integer, shape::step, every_run,
      "stage of the run: 0 pre-stretch, 1 dead load, 2 voltage",
      [](const StepSummary &s) { return std::vector<double>{double(static_cast<int>(s.stage))}; });
    inline constexpr Quantity load_factor = summary_column_row(
      "load_factor", units::one, Storage::real, shape::step, every_run,
      "stage parameter (voltage path parameter in stage 2)",
      [](const StepSummary &s) { return std::vector<double>{s.load_factor}; });
    inline constexpr Quantity voltage = summary_column_row(
      "voltage_kV", units::kV, Storage::real, shape::step_ring, every_run,
      "voltage of each ring (steps x rings)",
      [](const StepSummary &s) { return s.voltages; });
    inline constexpr Quantity mass = summary_column_row(
      "mass_g", units::g, Storage::real, shape::step, every_run,
      "dead-load mass on the disk",
      [](const StepSummary &s) { return std::vector<double>{s.mass}; });
    inline constexpr Quantity displacement = summary_column_row(
      "displacement_mm", units::mm, Storage::real, shape::step, every_run,
      "disk deflection from the frame plane |z(disk) - z(frame)|",
      [](const StepSummary &s) { return std::vector<double>{s.displacement}; });
    inline constexpr Quantity stroke = summary_column_row(
      "stroke_mm", units::mm, Storage::real, shape::step, every_run,
      "displacement minus its zero-voltage value under the same load (NaN before the end of "
      "the load stage)",
      [](const StepSummary &s) { return std::vector<double>{s.stroke}; });
    inline constexpr Quantity s2_min = summary_column_row(
      "s2_min_kPa", units::kPa, Storage::real, shape::step, every_run,
      "smallest nominal hoop stress s2 anywhere",
      [](const StepSummary &s) { return std::vector<double>{s.s2_min}; });
    inline constexpr Quantity s2_ring_inner = summary_column_row(
      "s2_ring_inner_kPa", units::kPa, Storage::real, shape::step_ring, every_run,
      "nominal hoop stress s2 at the inner edge of each ring (steps x rings)",
      [](const StepSummary &s) { return s.s2_ring_inner; });
    inline constexpr Quantity wrinkled = summary_column_row(
      "wrinkled", units::one, Storage::integer, shape::step, every_run,
      "1 if the hoop stress is negative somewhere (loss of tension)",
      [](const StepSummary &s) { return std::vector<double>{s.wrinkled ? 1. : 0.}; });
    inline constexpr Quantity newton_iterations = summary_column_row(
      "newton_iterations", units::one, Storage::integer, shape::step, every_run,
      "Newton iterations of the converged step",
      [](const StepSummary &s) { return std::vector<double>{double(s.newton_iterations)}; });

    // The postprocessors' columns (solver/postprocessors.h, solver/state_check.h,
    // the time stepper): reals, one per step, NaN in rows that lack them.
    inline constexpr Quantity wrinkled_zone_inner = summary_column_row(
      "wrinkled_zone_inner_mm", units::mm, Storage::real, shape::step, every_run,
      "pre-stretched flat radius lam_pre R where the relaxed law's wrinkled zone starts "
      "(NaN: none, or Wrinkling/Model = check)");
    inline constexpr Quantity wrinkled_zone_outer = summary_column_row(
      "wrinkled_zone_outer_mm", units::mm, Storage::real, shape::step, every_run,
      "pre-stretched flat radius where the wrinkled zone ends");
    inline constexpr Quantity min_eigenvalue = summary_column_row(
      "min_eigenvalue", units::N_per_m, Storage::real, shape::step, every_run,
      "smallest eigenvalue of the tangent with dead load and voltages held (NaN: "
      "Solver/Stability check off)");
    inline constexpr Quantity stable = summary_column_row(
      "stable", units::zero_one, Storage::real, shape::step, every_run,
      "min_eigenvalue > 0");
    inline constexpr Quantity max_field = summary_column_row(
      "max_field_MV_per_m", units::MV_per_m, Storage::real, shape::step, every_run,
      "largest true electric field (NaN: breakdown check off)");
    inline constexpr Quantity volume = summary_column_row(
      "volume_mm3", units::mm3, Storage::real, shape::step, every_run,
      "volume enclosed between the frame plane and the deformed membrane with the disk, pi "
      "int r^2 dz");
    inline constexpr Quantity volume_change = summary_column_row(
      "volume_change_mm3", units::mm3, Storage::real, shape::step, every_run,
      "enclosed volume minus its value at the end of the load stage (NaN before)");
    inline constexpr Quantity level_drop = summary_column_row(
      "level_drop_mm", units::mm, Storage::real, shape::step, every_run,
      "volume change / cross-section of the Reservoir level tube");
    inline constexpr Quantity nonphysical = summary_column_row(
      "nonphysical", units::bits, Storage::real, shape::step, every_run,
      "0: a possible state; 1: the meridian leaves 0 <= r <= b; 2: it crosses itself or the "
      "disk (3: both)");
    inline constexpr Quantity waveform_time = summary_column_row(
      "time_s", units::s, Storage::real, shape::step, time_run,
      "time since the voltage waveform started (negative: rest)");
    inline constexpr Quantity disk_velocity = summary_column_row(
      "disk_velocity_mm_per_s", units::mm_per_s, Storage::real, shape::step, time_run,
      "velocity of the disk dz(A)/dt");
    inline constexpr Quantity electrical_work = summary_column_row(
      "electrical_work_mJ", units::mJ, Storage::real, shape::step, time_run,
      "electrical work done on the film since the start of the time integration");
    inline constexpr Quantity stored_energy_change = summary_column_row(
      "stored_energy_change_mJ", units::mJ, Storage::real, shape::step, time_run,
      "change of elastic, weight, water, electrostatic and kinetic energy since then");
    inline constexpr Quantity dissipated_energy = summary_column_row(
      "dissipated_energy_mJ", units::mJ, Storage::real, shape::step, time_run,
      "energy dissipated by the dashpots since then");
    // clang-format on
  } // namespace summary_column

  /// The standard /summary columns in the file's order (stage ...
  /// newton_iterations): the rows with summary_values.
  const std::vector<const Quantity *> &standard_summary_columns();

  /// The attributes of each /steps/NNNNNN group, in the file's order: rows of
  /// the standard columns (stage, load_factor, voltage_kV, displacement_mm).
  const std::vector<const Quantity *> &step_attributes();

  /// The root attributes of a run's results file (besides parameters and
  /// code_version, model/quantities_common.h): strings but n_rings.
  namespace run_attribute
  {
    // clang-format off
    inline constexpr Quantity n_rings = summary_attribute_row(
      "n_rings", units::one, Storage::integer, shape::scalar, every_run,
      "electrode rings of the actuator");
    inline constexpr Quantity method = summary_attribute_row(
      "method", units::none, Storage::text, shape::scalar, every_run,
      "the model: finite elements, shooting, or finite elements in time");
    inline constexpr Quantity run_status = summary_attribute_row(
      "run_status", units::none, Storage::text, shape::scalar, every_run,
      "complete, or how and after which step the run stopped (running: a checkpoint)");
    inline constexpr Quantity material_model = summary_attribute_row(
      "material_model", units::none, Storage::text, shape::scalar, time_run,
      "Material/Model of the time run");
    inline constexpr Quantity waveform = summary_attribute_row(
      "waveform", units::none, Storage::text, shape::scalar, time_run, "Time/Waveform");
    inline constexpr Quantity time_scheme = summary_attribute_row(
      "time_scheme", units::none, Storage::text, shape::scalar, time_run, "Time/Scheme");
    inline constexpr Quantity time_step_control = summary_attribute_row(
      "time_step_control", units::none, Storage::text, shape::scalar, time_run,
      "how an ESDIRK run sizes its steps: by its error estimate or fixed");
    // clang-format on
  } // namespace run_attribute

  /// The /summary attributes: the loss of tension (onset), limit points and
  /// breakdown. Written as attributes (no unit or description in the file).
  namespace summary_attribute
  {
    // clang-format off
    // Each row: name, unit, storage, shape, runs, description.
    inline constexpr Quantity onset_found = summary_attribute_row(
      "onset_found", units::one, Storage::integer, shape::scalar, every_run,
      "1 if the hoop stress reached zero along the path");
    inline constexpr Quantity onset_voltage = summary_attribute_row(
      "onset_voltage_kV", units::kV, Storage::real, shape::ring, every_run,
      "ring voltages where the hoop stress first reaches zero (NaN per ring if never)");
    inline constexpr Quantity onset_radius = summary_attribute_row(
      "onset_radius_mm", units::mm, Storage::real, shape::scalar, every_run,
      "pre-stretched flat radius lam_pre R where it does (NaN if never)");
    inline constexpr Quantity onset_load_factor = summary_attribute_row(
      "onset_load_factor", units::one, Storage::real, shape::scalar, every_run,
      "the stage parameter t there (NaN if never)");
    inline constexpr Quantity limit_point_voltage = summary_attribute_row(
      "limit_point_voltage_kV", units::kV, Storage::real, shape::limit_ring,
      load_path_runs,
      "ring voltages of each limit point (fold) of the path, k x rings");
    inline constexpr Quantity limit_point_displacement = summary_attribute_row(
      "limit_point_displacement_mm", units::mm, Storage::real, shape::limit,
      load_path_runs,
      "displacement at each limit point (k values)");
    inline constexpr Quantity breakdown_voltage = summary_attribute_row(
      "breakdown_voltage_kV", units::kV, Storage::real, shape::ring, every_run,
      "ring voltages where the breakdown field is first reached (only if it is)");
    inline constexpr Quantity breakdown_radius = summary_attribute_row(
      "breakdown_radius_mm", units::mm, Storage::real, shape::scalar, every_run,
      "pre-stretched flat radius where it is reached");
    inline constexpr Quantity time_steps = summary_attribute_row(
      "time_steps", units::one, Storage::real, shape::scalar, time_run,
      "accepted steps of the time integration");
    inline constexpr Quantity time_steps_rejected = summary_attribute_row(
      "time_steps_rejected", units::one, Storage::real, shape::scalar, time_run,
      "steps the error control (or a failed Newton solve) rejected and took again shorter");
    inline constexpr Quantity time_error_estimate = summary_attribute_row(
      "time_error_estimate_mm", units::mm, Storage::real, shape::scalar, time_run,
      "estimated global error of the disk's position: the sum of the steps' local error "
      "estimates (NaN for the fixed-step schemes, which have none)");
    // clang-format on
  } // namespace summary_attribute

  /// The /summary attributes of what a run reports, each a row of
  /// namespace summary_attribute with its SI values: the one assembly of
  /// them, which the run's product stream (model/run_stream.h) sends to the
  /// results file, its journal and a run kept in memory.
  /// onset_found, onset_voltage_kV (NaN per ring if none), onset_radius_mm
  /// and onset_load_factor (NaN if none).
  ProductGroup onset_attributes(const OnsetRecord &onset, unsigned int n_rings);

  /// limit_point_voltage_kV (k x rings) and limit_point_displacement_mm (k).
  ProductGroup limit_point_attributes(const std::vector<LimitPoint> &limits, unsigned int n_rings);

  /// breakdown_voltage_kV (one per ring) and breakdown_radius_mm (one value);
  /// none if the breakdown field was not reached.
  ProductGroup breakdown_attributes(const OnsetRecord &breakdown);

  /// time_steps, time_steps_rejected and time_error_estimate_mm (@p error_estimate in m).
  ProductGroup time_integration_attributes(unsigned int steps, unsigned int rejected,
                                           double error_estimate);

  /// A dataset of /steps/NNNNNN, or a point array of the ParaView output.
  struct StepField
  {
    Quantity field;
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
