#include <cdea/model/output_fields.h>
#include <cdea/model/quantities_error.h>
#include <cdea/model/run_stream.h>

#include <cmath>

namespace cdea
{
  RunStream::RunStream(RunSink &sink, const unsigned int n_rings, const unsigned int run)
    : sink(sink)
    , n_rings(n_rings)
    , run(run)
  {}

  void RunStream::start()
  {
    sink.set_summary_attributes(onset_attributes(OnsetRecord(), n_rings));
    if (run & summary_attribute::limit_point_voltage.runs)
      sink.set_summary_attributes(limit_point_attributes(limits, n_rings));
  }

  void RunStream::step(const StepSummary &summary, const StepFields &fields)
  {
    sink.append(summary, fields);
    ++steps;
  }

  void RunStream::onset(const OnsetRecord &onset)
  {
    sink.set_summary_attributes(onset_attributes(onset, n_rings));
  }

  void RunStream::limit_point(const LimitPoint &limit)
  {
    limits.push_back(limit);
    sink.set_summary_attributes(limit_point_attributes(limits, n_rings));
  }

  void RunStream::breakdown(const OnsetRecord &breakdown)
  {
    sink.set_summary_attributes(breakdown_attributes(breakdown));
  }

  void RunStream::time_integration(const unsigned int steps_taken, const unsigned int rejected,
                                   const double error_estimate)
  {
    if (steps > 0 && !std::isnan(error_estimate))
      sink.set_summary_attributes(
        time_integration_attributes(steps_taken, rejected, error_estimate));
  }

  void RunStream::error_estimate(const OutputErrors &errors)
  {
    sink.set_summary_attributes(error_estimate_attributes(errors, n_rings));
  }
} // namespace cdea
