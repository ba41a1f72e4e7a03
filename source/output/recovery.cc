// recover_results(): the results of a run that did not finish its file,
// rebuilt from its journal (or its last checkpoint where the journal is
// damaged). Nothing is removed that was not recovered whole.
#include <cdea/base/file_reading.h>
#include <cdea/output/hdf5_support.h>
#include <cdea/output/journal.h>
#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>

namespace cdea
{
  namespace
  {
    std::string journal_of(const std::string &path) { return path + ".journal"; }
    std::string checkpoint_of(const std::string &path) { return sibling_name(path, ".partial"); }

    void remove_leftovers(const std::string &path)
    {
      remove_file(journal_of(path));
      remove_file(checkpoint_of(path));
      remove_file(path + ".tmp");
      remove_file(checkpoint_of(path) + ".tmp");
    }

    /// The journal's flock for the time of the recovery; throws if a run
    /// still holds it (that run's journal is live, not left over).
    class JournalClaim
    {
    public:
      explicit JournalClaim(const std::string &journal)
        : fd(-1)
      {
        // Only a regular file is opened (opening a device can act on it);
        // O_NONBLOCK: a FIFO put in its place meanwhile must not wait for a
        // writer; O_NOFOLLOW: a link there is not a journal of cdea's.
        struct stat st = {};
        if (::lstat(journal.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
          throw NotAJournal("the journal " + journal + " is a symbolic link, not a journal "
                            "cdea wrote");
        if (::lstat(journal.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
          throw NotAJournal("the journal " + journal + " is not a regular file (" +
                            (S_ISDIR(st.st_mode) ? "a directory" : "a FIFO, device or socket") +
                            ")");
        fd = ::open(journal.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0 && errno == ELOOP)
          throw NotAJournal("the journal " + journal + " is a symbolic link, not a journal "
                            "cdea wrote");
        if (fd >= 0 && (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)))
          {
            ::close(fd);
            throw NotAJournal("the journal " + journal + " is not a regular file (" +
                              (S_ISDIR(st.st_mode) ? "a directory" : "a FIFO, device or socket") +
                              ")");
          }
        if (fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) != 0)
          {
            ::close(fd);
            throw JournalInUse("a running cdea process is still writing the journal " + journal +
                               " (it holds the journal's lock)");
          }
      }
      ~JournalClaim()
      {
        if (fd >= 0)
          ::close(fd);
      }
      JournalClaim(const JournalClaim &)            = delete;
      JournalClaim &operator=(const JournalClaim &) = delete;

    private:
      int fd;
    };

    /// The checkpoint at @p path read once (a regular file, not through a
    /// link: cdea's own), and the rows of /summary in it (0 if it is
    /// missing or unreadable).
    struct Checkpoint
    {
      std::vector<char> bytes;
      unsigned int      steps = 0;
    };

    unsigned int summary_rows(std::vector<char> &bytes)
    {
      hdf5::ErrorPrintingOff quiet;
      const hdf5::Handle     fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
      // The image in memory: H5Fopen reads it, not the file of that name.
      if (fapl < 0 || H5Pset_fapl_core(fapl, 1 << 16, false) < 0 ||
          H5Pset_file_image(fapl, bytes.data(), bytes.size()) < 0)
        return 0;
      static unsigned long long count = 0;
      const std::string name = "cdea-checkpoint-image-" + std::to_string(++count);
      const hdf5::Handle file(H5Fopen(name.c_str(), H5F_ACC_RDONLY, fapl), H5Fclose);
      if (file < 0)
        return 0;
      const hdf5::Handle set(H5Dopen2(file, "/summary/stage", H5P_DEFAULT), H5Dclose);
      if (set < 0)
        return 0;
      const hdf5::Handle space(H5Dget_space(set), H5Sclose);
      hsize_t            rows = 0;
      if (space < 0 || H5Sget_simple_extent_ndims(space) != 1 ||
          H5Sget_simple_extent_dims(space, &rows, nullptr) != 1)
        return 0;
      return static_cast<unsigned int>(rows);
    }

    Checkpoint read_checkpoint(const std::string &path)
    {
      Checkpoint  c;
      ReadOptions options;
      options.follow_links = false;
      const FileRead read  = read_regular_file(path, max_journal_bytes, options);
      if (!read.ok || read.bytes.empty())
        return c;
      c.bytes.assign(read.bytes.begin(), read.bytes.end());
      c.steps = summary_rows(c.bytes);
      return c;
    }

    std::string where_to(const std::string &path, const bool into_path_if_free)
    {
      return into_path_if_free && !file_exists(path) ? path :
                                                       free_sibling_name(path, ".recovered");
    }
  } // namespace

