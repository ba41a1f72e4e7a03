#include <cdea/analysis/run_output.h>
#include <cdea/analysis/run_record.h>
#include <cdea/output/safe_files.h>

#include <iomanip>
#include <iostream>

namespace cdea
{
  std::unique_ptr<RunOutput>
  RunOutput::open(const std::string &path, const std::string &parameters_text,
                  const unsigned int n_rings,
                  const std::vector<std::pair<std::string, std::string>> &root_attributes)
  {
    std::unique_ptr<RunOutput> output(new RunOutput());
    try
      {
        output->results =
          std::make_unique<ResultsFile>(path, parameters_text, n_rings, root_attributes);
      }
    catch (const std::exception &e)
      {
        std::cerr << "cdea: " << one_line_message(e) << '\n';
        return nullptr;
      }
    for (const std::string &note : output->results->notes())
      std::cerr << "cdea: " << note << '\n';
    return output;
  }

  void RunOutput::stop_point()
  {
    if (StopOnSignals::requested() != 0)
      throw RunInterrupted(StopOnSignals::requested());
  }

  bool RunOutput::prepare(const std::function<void()> &setup)
  {
    try
      {
        setup();
        return true;
      }
    catch (const std::exception &e)
      {
        results->abandon();
        std::cerr << "cdea: cannot write results file '" << results->path()
                  << "': " << one_line_message(e) << " (nothing was written)\n";
        return false;
      }
  }

  RunResult RunOutput::guard(const std::function<RunResult()> &run)
  {
    RunResult   result;
    std::string stopped; // why the run was cut short, "" if it was not
    try
      {
        result = run();
      }
    catch (const RunInterrupted &e)
      {
        stopped       = e.what();
        was_cut_short = true;
      }
    catch (const OutputError &e)
      {
        stopped = std::string("the results cannot be written: ") + e.what();
      }
    catch (const std::exception &e)
      {
        stopped   = "error: " + one_line_message(e);
        was_cut_short = true;
      }
    if (!stopped.empty())
      {
        result.completed = false;
        result.message   = stopped;
        result.steps     = results->n_steps();
      }
    return result;
  }

  int RunOutput::finish(const RunResult &result)
  {
    const ResultsFile::Finish done =
      results->finish(run_status(result, results->n_steps()), was_cut_short);
    std::cout << "results: " << done.steps_written << " steps in "
              << (done.written ? done.file : std::string("no file")) << " ("
              << results->checkpoints() << " checkpoints, " << std::fixed << std::setprecision(3)
              << results->checkpoint_seconds() << " s)" << std::endl;
    if (!result.completed)
      std::cerr << "cdea: the run stopped early: " << result.message << '\n';
    for (const std::string &message : done.messages)
      std::cerr << "cdea: " << message << '\n';
    if (!result.completed && done.written)
      std::cerr << "cdea: the " << done.steps_written << " converged steps are in " << done.file
                << '\n';
    if (!done.written && results->n_steps() == 0)
      return exit_input_error; // nothing computed and nothing left behind
    const bool all_written = done.written && done.steps_written == results->n_steps();
    return result.completed && all_written ? exit_success : exit_not_complete;
  }
} // namespace cdea
