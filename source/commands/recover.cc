// `cdea recover FILE.h5`: the results of a killed run that was writing
// FILE.h5, rebuilt from its journal into FILE.h5 (or, if that exists,
// FILE.recovered.h5); a checkpoint without its journal is moved there.
// 0 done; 1 nothing to recover (no journal or checkpoint, a journal without
// a step or that is no regular file) or the run still going; 2 the journal
// or checkpoint is damaged (what could be read is written), the file cannot
// be written, or SIGINT, SIGTERM or SIGHUP stopped it (nothing changed).

#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <iostream>

namespace cdea
{
  namespace
  {
    class Recover final : public CommandJob
    {
    public:
      int run(Invocation &invocation) override
      {
        const std::string &path = invocation.arguments.at(0);
        if (!file_exists(path + ".journal") && !file_exists(sibling_name(path, ".partial")))
          {
            std::cerr << "cdea: nothing to recover for " << path << ": there is no journal "
                      << path << ".journal (a run that ends by itself, or stops on SIGINT or "
                      << "SIGTERM, writes its file and removes its journal)\n";
            return exit_input_error;
          }
        // The journal's run may still be going: it holds the lock.
        OutputLock  lock;
        std::string why;
        if (!lock.acquire(path, why))
          {
            std::cerr << "cdea: cannot recover " << path << ": " << why
                      << " (a running job keeps its own journal)\n";
            return exit_input_error;
          }
        return recover(path);
      }

    private:
      static int recover(const std::string &path)
      {
        try
          {
            const Recovery r = recover_results(path, true, false, true);
            if (r.damaged)
              {
                // Not everything could be read: the journal stays for a closer look.
                std::cerr << "cdea: " << r.message << '\n';
                return exit_not_complete;
              }
            if (r.steps == 0)
              {
                std::cerr << "cdea: nothing to recover for " << path << ": " << r.message
                          << '\n';
                return exit_input_error;
              }
            std::cout << "cdea recover: " << r.message << '\n';
            return exit_success;
          }
        catch (const RunInterrupted &e)
          {
            std::cerr << "cdea: " << e.what() << " while reading the journal of " << path
                      << ": nothing was changed (the journal is kept)\n";
            return exit_not_complete;
          }
        catch (const JournalInUse &e)
          {
            std::cerr << "cdea: cannot recover " << path << ": " << e.what()
                      << " (a running job keeps its own journal)\n";
            return exit_input_error;
          }
        catch (const NotAJournal &e)
          {
            std::cerr << "cdea: nothing to recover for " << path << ": " << e.what() << '\n';
            return exit_input_error;
          }
        catch (const std::exception &e)
          {
            std::cerr << "cdea: " << e.what() << '\n';
            return exit_not_complete;
          }
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> recover_job()
  {
    return std::make_unique<Recover>();
  }
} // namespace cdea
