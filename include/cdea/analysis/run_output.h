#pragma once
// The results file of a command's run from start to end, shared by the
// quasi-static run (`cdea run`, `cdea shoot`) and the time run: the file is
// claimed at the start (a run that cannot have it exits 1 and writes
// nothing), every step is appended and, after it, a SIGINT/SIGTERM (which the
// command front turns into a stop request, StopOnSignals) stops the run at
// that step boundary; a stop or an output error ends the run as incomplete
// instead of killing it; at the end the file is written whole and renamed
// into place, or, for a run cut short by a signal or an error, beside an
// older file to <stem>.partial.h5 (doc/usage.md, "What survives what").

#include <cdea/base/run_control.h>
#include <cdea/output/results_file.h>
#include <cdea/solver/load_stepper.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  class RunOutput
  {
  public:
    /// The file at @p path for a run of @p n_rings rings; nullptr (with the
    /// message printed) if it cannot be this run's.
    static std::unique_ptr<RunOutput>
    open(const std::string &path, const std::string &parameters_text, unsigned int n_rings,
         const std::vector<std::pair<std::string, std::string>> &root_attributes);

    ResultsFile &file() { return *results; }

    /// Call after each step is written: throws RunInterrupted once a stop
    /// was asked for.
    static void stop_point();

    /// Runs @p setup, the writes before the first step; if one fails the
    /// output is given up (nothing left behind) and, with the message
    /// printed, false is returned: the command exits 1.
    bool prepare(const std::function<void()> &setup);

    /// Runs @p run; a stop, an output error or another error ends it as
    /// incomplete with the reason (the steps so far stay; after a stop or an
    /// error beside an older file, which stays: ResultsFile::finish()).
    RunResult guard(const std::function<RunResult()> &run);

    /// A signal or an error cut the run short (after guard()).
    bool cut_short() const { return was_cut_short; }

    /// Writes the file, prints where the steps went (and why not all, if
    /// so) and returns the exit code of the run.
    int finish(const RunResult &result);

  private:
    RunOutput() = default;
    std::unique_ptr<ResultsFile> results;
    bool was_cut_short = false; ///< a signal or an error stopped the run

  };
} // namespace cdea
