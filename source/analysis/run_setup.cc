#include <cdea/analysis/run_setup.h>
#include <cdea/input/solver_settings.h>
#include <cdea/shooting/shooting_model.h>
#include <cdea/solver/postprocessors.h>

namespace cdea
{
  std::unique_ptr<MembraneModel> make_fe_model(const Parameters &p, const Scene &scene)
  {
    return make_fe_model(p, scene, fe_discretization(p));
  }

  std::unique_ptr<MembraneModel> make_fe_model(const Parameters &p, const Scene &scene,
                                               const FeDiscretization &discretization)
  {
    auto model = std::make_unique<MembraneModel>(scene, discretization, newton_settings(p));
    model->set_linear_solver(p.solver.linear_solver);
    model->set_relaxed(p.wrinkling.model == WrinklingModel::relaxed);
    model->set_load_terms(p.load_terms.values);
    return model;
  }

  std::unique_ptr<RunErrorEstimate> make_error_estimate(const Parameters &p, const Scene &scene,
                                                        const RunMethod method)
  {
    if (method != RunMethod::finite_elements || !p.discretization.error_estimate)
      return nullptr;
    return std::make_unique<RunErrorEstimate>(
      scene, fe_discretization(p), p.wrinkling.onset_tolerance_V,
      [&p, &scene](const FeDiscretization &d) { return make_fe_model(p, scene, d); });
  }

  std::unique_ptr<EquilibriumModel> make_model(const RunInput &input, const RunMethod method)
  {
    if (method == RunMethod::shooting)
      return std::make_unique<shooting::ShootingModel>(input.scene,
                                                       shooting_options(input.parameters));
    return make_fe_model(input.parameters, input.scene);
  }

  std::vector<TimeStepper::PostprocessorFactory> run_postprocessors(const Parameters &p,
                                                                    const Scene      &scene)
  {
    PostprocessorSetup setup = postprocessor_setup(scene, stepping_settings(p));
    setup.tube_area          = tube_area(p);
    std::vector<TimeStepper::PostprocessorFactory> list;
    for (const Postprocessors::Plugin &plugin : Postprocessors::plugins())
      if (plugin.flags & on_runs)
        list.push_back([create = plugin.create, setup] { return create(setup); });
    return list;
  }

  void add_run_postprocessors(LoadStepper &stepper, const Parameters &p, const Scene &scene)
  {
    for (const auto &make : run_postprocessors(p, scene))
      stepper.add_postprocessor(make());
  }

  void add_run_postprocessors(TimeStepper &stepper, const Parameters &p, const Scene &scene)
  {
    for (const auto &make : run_postprocessors(p, scene))
      stepper.add_postprocessor(make);
  }
} // namespace cdea
