#include <cdea/analysis/run_record.h>
#include <cdea/output/results_file.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cdea
{
  std::string to_string(const RunStatus status)
  {
    return status == RunStatus::complete ? "complete" : "stopped";
  }

  std::string run_status(const RunResult &result, const std::size_t n_steps)
  {
    if (result.completed)
      return to_string(RunStatus::complete);
    return to_string(RunStatus::stopped) + " after step " + std::to_string(int(n_steps) - 1) +
           ": " + result.message;
  }


  void write_summary_attributes(ResultsFile &file, const std::vector<SummaryAttribute> &attributes)
  {
    for (const SummaryAttribute &a : attributes)
      if (a.rows == 0)
        file.set_summary_attribute(a.name, a.values);
      else
        file.set_summary_attribute(a.name, a.values, a.rows, a.columns);
  }

  void run_keeping_steps(RunRecord &record, const std::function<RunResult()> &run)
  {
    const auto start = std::chrono::steady_clock::now();
    try
      {
        record.result = run();
      }
    catch (const std::exception &e)
      {
        // The steps so far stay; the run says why it ended.
        record.result.completed = false;
        record.result.message   = std::string("error: ") + e.what();
        record.result.steps     = static_cast<unsigned int>(record.steps.size());
      }
    record.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  void write_run(const RunRecord &record, const std::string &path)
  {
    std::vector<std::pair<std::string, std::string>> root_attributes = {
      {"method", to_string(record.method)}};
    root_attributes.insert(root_attributes.end(), record.root_attributes.begin(),
                           record.root_attributes.end());
    ResultsFile file(path, record.parameters, record.n_rings, root_attributes);
    for (std::size_t i = 0; i < record.steps.size(); ++i)
      file.append(record.steps[i], record.fields[i]);
    file.write_onset(record.result.onset);
    if (!record.time_run)
      write_summary_attributes(file,
                               limit_point_attributes(record.result.limit_points, record.n_rings));
    write_summary_attributes(file, breakdown_attributes(record.result.breakdown));
    if (record.time_run && !record.steps.empty() && !std::isnan(record.result.error_estimate))
      write_summary_attributes(file, time_integration_attributes(record.result.time_steps,
                                                                 record.result.rejected_steps,
                                                                 record.result.error_estimate));
    const ResultsFile::Finish done = file.finish(run_status(record.result, record.steps.size()));
    if (!done.written || done.steps_written != record.steps.size())
      {
        std::string why = "cannot write '" + path + "'";
        for (const std::string &m : done.messages)
          why += "; " + m;
        throw std::runtime_error(why);
      }
  }
} // namespace cdea
