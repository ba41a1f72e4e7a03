#pragma once
// A run's product as it streams: the root attributes come with the sink,
// then a step at a time (a /summary row and, with fields, a /steps group)
// and the /summary attributes set or replaced as the run reports its onset,
// limit points, breakdown and time integration. RunStream is the one
// assembly of that stream from the run's reports (by the rows of
// model/output_fields.h); its sinks are the results file with its journal
// (output/results_file.h) and a run kept in memory (analysis/run_record.h),
// so that the file, a recovered file and the Python result hold the same.

#include <cdea/model/product.h>
#include <cdea/model/records.h>

#include <vector>

namespace cdea
{
  /// What receives a run's product stream.
  class RunSink
  {
  public:
    virtual ~RunSink() = default;
    /// One converged step: its /summary row and, if @p fields has samples,
    /// its /steps group.
    virtual void append(const StepSummary &summary, const StepFields &fields) = 0;
    /// /summary attributes set or replaced (each entry a row of the table
    /// with its SI values).
    virtual void set_summary_attributes(const ProductGroup &attributes) = 0;
  };

  struct OutputErrors;

  class RunStream
  {
  public:
    /// The stream of a run of kind @p run (a RunKind) with @p n_rings rings.
    RunStream(RunSink &sink, unsigned int n_rings, unsigned int run);

    /// The attributes a run starts with: no onset, and for a load path run
    /// no limit points.
    void start();
    void step(const StepSummary &summary, const StepFields &fields);
    void onset(const OnsetRecord &onset);
    /// A further limit point: the attributes list every one so far.
    void limit_point(const LimitPoint &limit);
    void breakdown(const OnsetRecord &breakdown);
    /// The time integration's counts and error estimate (m), at the end of
    /// a time run: set if a step was streamed and the estimate is a number
    /// (the fixed-step schemes have none).
    void time_integration(unsigned int steps, unsigned int rejected, double error_estimate);
    /// Further /summary attributes (the answers' uncertainty,
    /// model/quantities_uncertainty.h), set or replaced.
    void attributes(const ProductGroup &rows) { sink.set_summary_attributes(rows); }

    /// The estimated errors of the final state's key outputs, at the end
    /// of a quasi-static run (model/quantities_error.h).
    void error_estimate(const OutputErrors &errors);

    unsigned int n_steps() const { return steps; }

  private:
    RunSink                &sink;
    const unsigned int      n_rings, run;
    std::vector<LimitPoint> limits;
    unsigned int            steps = 0;
  };
} // namespace cdea
