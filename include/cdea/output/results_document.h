#pragma once
// The HDF5 layout of a results file, built in memory (see results_file.h for
// the layout and for how it reaches the disk safely), from the table of
// output fields (model/output_fields.h). Plain HDF5 C API, no deal.II.

#include <cdea/model/records.h>
#include <cdea/output/file_attribute.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  /// A /summary column outside the table, by name (the unit in the name),
  /// with its value as written.
  using NamedColumn = std::pair<std::string, double>;

  /// The /summary columns beyond the standard ones of a step: those of
  /// summary.columns (names and file units from the table), then @p extra.
  std::vector<NamedColumn> named_columns(const StepSummary              &summary,
                                         const std::vector<NamedColumn> &extra);

  class ResultsDocument
  {
  public:
    /// The root attributes and the empty /summary (onset_found = 0) and
    /// /steps groups. @p name appears in error messages. Throws
    /// std::invalid_argument if n_rings == 0 or an extra attribute name is
    /// empty or reserved (parameters, code_version, n_rings, run_status).
    ResultsDocument(const std::string &name,
                    const std::string &parameters_text,
                    unsigned int       n_rings,
                    const std::vector<std::pair<std::string, std::string>>
                      &extra_root_attributes = {});
    ~ResultsDocument();
    ResultsDocument(ResultsDocument &&) noexcept;
    ResultsDocument &operator=(ResultsDocument &&) noexcept;

    /// Throws std::invalid_argument if append() would reject these (see
    /// ResultsFile::append()); changes nothing.
    void check_append(const StepSummary &summary, const StepFields &fields,
                      const std::vector<NamedColumn> &extra_columns = {}) const;
    /// The columns of summary.columns are described by their rows of the
    /// table when they first appear.
    void append(const StepSummary &summary, const StepFields &fields,
                const std::vector<NamedColumn> &extra_columns = {});
    void describe_column(const std::string &name, const std::string &unit,
                         const std::string &description);
    void check_onset(const OnsetRecord &onset) const;
    void write_onset(const OnsetRecord &onset);
    /// A double attribute of /summary: 1D if rows == 0, else rows x columns.
    void set_summary_attribute(const std::string &name, const std::vector<double> &values,
                               unsigned int rows, unsigned int columns);
    /// An attribute of /summary as the file holds it; check_...() throws
    /// std::invalid_argument (changing nothing) if set_...() would reject it.
    void set_summary_attribute(const FileAttribute &attribute);
    void check_summary_attribute(const FileAttribute &attribute) const;
    /// A string attribute of the root group (e.g. run_status).
    void set_root_attribute(const std::string &name, const std::string &value);

    unsigned int n_steps() const;
    unsigned int n_rings() const;

    /// The file's bytes as they go to disk, and their number.
    std::vector<char> image() const;
    std::size_t       image_size() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };
} // namespace cdea
