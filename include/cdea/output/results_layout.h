#pragma once
// What a results file calls its quantities, in which units, and how the
// solvers' SI values convert to them: the one place shared by the HDF5 writer
// (results_file.cc) and the in-process results of the Python module, so that
// a /summary column or a /steps field has the same name and the same numbers
// in both. The file's units: lengths in mm, stresses in kPa, voltages in kV,
// fields in MV/m, masses in g. The postprocessors' extra columns
// (StepSummary::columns) carry their unit in their name and are already in it.
// No HDF5 and no deal.II here.

#include <cdea/model/records.h>

#include <string>
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
  } // namespace file_units

  /// A standard /summary column (the ones every run has, before the
  /// postprocessors' extra columns).
  struct StandardColumn
  {
    std::string name, unit, description;
    bool        integer;  ///< stored as 32-bit integers (stage, flags, counts)
    bool        per_ring; ///< steps x rings instead of one value per step
  };

  /// The standard /summary columns, in the order of standard_summary_values().
  const std::vector<StandardColumn> &standard_summary_columns();

  /// The values of @p summary for each standard column, in the file's units
  /// (integers exactly as doubles); a per-ring column has one value per ring.
  std::vector<std::vector<double>> standard_summary_values(const StepSummary &summary);

  /// A dataset of /steps/NNNNNN: one field along the meridian.
  struct FieldDataset
  {
    std::string name, unit, description;
    double      factor; ///< from SI to the file's unit
    /// The field in StepFields; null for `ring`, the integer ring index.
    std::vector<double> StepFields::*values;
  };

  /// The /steps datasets, in the file's order of description.
  const std::vector<FieldDataset> &field_datasets();

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

  /// Every value of @p values times @p factor.
  std::vector<double> scaled(const std::vector<double> &values, double factor);
} // namespace cdea
