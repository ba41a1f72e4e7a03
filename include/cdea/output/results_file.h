#pragma once
// The HDF5 results file of one run, written so that results survive kills,
// full disks, re-runs and concurrent runs (plain HDF5 C API, no deal.II).
//
// Layout (all lengths in mm, stresses in kPa, voltages in kV, fields in MV/m,
// masses in g; every dataset carries string attributes `unit` and `description`):
//
//   /                       attributes: parameters (prm text), code_version,
//                           n_rings (int), run_status (how the run ended),
//                           and any extra string attributes
//   /summary/               one row per converged step (1D chunked, unlimited;
//                           steps x n_rings where marked [rings])
//       stage (int: 0 pre-stretch, 1 load, 2 voltage), load_factor,
//       voltage_kV [rings], mass_g, displacement_mm, stroke_mm (NaN allowed),
//       s2_min_kPa, s2_ring_inner_kPa [rings], wrinkled (int 0/1),
//       newton_iterations (int), plus the postprocessors' columns and any
//       extra columns (double, NaN-padded for rows written before the column
//       first appeared)
//     attributes: onset_found (int), onset_voltage_kV (double[n_rings]),
//                 onset_radius_mm (double), onset_load_factor (double: the
//                 stage parameter t there), plus set_summary_attribute() ones
//   /steps/NNNNNN           one group per appended step (6 digits from 000000)
//       R, r, z (mm), theta (rad), lambda1, lambda2, s1, s2 (kPa), E (MV/m),
//       Phi (kV), ring (int), and the internal variables the material law
//       writes (xi1, xi2 for the viscous film of a time run);
//       1D, one entry per sample point. A step appended with empty fields
//       (R empty) has a /summary row and no group (time runs, doc/time.md)
//     attributes: stage (int), load_factor, voltage_kV (double[n_rings]),
//                 displacement_mm
//
// How it reaches the disk (doc/usage.md, "What survives what"): the file is
// built in memory. Every call is first appended to the journal
// <file>.journal; at most about once a second (CDEA_CHECKPOINT_SECONDS) the
// whole file is written to <stem>.partial.h5 by write-then-rename; finish()
// writes <file> the same way and removes the journal, the checkpoint and the
// lock <file>.lock. Until then an older <file> is not touched, and a run cut
// short leaves it alone for good (its steps go to <stem>.partial.h5). A killed
// run leaves the journal, which recover_results() turns into a file.

