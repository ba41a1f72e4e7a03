#pragma once
// The append-only journal of a results file, "<file>.journal": one record per
// call that changes the file (its start, every step, onset, attributes, column
// descriptions), each written with a single write() before the step is
// printed. A process killed at any moment leaves a journal whose complete
// records replay into the file it was building; a record cut short by the
// kill fails its length or CRC-32 check and is dropped with everything after
// it; damage elsewhere (a record failing its check with more data after it)
// is reported, never taken for the end. Records are in the machine's byte order (the journal is read back on
// the machine that wrote it, by `cdea recover` or the next run).

#include <cdea/model/records.h>
#include <cdea/output/results_document.h>

#include <climits>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  class JournalWriter
  {
  public:
    JournalWriter() = default;
    ~JournalWriter();
    JournalWriter(const JournalWriter &)            = delete;
    JournalWriter &operator=(const JournalWriter &) = delete;

    /// Creates (truncates) @p path, holding an flock on it until close(),
    /// and writes the first record. Throws OutputError naming the path, also
    /// if another process holds the journal's flock.
    void open(const std::string &path, const std::string &parameters_text, unsigned int n_rings,
              const std::vector<std::pair<std::string, std::string>> &extra_root_attributes);

    /// One record each; throw OutputError (with the system's reason) if the
    /// record cannot be written whole, after cutting the journal back to its
    /// last complete record.
    void describe_column(const std::string &name, const std::string &unit,
                         const std::string &description);
    /// A step; before it, the description of each column of
    /// summary.columns not yet recorded.
    void append(const StepSummary &summary, const StepFields &fields,
                const std::vector<NamedColumn> &extra_columns);
    /// A /summary attribute as the file holds it.
    void summary_attribute(const FileAttribute &attribute);

    void        close() noexcept;
    bool        is_open() const { return fd >= 0; }
    std::size_t size() const { return bytes; }

  private:
    int         fd    = -1;
    std::size_t bytes = 0;
    std::string file;
    /// The columns of the table whose description is recorded.
    std::vector<const Quantity *> described;
    void        write_record(unsigned char type, const std::string &payload);
  };

  constexpr std::size_t no_damage = std::size_t(-1);

  /// A results document rebuilt from a journal.
  struct JournalReplay
  {
    std::unique_ptr<ResultsDocument> document; ///< null if not even the first record is complete
    unsigned int steps          = 0; ///< steps in the document
    unsigned int journal_steps  = 0; ///< complete step records in the journal
    std::size_t  dropped_bytes  = 0; ///< of an incomplete last record, or from the damage on
    /// Byte offset of a damaged record with data after it (not a record cut
    /// short at the end), or no_damage. The records from there on are lost.
    std::size_t  damaged_at     = no_damage;
  };

  /// Replays the journal at @p path into a new document named @p name, with
  /// at most @p max_steps steps (the records after the last step kept are
  /// left out too). Only a regular file of at most max_journal_bytes is read.
  /// Throws OutputError if the journal cannot be read, and with
  /// @p stop_on_request RunInterrupted (base/run_control.h) between records
  /// once a stop is requested (`cdea recover` under SIGINT).
  JournalReplay replay_journal(const std::string &path, const std::string &name,
                               unsigned int max_steps = UINT_MAX, bool stop_on_request = false);

  /// The largest journal read back: a run's results are held in memory and
  /// limited to 2 GB (doc/usage.md), and its journal is smaller than them.
  constexpr std::size_t max_journal_bytes = std::size_t(4) << 30;

} // namespace cdea
