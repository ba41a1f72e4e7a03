#pragma once
// Scenes and run helpers shared by the test programs.

#include <cdea/model/scene.h>
#include <cdea/solver/load_stepper.h>

#include <stdexcept>
#include <vector>

namespace cdea_test
{
  using cdea::paper_scene;

  /// Run all stages; returns the summary of the last converged step.
  inline cdea::StepSummary run_to_end(cdea::EquilibriumModel &model, const cdea::Scene &scene,
                                      cdea::RunResult *result = nullptr)
  {
    cdea::SteppingSettings settings;
    cdea::LoadStepper      stepper(scene, model, settings);
    cdea::StepSummary      last;
    stepper.on_step = [&](const cdea::StepSummary &s) { last = s; };
    const cdea::RunResult r = stepper.run();
    if (result)
      *result = r;
    else if (!r.completed)
      throw std::runtime_error("run did not complete: " + r.message);
    return last;
  }

  /// A run's result and every converged step.
  struct RunTrace
  {
    cdea::RunResult                result;
    std::vector<cdea::StepSummary> steps;
  };

  /// Run all stages with @p settings, keeping every step.
  inline RunTrace trace_run(cdea::EquilibriumModel &model, const cdea::Scene &scene,
                            const cdea::SteppingSettings &settings)
  {
    RunTrace          trace;
    cdea::LoadStepper stepper(scene, model, settings);
    stepper.on_step = [&](const cdea::StepSummary &s) { trace.steps.push_back(s); };
    trace.result    = stepper.run();
    return trace;
  }
} // namespace cdea_test
