#include <deal.II/base/multithread_info.h>

#include <cdea/analysis/run_setup.h>
#include <cdea/analysis/session.h>
#include <cdea/analysis/time_run.h>
#include <cdea/analysis/uncertainty_run.h>
#include <cdea/input/solver_settings.h>

#include <memory>
#include <optional>

namespace cdea
{
  RunRecord run_in_memory(const RunInput &input, const RunMethod method)
  {
    const Parameters &p = input.parameters;
    if (p.time.enabled)
      return time_run_in_memory(input);
    RunRecord record;
    record.method       = method;
    record.n_rings      = input.scene.n_rings();
    record.parameters   = input.text;
    record.results_path = results_path(p, method);
    const std::unique_ptr<EquilibriumModel> model = make_model(input, method);
    const std::unique_ptr<RunErrorEstimate> estimate = make_error_estimate(p, input.scene, method);

    LoadStepper stepper(input.scene, *model, stepping_settings(p));
    add_run_postprocessors(stepper, p, input.scene);
    // The run's product stream, as the command's file gets it.
    RunStream stream(record, record.n_rings, load_path_runs);
    stream.start();
    stepper.on_step = [&](const StepSummary &s) {
      if (estimate)
        estimate->step(s, *model);
      stream.step(s, stepper.step_fields());
    };
    stepper.on_onset = [&](const OnsetRecord &onset) {
      if (estimate)
        estimate->onset(*model);
      stream.onset(onset);
    };
    stepper.on_limit_point = [&](const LimitPoint &limit) { stream.limit_point(limit); };
    stepper.on_breakdown   = [&](const OnsetRecord &breakdown) { stream.breakdown(breakdown); };
    // The answers' uncertainty (Uncertainty/Mode) as the command's file has it.
    auto *const                         fe_model = dynamic_cast<MembraneModel *>(model.get());
    std::optional<LinearRunUncertainty> linear;
    if (input.uncertainty.mode == UncertaintyMode::linear && fe_model)
      linear.emplace(input.uncertainty, input.scene).follow(stepper, *fe_model);
    run_keeping_steps(record, [&] {
      const RunResult result = stepper.run();
      if (result.completed && linear)
        stream.attributes(linear->finish(*fe_model));
      else if (result.completed && input.uncertainty.mode == UncertaintyMode::monte_carlo)
        stream.attributes(monte_carlo_run(input, input.uncertainty, false));
      return result;
    });
    // The final state's estimated errors, as `cdea run` writes them (not
    // after a stop or an error: the steps so far are the result).
    if (estimate && !record.steps.empty() && record.result.message.rfind("error: ", 0) != 0)
      stream.error_estimate(estimate->estimate());
    return record;
  }

  void prepare_in_process_runs()
  {
    dealii::MultithreadInfo::set_thread_limit(1);
  }
} // namespace cdea
