#pragma once
// Runs of the validation scenes with the error estimate of `cdea run`
// (fe/error_estimate.h) and their true errors against a much finer FE run:
// shared by tests/test_error_estimate.cc and benchmarks/bench_error_estimate.cc.

#include <cdea/fe/error_estimate.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/solver/load_stepper.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

namespace cdea_test
{
  /// A quasi-static run through all load stages with its estimate.
  struct EstimatedRun
  {
    cdea::RunResult    result;
    cdea::StepSummary  last;
    cdea::OutputErrors errors;
    double             run_seconds = 0., estimate_seconds = 0.; ///< wall clock
  };

  /// The key outputs of a run as the estimate has them (SI): displacement,
  /// stroke, volume change, s2_min, then the onset voltage of each ring.
  inline std::vector<double> key_values(const EstimatedRun &run)
  {
    std::vector<double> v = {run.last.displacement, run.last.stroke,
                             run.last.columns.get(cdea::summary_column::volume_change),
                             run.last.s2_min};
    for (const double x : run.result.onset.voltages)
      v.push_back(x);
    return v;
  }

  /// Their estimated errors, in the same order (NaN per ring without an onset).
  inline std::vector<double> estimated_errors(const EstimatedRun &run)
  {
    const cdea::OutputErrors &e = run.errors;
    std::vector<double>       v = {e.displacement.total(), e.stroke.total(),
                                   e.volume_change.total(), e.s2_min.total()};
    for (const cdea::ErrorParts &p : e.onset_voltages)
      v.push_back(p.total());
    return v;
  }

  inline const char *key_name(const std::size_t k)
  {
    static const char *names[] = {"displacement", "stroke", "volume change", "s2_min"};
    return k < 4 ? names[k] : "onset voltage";
  }

  /// @p scene on @p d with the run's postprocessors (the enclosed volume),
  /// the onset located to @p onset_tolerance (V), and the estimate
  /// afterwards unless @p with_estimate is false; the run's Newton settings
  /// @p newton (the estimate's own models have the default ones).
  inline EstimatedRun estimated_run(const cdea::Scene &scene, const cdea::FeDiscretization &d,
                                    const double onset_tolerance, const bool with_estimate = true,
                                    const cdea::NewtonSettings &newton = cdea::NewtonSettings())
  {
    using clock = std::chrono::steady_clock;
    cdea::MembraneModel     model(scene, d, newton);
    cdea::SteppingSettings  settings;
    settings.onset_tolerance = onset_tolerance;
    cdea::LoadStepper       stepper(scene, model, settings);
    for (const auto &p : cdea::Postprocessors::plugins())
      if (p.flags & cdea::on_runs)
        {
          cdea::PostprocessorSetup setup = cdea::postprocessor_setup(scene, settings);
          setup.tube_area                = 1.; // m^2: the level drop is not compared
          stepper.add_postprocessor(p.create(setup));
        }
    cdea::RunErrorEstimate estimate(scene, d, onset_tolerance,
                                    [&](const cdea::FeDiscretization &e) {
                                      return std::make_unique<cdea::MembraneModel>(
                                        scene, e, cdea::NewtonSettings());
                                    });
    EstimatedRun out;
    stepper.on_step = [&](const cdea::StepSummary &s) {
      estimate.step(s, model);
      out.last = s;
    };
    stepper.on_onset = [&](const cdea::OnsetRecord &) { estimate.onset(model); };
    const auto t0    = clock::now();
    out.result       = stepper.run();
    const auto t1    = clock::now();
    if (with_estimate)
      out.errors = estimate.estimate();
    const auto t2        = clock::now();
    out.run_seconds      = std::chrono::duration<double>(t1 - t0).count();
    out.estimate_seconds = std::chrono::duration<double>(t2 - t1).count();
    return out;
  }

  /// The reference: p = 8 with 8 elements per ring, the onset to 1e-7 V.
  inline EstimatedRun reference_run(const cdea::Scene &scene)
  {
    cdea::FeDiscretization fine;
    fine.degree            = 8;
    fine.elements_per_ring = 8;
    return estimated_run(scene, fine, 1e-7, false);
  }
} // namespace cdea_test