  namespace
  {
    /// The damaged journal's readable steps, or the checkpoint's if it has
    /// more, written to a free name; the journal and checkpoint stay.
    Recovery save_damaged(const std::string &path, JournalReplay &replay,
                          const bool into_path_if_free)
    {
      Recovery           r;
      const std::string  journal    = journal_of(path);
      const unsigned int steps      = replay.document ? replay.steps : 0;
      const std::string  damage     = "the journal " + journal + " is damaged at byte " +
                                  std::to_string(replay.damaged_at) +
                                  " (a record there fails its check, or starts a second "
                                  "journal, and " + std::to_string(replay.dropped_bytes) +
                                  " bytes from there on cannot be read)";
      r.found                       = true;
      r.damaged                     = true;
      const std::string  checkpoint = checkpoint_of(path);
      Checkpoint         copy       = read_checkpoint(checkpoint);
      const unsigned int saved      = copy.steps;
      const std::string  kept =
        "; the journal" + std::string(file_exists(checkpoint) ? " and " + checkpoint : "") +
        " are kept: remove them once you have what you need";
      if (steps == 0 && saved == 0)
        {
          r.message = damage + "; no step could be read before it" + kept;
          return r;
        }
      r.file = where_to(path, into_path_if_free);
      std::vector<char> bytes;
      if (saved > steps)
        bytes = std::move(copy.bytes);
      else
        {
          replay.document->set_root_attribute(
            "run_status", "rebuilt from the readable start of a damaged journal: the steps "
                          "after the last one here were lost");
          bytes = replay.document->image();
        }
      const WriteOutcome out = replace_file(r.file, bytes, true);
      if (!out.ok)
        throw OutputError("cannot write the recovered results: " + out.message + " (" + damage +
                          "; the journal is kept)");
      r.steps   = std::max(saved, steps);
      r.message = damage + "; the " + std::to_string(r.steps) + " step(s) of the " +
                  (saved > steps ? "last checkpoint " + checkpoint :
                                   std::string("journal before the damage")) +
                  " are in " + r.file + kept;
      return r;
    }

    /// A checkpoint without its journal (the journal was deleted): moved to
    /// a free name if readable, else kept and reported as damage.
    Recovery save_checkpoint(const std::string &path, const bool into_path_if_free,
                             const bool only_if_intact)
    {
      Recovery           r;
      const std::string  checkpoint = checkpoint_of(path);
      const Checkpoint   copy       = read_checkpoint(checkpoint);
      const unsigned int steps      = copy.steps;
      r.found                       = true;
      if (steps == 0)
        {
          r.damaged = true;
          r.message = "there is no journal " + journal_of(path) + ", and the checkpoint " +
                      checkpoint + " cannot be read; it is kept: remove it once you have "
                      "looked at it";
          if (only_if_intact)
            throw OutputError(r.message);
          return r;
        }
      // Copied, not renamed: the bytes checked are the bytes written.
      r.file                 = where_to(path, into_path_if_free);
      const WriteOutcome out = replace_file(r.file, copy.bytes, true);
      if (!out.ok)
        throw OutputError("cannot write the checkpoint's steps: " + out.message +
                          " (the checkpoint " + checkpoint + " is kept)");
      remove_file(checkpoint);
      r.steps   = steps;
      r.message = "there is no journal " + journal_of(path) + "; the checkpoint's " +
                  std::to_string(steps) + " step(s) (the run as it was at its last " +
                  "checkpoint) are in " + r.file;
      return r;
    }
  } // namespace

  Recovery recover_results(const std::string &path, const bool into_path_if_free,
                           const bool only_if_intact, const bool stop_on_request)
  {
    Recovery          r;
    const std::string journal = journal_of(path);
    if (!file_exists(journal))
      {
        if (file_exists(checkpoint_of(path)))
          return save_checkpoint(path, into_path_if_free, only_if_intact);
        r.message = "no journal " + journal + ": nothing to recover";
        return r;
      }
    r.found = true;
    const JournalClaim claim(journal);
    JournalReplay      replay = replay_journal(journal, path, UINT_MAX, stop_on_request);
    const unsigned int steps  = replay.document ? replay.steps : 0;
    if (replay.damaged_at != no_damage)
      {
        if (only_if_intact)
          throw OutputError("the journal " + journal + " is damaged at byte " +
                            std::to_string(replay.damaged_at) + "; run 'cdea recover " + path +
                            "' to save its readable steps, then move the journal away");
        return save_damaged(path, replay, into_path_if_free);
      }
    if (steps == 0)
      {
        remove_leftovers(path);
        r.message = "the journal " + journal + " held no step (removed): nothing to recover";
        return r;
      }
    replay.document->set_root_attribute(
      "run_status", "rebuilt from the journal: the run ended without writing all its steps "
                    "(killed, crashed, or out of disk space) after the last step here");
    r.file                 = where_to(path, into_path_if_free);
    const WriteOutcome out = replace_file(r.file, replay.document->image(), true);
    if (!out.ok)
      throw OutputError("cannot write the recovered results: " + out.message + " (the journal " +
                        journal + " is kept)");
    r.steps = steps;
    remove_leftovers(path);
    r.message = "its " + std::to_string(r.steps) + " step(s) are in " + r.file;
    if (replay.dropped_bytes > 0)
      r.message += " (an incomplete last record of " + std::to_string(replay.dropped_bytes) +
                   " bytes was dropped)";
    return r;
  }
} // namespace cdea
