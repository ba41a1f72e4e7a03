#pragma once
// HDF5 results file of one run (plain HDF5 C API, no deal.II).
//
// Layout (all lengths in mm, stresses in kPa, voltages in kV, fields in MV/m,
// masses in g; every dataset carries string attributes `unit` and `description`):
//
//   /                       attributes: parameters (prm text), code_version,
//                           n_rings (int), and any extra string attributes
//   /summary/               one row per converged step (1D chunked, unlimited;
//                           steps x n_rings where marked [rings])
//       stage (int: 0 pre-stretch, 1 load, 2 voltage), load_factor,
//       voltage_kV [rings], mass_g, displacement_mm, stroke_mm (NaN allowed),
//       s2_min_kPa, s2_ring_inner_kPa [rings], wrinkled (int 0/1),
//       newton_iterations (int), plus extra columns (double, NaN-padded for
//       rows written before the column first appeared)
//     attributes: onset_found (int), onset_voltage_kV (double[n_rings]),
//                 onset_radius_mm (double), onset_load_factor (double: the
//                 stage parameter t there), plus set_summary_attribute() ones
//   /steps/NNNNNN           one group per appended step (6 digits from 000000)
//       R, r, z (mm), theta (rad), lambda1, lambda2, s1, s2 (kPa), E (MV/m),
//       Phi (kV), ring (int), and xi1, xi2 for a viscous film (time runs);
//       1D, one entry per sample point. A step appended with empty fields
//       (R empty) has a /summary row and no group (time runs, doc/time.md)
//     attributes: stage (int), load_factor, voltage_kV (double[n_rings]),
//                 displacement_mm
//
// The file is flushed after every append(), write_onset() and
// set_summary_attribute(), so a process killed between two calls leaves a
// readable file holding every earlier step.

#include <cdea/output/records.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  class ResultsFile
  {
  public:
    /// Creates (or truncates) the file at @p path, creating its parent
    /// directory if missing, and writes the root attributes and the empty
    /// /summary (with onset_found = 0) and /steps groups. Throws
    /// std::runtime_error naming the path and the reason on failure and
    /// std::invalid_argument if n_rings == 0 or an extra attribute name is
    /// empty or reserved (parameters, code_version, n_rings).
    ResultsFile(const std::string &path,
                const std::string &parameters_text,
                unsigned int       n_rings,
                const std::vector<std::pair<std::string, std::string>>
                  &extra_root_attributes = {});

    /// Closes every HDF5 object and the file; never throws.
    ~ResultsFile();

    ResultsFile(const ResultsFile &)            = delete;
    ResultsFile &operator=(const ResultsFile &) = delete;
    ResultsFile(ResultsFile &&) noexcept;
    ResultsFile &operator=(ResultsFile &&) noexcept;

    /// Adds one row to /summary and the group /steps/NNNNNN, then flushes.
    /// @p extra_columns are further /summary datasets (double, written as
    /// given; the name carries the unit, e.g. "volume_mm3"). A column first
    /// seen now is NaN for earlier rows; a known column left out now is NaN
    /// in this row.
    /// Throws std::invalid_argument (before writing anything) if
    /// summary.voltages or summary.s2_ring_inner do not have n_rings entries,
    /// if the field vectors differ in length, or if an extra column name is
    /// empty, contains '/', repeats, or is one of the standard column names;
    /// std::runtime_error if HDF5 fails.
    void append(const StepSummary &summary,
                const StepFields  &fields,
                const std::vector<std::pair<std::string, double>> &extra_columns = {});

    /// Sets the unit and description attributes of an extra /summary column
    /// (by default unit "" and a generic description). May be called before
    /// the column first appears; overwrites earlier settings.
    void describe_column(const std::string &name,
                         const std::string &unit,
                         const std::string &description);

    /// (Over)writes the /summary attributes onset_found, onset_voltage_kV and
    /// onset_radius_mm (NaN when not found), then flushes. Throws
    /// std::invalid_argument if onset.found and onset.voltages does not have
    /// n_rings entries.
    void write_onset(const OnsetRecord &onset);

    /// (Over)writes a 1D double attribute of /summary (written as given, no
    /// unit conversion: put the unit in the name), then flushes.
    void set_summary_attribute(const std::string         &name,
                               const std::vector<double> &values);

    /// The same as a rows x columns attribute (@p values row by row; with
    /// rows == 0, an empty attribute).
    void set_summary_attribute(const std::string         &name,
                               const std::vector<double> &values,
                               unsigned int               rows,
                               unsigned int               columns);

    /// Number of steps appended so far (= rows of /summary).
    unsigned int n_steps() const;
    unsigned int n_rings() const;
    const std::string &path() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };
} // namespace cdea
