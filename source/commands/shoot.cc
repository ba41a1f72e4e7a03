// `cdea shoot FILE.prm`: the shooting model along the same load stages,
// written to <Base name>_shooting.h5.

#include <cdea/analysis/quasi_static_run.h>
#include <cdea/commands/command.h>
#include <cdea/input/solver_settings.h>
#include <cdea/shooting/shooting_model.h>

#include <iostream>

namespace cdea
{
  namespace
  {
    class Shoot final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        input = run_input(invocation.parameters, invocation.parameter_text, RunMethod::shooting,
                          "shoot", &note);
      }

      int run(Invocation &) override
      {
        if (!note.empty())
          std::cout << note << '\n';
        const Parameters       &p = input.parameters;
        shooting::ShootingModel model(input.scene, shooting_options(p));
        std::cout << "Shooting model: Dormand-Prince 5(4), tolerance " << p.shooting.tolerance
                  << '\n';
        return run_quasi_static(model, input, RunMethod::shooting);
      }

    private:
      RunInput    input;
      std::string note; ///< the path followed by load stepping, if that changed it
    };
  } // namespace

  std::unique_ptr<CommandJob> shoot_job()
  {
    return std::make_unique<Shoot>();
  }
} // namespace cdea
