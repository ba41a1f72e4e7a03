// `cdea recover FILE.h5`: the results of a killed run, rebuilt from its journal.

#include <cdea/analysis/commands.h>
#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <iostream>

namespace cdea
{
  int recover(const std::string &path)
  {
    if (!file_exists(path + ".journal"))
      {
        std::cerr << "cdea: nothing to recover for " << path << ": there is no journal "
                  << path << ".journal (a run that ends by itself, or stops on SIGINT or "
                  << "SIGTERM, writes its file and removes its journal)\n";
        return exit_input_error;
      }
    OutputLock  lock;
    std::string why;
    if (!lock.acquire(path, why))
      {
        std::cerr << "cdea: cannot recover " << path << ": " << why
                  << " (a running job keeps its own journal)\n";
        return exit_input_error;
      }
    try
      {
        const Recovery r = recover_results(path, true);
        if (r.damaged)
          {
            // Not everything could be read: the journal stays for a closer look.
            std::cerr << "cdea: " << r.message << '\n';
            return exit_not_complete;
          }
        if (r.steps == 0)
          {
            std::cerr << "cdea: nothing to recover for " << path << ": " << r.message << '\n';
            return exit_input_error;
          }
        std::cout << "cdea recover: " << r.message << '\n';
        return exit_success;
      }
    catch (const std::exception &e)
      {
        std::cerr << "cdea: " << e.what() << '\n';
        return exit_not_complete;
      }
  }
} // namespace cdea