#include <cdea/model/records.h>
#include <cdea/model/run_stream.h>
#include <cdea/output/file_attribute.h>
#include <cdea/output/safe_files.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  /// A sink of a run's product stream (model/run_stream.h).
  class ResultsFile : public RunSink
  {
  public:
    /// Starts the results of a run for @p path: creates the parent directory
    /// if missing, takes the lock, saves the journal of an earlier killed run
    /// onto the same path as a file of its own (see notes()), and starts the
    /// journal. Writes nothing at @p path. Throws OutputError (safe_files.h)
    /// naming the path and the reason if the output cannot be written or
    /// another process writes it (directories it created are removed again),
    /// and std::invalid_argument if n_rings == 0 or an extra attribute name
    /// is empty or reserved (parameters, code_version, n_rings, run_status).
    ResultsFile(const std::string &path,
                const std::string &parameters_text,
                unsigned int       n_rings,
                const std::vector<std::pair<std::string, std::string>>
                  &extra_root_attributes = {});

    /// finish("ended without finishing") if finish() was not called; never
    /// throws.
    ~ResultsFile() override;

    ResultsFile(const ResultsFile &)            = delete;
    ResultsFile &operator=(const ResultsFile &) = delete;
    ResultsFile(ResultsFile &&) noexcept;
    ResultsFile &operator=(ResultsFile &&) noexcept;

    /// Adds one row to /summary and the group /steps/NNNNNN. The columns of
    /// summary.columns become /summary datasets with the names, units,
    /// descriptions and file units of their rows of the table
    /// (model/output_fields.h); @p extra_columns are further ones outside
    /// the table (double, written as given; the name carries the unit, e.g.
    /// "energy_mJ"). A column first seen now is NaN for earlier rows; a
    /// known column left out now is NaN in this row.
    /// Throws std::invalid_argument (before recording anything) if
    /// summary.voltages or summary.s2_ring_inner do not have n_rings entries,
    /// if the field vectors differ in length, or if an extra column name is
    /// empty, contains '/', repeats, or is one of the standard column names.
    /// Throws OutputError if the step cannot be recorded (the journal or a
    /// checkpoint cannot be written) or the output directory has vanished:
    /// the run should stop and finish().
    void append(const StepSummary &summary,
                const StepFields  &fields,
                const std::vector<std::pair<std::string, double>> &extra_columns);
    /// append() without extra columns: a step of the run's stream.
    void append(const StepSummary &summary, const StepFields &fields) override;

    /// The /summary attributes of the stream (each converted by its row;
    /// file_attribute()), recorded in the journal and set in the file.
    void set_summary_attributes(const ProductGroup &attributes) override;
    void set_summary_attribute(const FileAttribute &attribute);

    /// Sets the unit and description attributes of an extra /summary column
    /// (by default unit "" and a generic description). May be called before
    /// the column first appears; overwrites earlier settings.
    void describe_column(const std::string &name,
                         const std::string &unit,
                         const std::string &description);

    /// (Over)writes the /summary attributes onset_found, onset_voltage_kV,
    /// onset_radius_mm and onset_load_factor (onset_attributes(); NaN when
    /// not found). Throws std::invalid_argument if onset.found and
    /// onset.voltages does not have n_rings entries.
    void write_onset(const OnsetRecord &onset);

    /// (Over)writes a 1D double attribute of /summary (written as given, no
    /// unit conversion: put the unit in the name).
    void set_summary_attribute(const std::string         &name,
                               const std::vector<double> &values);

    /// The same as a rows x columns attribute (@p values row by row; with
    /// rows == 0, an empty attribute).
    void set_summary_attribute(const std::string         &name,
                               const std::vector<double> &values,
                               unsigned int               rows,
                               unsigned int               columns);

    /// What finish() did.
    struct Finish
    {
      bool         written = false; ///< a file holds steps_written steps
      std::string  file;            ///< where they are (path, or elsewhere)
      unsigned int steps_written = 0;
      /// Lines for the user: where the results went, what was lost and why.
      std::vector<std::string> messages;
    };

    /// Ends the run's output: sets the root attribute run_status to
    /// @p status and writes the file at path() (written whole, then renamed
    /// onto any older file); with @p keep_older (the run was cut short: a
    /// signal, an error) an older file at path() stays as it is and the
    /// steps go beside it to <stem>.partial.h5. If the output directory vanished it is created
    /// again; if the file does not fit (disk full, file size limit), the
    /// leading steps that fit are written, to path() if nothing is there,
    /// else beside an older file (which stays as it is) to the checkpoint's
    /// name <stem>.partial.h5, and the journal is kept. Then the journal,
    /// checkpoint and lock go. Never throws; calls after the first do
    /// nothing.
    Finish finish(const std::string &status, bool keep_older = false);

    /// Gives the output up before its first step (a write failed): removes
    /// the journal, the lock and the directories this run created, and
    /// writes nothing. Never throws; finish() then does nothing.
    void abandon() noexcept;
    /// Lines for the user from the start (an earlier run's journal saved).
    const std::vector<std::string> &notes() const;

    /// Number of steps appended so far (= rows of /summary).
    unsigned int n_steps() const;
    unsigned int n_rings() const;
    const std::string &path() const;
    std::string checkpoint_path() const;
    std::string journal_path() const;

    /// Checkpoints written so far and the wall time they took (s).
    unsigned int checkpoints() const;
    double       checkpoint_seconds() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };

  /// What recover_results() did.
  struct Recovery
  {
    bool         found = false; ///< there was a journal
    std::string  file;          ///< where the rebuilt file was written ("" if none)
    unsigned int steps = 0;
    std::string  message;       ///< one line for the user
    /// The journal is damaged before its end: what could be read is in file
    /// (if any), and the journal and checkpoint are kept.
    bool damaged = false;
  };

  /// recover_results(): a run still writes the journal (holds its flock).
  class JournalInUse : public OutputError
  {
  public:
    using OutputError::OutputError;
  };

  /// recover_results(): the journal's name is taken by something other than
  /// a regular file (a directory, a FIFO, a device).
  class NotAJournal : public OutputError
  {
  public:
    using OutputError::OutputError;
  };

  /// Rebuilds the results of a killed run that was writing @p path from its
  /// journal. The file goes to @p path if nothing is there and
  /// @p into_path_if_free, else to a free "<stem>.recovered[-N].h5" beside
  /// it; the journal and checkpoint are then removed. A journal damaged
  /// before its end (not a last record cut short) is never removed: the more
  /// steps of its readable part and the checkpoint are written, or, with
  /// @p only_if_intact, nothing is done and OutputError says where the damage
  /// is. A checkpoint without a journal is moved to the same place if it
  /// can be read (else reported as damage and kept). The caller must hold
  /// the lock of @p path. Throws JournalInUse if the journal is still being
  /// written (its flock is held), NotAJournal if it is not a regular file,
  /// OutputError if it cannot be read or the file cannot be written, and
  /// with @p stop_on_request RunInterrupted once a stop is requested during
  /// the replay (source/output/recovery.cc).
  Recovery recover_results(const std::string &path, bool into_path_if_free,
                           bool only_if_intact = false, bool stop_on_request = false);
} // namespace cdea
