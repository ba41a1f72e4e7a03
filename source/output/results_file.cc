#include <cdea/model/output_fields.h>
#include <cdea/output/journal.h>
#include <cdea/output/results_document.h>
#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace cdea
{
  namespace
  {
    using Clock = std::chrono::steady_clock;

    /// A checkpoint at most every this many seconds, and never taking more
    /// than 1/checkpoint_cost_ratio of the run's time.
    double checkpoint_interval_setting()
    {
      if (const char *env = std::getenv("CDEA_CHECKPOINT_SECONDS"))
        {
          char        *end = nullptr;
          const double v   = std::strtod(env, &end);
          if (end != env && *end == '\0' && v >= 0.)
            return v;
        }
      return 1.;
    }
    constexpr double checkpoint_cost_ratio = 20.;

    std::string journal_of(const std::string &path) { return path + ".journal"; }
    std::string checkpoint_of(const std::string &path) { return sibling_name(path, ".partial"); }

    /// Leftovers of a run that died while writing a file whole.
    void remove_temporaries(const std::string &path)
    {
      remove_file(path + ".tmp");
      remove_file(checkpoint_of(path) + ".tmp");
    }
  } // namespace

  struct ResultsFile::Impl
  {
    std::string                      file_path, directory;
    std::unique_ptr<ResultsDocument> document;
    JournalWriter                    journal;
    OutputLock                       lock;
    DirectoryIdentity                directory_id;
    std::vector<std::string>         notes;
    std::vector<std::string>         created; ///< directories this run created
    std::string                      failure; ///< the first OutputError of the run
    bool                             finished = false;
    Finish                           finish_result;

    double            minimum_interval = 1.;
    Clock::time_point last_checkpoint  = Clock::now();
    double            last_duration    = 0.;
    unsigned int      checkpoints      = 0;
    double            checkpoint_time  = 0.;

    void before_change() const
    {
      if (finished)
        throw std::logic_error("ResultsFile '" + file_path + "': changed after finish()");
      if (!failure.empty())
        throw OutputError(failure);
    }

    /// Runs @p write; an OutputError is remembered (the run must stop).
    template <typename Write>
    void record(const Write &write)
    {
      try
        {
          write();
        }
      catch (const OutputError &e)
        {
          failure = e.what();
          throw;
        }
    }

    void check_directory()
    {
      if (!(DirectoryIdentity::of(directory) == directory_id))
        record([&] {
          throw OutputError("the output directory '" + directory +
                            "' was removed or replaced during the run");
        });
    }

    void checkpoint_if_due()
    {
      const Clock::time_point now = Clock::now();
      const double since = std::chrono::duration<double>(now - last_checkpoint).count();
      if (since < minimum_interval || since < checkpoint_cost_ratio * last_duration)
        return;
      record([&] {
        document->set_root_attribute(run_attribute::run_status.name,
                                     "running: checkpoint after step " +
                                       std::to_string(document->n_steps() - 1) +
                                       " (the run had not ended)");
        const WriteOutcome out = replace_file(checkpoint_of(file_path), document->image(), false);
        if (!out.ok)
          throw OutputError("cannot write the checkpoint: " + out.message);
      });
      last_checkpoint = Clock::now();
      last_duration   = std::chrono::duration<double>(last_checkpoint - now).count();
      checkpoint_time += last_duration;
      ++checkpoints;
    }

    Finish finish(const std::string &status, bool keep_older);

    /// The steps of finish(): the output directory vanished during the run,
    /// so create it again and take the lock (@p owner: it was free; the
    /// target path, elsewhere if not); the whole file did not fit, so write
    /// the leading steps that do (true if some did); nothing was written.
    std::string reclaim_directory(bool &owner, Finish &f);
    bool        write_leading_steps(const std::string &target, const std::string &status,
                                    const WriteOutcome &out, std::size_t full_size, Finish &f);
    void        nothing_written(unsigned int n, Finish &f);
  };

  ResultsFile::ResultsFile(const std::string &path, const std::string &parameters_text,
                           const unsigned int n_rings,
                           const std::vector<std::pair<std::string, std::string>>
                             &extra_root_attributes)
    : impl(std::make_unique<Impl>())
  {
    Impl &d     = *impl;
    d.file_path = path;
    d.directory = parent_directory(path);
    d.document =
      std::make_unique<ResultsDocument>(path, parameters_text, n_rings, extra_root_attributes);
    d.minimum_interval = checkpoint_interval_setting();

    std::vector<std::string> &created = d.created;
    {
      std::string why;
      if (!claim_output(path, d.lock, why, &created))
        throw OutputError("cannot write results file '" + path + "': " + why);
    }
    try
      {
        if (file_exists(journal_of(path)) || file_exists(checkpoint_of(path)))
          {
            try
              {
                const Recovery saved = recover_results(path, false, true);
                d.notes.push_back("an earlier run writing " + path +
                                  " did not finish its file: " + saved.message);
              }
            catch (const OutputError &e)
              {
                throw OutputError("cannot start writing " + path +
                                  ": the journal of an earlier run that did not write all its "
                                  "steps must be saved first, but " + e.what());
              }
          }
        remove_temporaries(path);
        remove_file(checkpoint_of(path));
        d.journal.open(journal_of(path), parameters_text, n_rings, extra_root_attributes);
        d.directory_id = DirectoryIdentity::of(d.directory);
      }
    catch (...)
      {
        if (d.journal.is_open()) // ours, not another process's
          remove_file(journal_of(path));
        d.journal.close();
        d.lock.release();
        remove_created_directories(created);
        d.finished = true;
        throw;
      }
  }

  ResultsFile::~ResultsFile()
  {
    if (impl && !impl->finished)
      impl->finish("ended without finishing: the program left the run early", true);
  }

  ResultsFile::ResultsFile(ResultsFile &&) noexcept            = default;
  ResultsFile &ResultsFile::operator=(ResultsFile &&) noexcept = default;

  void ResultsFile::append(const StepSummary &summary, const StepFields &fields,
                           const std::vector<std::pair<std::string, double>> &extra_columns)
  {
    Impl &d = *impl;
    d.before_change();
    d.document->check_append(summary, fields, extra_columns);
    d.record([&] { d.journal.append(summary, fields, extra_columns); });
    d.document->append(summary, fields, extra_columns);
    d.check_directory();
    d.checkpoint_if_due();
  }

  void ResultsFile::describe_column(const std::string &name, const std::string &unit,
                                    const std::string &description)
  {
    Impl &d = *impl;
    d.before_change();
    d.record([&] { d.journal.describe_column(name, unit, description); });
    d.document->describe_column(name, unit, description);
  }

  void ResultsFile::append(const StepSummary &summary, const StepFields &fields)
  {
    append(summary, fields, {});
  }

  void ResultsFile::write_onset(const OnsetRecord &onset)
  {
    impl->document->check_onset(onset);
    set_summary_attributes(onset_attributes(onset, n_rings()));
  }

  void ResultsFile::set_summary_attributes(const ProductGroup &attributes)
  {
    for (const ProductEntry &e : attributes.attributes)
      set_summary_attribute(file_attribute(e));
  }

  void ResultsFile::set_summary_attribute(const FileAttribute &attribute)
  {
    Impl &d = *impl;
    d.before_change();
    d.document->check_summary_attribute(attribute);
    d.record([&] { d.journal.summary_attribute(attribute); });
    d.document->set_summary_attribute(attribute);
  }

  void ResultsFile::set_summary_attribute(const std::string         &name,
                                          const std::vector<double> &values)
  {
    set_summary_attribute(name, values, 0, 0);
  }

  void ResultsFile::set_summary_attribute(const std::string         &name,
                                          const std::vector<double> &values,
                                          const unsigned int         rows,
                                          const unsigned int         columns)
  {
    Impl &d = *impl;
    d.before_change();
    if (name.empty() || std::size_t(rows) * columns != (rows == 0 ? 0 : values.size()) ||
        (rows == 0 && columns != 0 && !values.empty()))
      throw std::invalid_argument("ResultsFile '" + d.file_path + "': summary attribute '" +
                                  name + "' needs a name and rows x columns values");
    set_summary_attribute(real_attribute(name, values, rows, columns));
  }

  ResultsFile::Finish ResultsFile::finish(const std::string &status, const bool keep_older)
  {
    if (impl->finished)
      return impl->finish_result;
    impl->finished      = true;
    impl->finish_result = impl->finish(status, keep_older);
    return impl->finish_result;
  }

  ResultsFile::Finish ResultsFile::Impl::finish(const std::string &status, const bool keep_older)
  {
    Finish             f;
    const unsigned int n = document->n_steps();
    journal.close();
    try
      {
        document->set_root_attribute(run_attribute::run_status.name, status);
        const bool  vanished = !(DirectoryIdentity::of(directory) == directory_id);
        bool        owner    = true; // the journal and lock at file_path are ours
        std::string target   = vanished ? reclaim_directory(owner, f) : file_path;
        // Cut short: an older file stays, the steps go to the checkpoint's name.
        if (keep_older && !vanished && file_exists(file_path))
          {
            target = checkpoint_of(file_path);
            f.messages.push_back(file_path + " (older results) is kept as it was");
          }
        const std::size_t  full_size = document->image_size();
        const WriteOutcome out       = replace_file(target, document->image(), true);
        if (out.ok)
          {
            f.written       = true;
            f.file          = target;
            f.steps_written = n;
            if (owner)
              {
                // The checkpoint first: a kill between the two leaves a
                // journal, whose recovery removes both, not a lone checkpoint.
                if (target != checkpoint_of(file_path))
                  remove_file(checkpoint_of(file_path));
                remove_file(journal_of(file_path));
              }
            lock.release();
            return f;
          }
        f.messages.push_back("cannot write " + target + ": " + out.message);
        // An older file stays as it is: the steps that fit go beside it.
        const bool older = file_exists(target);
        if (older)
          {
            f.messages.push_back(target + " (older results) is kept as it was");
            remove_file(checkpoint_of(file_path)); // its room for the steps that fit
          }
        const std::string part = older ? checkpoint_of(file_path) : target;
        if (!vanished && out.written > 0 && write_leading_steps(part, status, out, full_size, f))
          return f;
        if (!vanished)
          nothing_written(n, f);
      }
    catch (const std::exception &e)
      {
        f.messages.push_back(std::string("writing the results failed: ") + e.what());
      }
    if (file_exists(checkpoint_of(file_path)))
      f.messages.push_back("the last checkpoint is " + checkpoint_of(file_path));
    lock.release();
    return f;
  }

  std::string ResultsFile::Impl::reclaim_directory(bool &owner, Finish &f)
  {
    // The journal went with the directory (its data only in memory now):
    // write the file into a new directory of the same name.
    lock.release();
    create_directories(directory);
    std::string why;
    owner = lock.acquire(file_path, why);
    f.messages.push_back("the output directory '" + directory +
                         "' vanished during the run; it was created again for the results");
    return owner ? file_path : free_sibling_name(file_path, ".vanished");
  }

  bool ResultsFile::Impl::write_leading_steps(const std::string &target, const std::string &status,
                                              const WriteOutcome &out, const std::size_t full_size,
                                              Finish &f)
  {
    // What fits: the leading steps whose file is no larger than what could
    // be written. The journal keeps all of them.
    const unsigned int n            = document->n_steps();
    const std::string  journal_path = journal_of(file_path);
    if (n >= 1000) // a rebuild takes about a second per 1000 steps: say why it waits
      std::cerr << "cdea: " << target << " does not fit (" << out.message
                << "): finding how many of the " << n << " steps fit..." << std::endl;
    // Image sizes grow about linearly with the steps: estimate from the
    // whole image, then fewer steps until the image fits (each try is one
    // replay of the journal, so this is linear in n).
    unsigned int k = static_cast<unsigned int>(
      std::min<double>(n, double(n) * double(out.written) / double(full_size)));
    for (int attempt = 0; k > 0 && attempt < 8; ++attempt)
      {
        JournalReplay part = replay_journal(journal_path, file_path, k);
        part.document->set_root_attribute(run_attribute::run_status.name,
                                          status + " (only the first " + std::to_string(k) +
                                            " of " + std::to_string(n) +
                                            " steps fit: " + out.message + ")");
        const std::vector<char> image = part.document->image();
        const WriteOutcome      fit =
          image.size() <= out.written ? replace_file(target, image, true) : WriteOutcome();
        if (!fit.ok)
          {
            const double room = double(image.size() <= out.written ? fit.written : out.written);
            k = std::min(k - 1, static_cast<unsigned int>(double(k) * room / double(image.size())));
            continue;
          }
        f.written       = true;
        f.file          = target;
        f.steps_written = k;
        if (target != checkpoint_of(file_path))
          remove_file(checkpoint_of(file_path));
        f.messages.push_back("only the first " + std::to_string(k) + " of " + std::to_string(n) +
                             " steps fit into " + target + "; the journal " + journal_path +
                             " keeps all " + std::to_string(n) + ": make room and run 'cdea " +
                             "recover " + file_path + "'");
        lock.release();
        return true;
      }
    return false;
  }

  void ResultsFile::Impl::nothing_written(const unsigned int n, Finish &f)
  {
    if (n == 0)
      {
        // No step to keep: leave nothing behind, as a run that cannot start does.
        remove_file(journal_of(file_path));
        lock.release();
        remove_created_directories(created);
        f.messages.push_back("no step had been computed: nothing was written");
      }
    else
      f.messages.push_back("nothing could be written; the journal " + journal_of(file_path) +
                           " keeps the " + std::to_string(n) + " steps: make room and run " +
                           "'cdea recover " + file_path + "'");
  }

  void ResultsFile::abandon() noexcept
  {
    Impl &d = *impl;
    if (d.finished)
      return;
    d.finished = true;
    if (d.journal.is_open())
      remove_file(journal_of(d.file_path));
    d.journal.close();
    remove_temporaries(d.file_path);
    remove_file(checkpoint_of(d.file_path));
    d.lock.release();
    remove_created_directories(d.created);
  }

  const std::vector<std::string> &ResultsFile::notes() const { return impl->notes; }
  unsigned int ResultsFile::n_steps() const { return impl->document->n_steps(); }
  unsigned int ResultsFile::n_rings() const { return impl->document->n_rings(); }
  const std::string &ResultsFile::path() const { return impl->file_path; }
  std::string ResultsFile::checkpoint_path() const { return checkpoint_of(impl->file_path); }
  std::string ResultsFile::journal_path() const { return journal_of(impl->file_path); }
  unsigned int ResultsFile::checkpoints() const { return impl->checkpoints; }
  double ResultsFile::checkpoint_seconds() const { return impl->checkpoint_time; }
} // namespace cdea
