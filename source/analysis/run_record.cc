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


  void RunRecord::append(const StepSummary &summary, const StepFields &step_fields)
  {
    steps.push_back(summary);
    fields.push_back(step_fields);
  }

  void RunRecord::set_summary_attributes(const ProductGroup &values)
  {
    for (const ProductEntry &e : values.attributes)
      attributes.set(e);
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
      {run_attribute::method.name, to_string(record.method)}};
    root_attributes.insert(root_attributes.end(), record.root_attributes.begin(),
                           record.root_attributes.end());
    ResultsFile file(path, record.parameters, record.n_rings, root_attributes);
    for (std::size_t i = 0; i < record.steps.size(); ++i)
      file.append(record.steps[i], record.fields[i]);
    file.set_summary_attributes(record.attributes);
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
