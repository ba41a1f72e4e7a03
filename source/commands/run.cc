// `cdea run FILE.prm`: the FE model along the load stages, or in time
// (Time/Enabled), printed and written as it goes.

#include <cdea/analysis/quasi_static_run.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/analysis/time_run.h>
#include <cdea/commands/command.h>
#include <cdea/fe/load_term.h>

#include <iostream>

namespace cdea
{
  namespace
  {
    class Run final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        input = run_input(invocation.parameters, invocation.parameter_text,
                          RunMethod::finite_elements, "run");
      }

      int run(Invocation &) override
      {
        const Parameters &p = input.parameters;
        if (p.time.enabled)
          return run_time(input);
        const auto model = make_fe_model(p, input.scene);
        std::cout << "FE model: " << model->n_elements() << " elements of degree "
                  << p.discretization.polynomial_degree << ", " << model->n_dofs()
                  << " unknowns\n";
        for (const LoadTerm *term : model->load_terms())
          if (const std::string line = term->describe(); !line.empty())
            std::cout << line << '\n';
        return run_quasi_static(*model, input, RunMethod::finite_elements);
      }

    private:
      RunInput input;
    };
  } // namespace

  std::unique_ptr<CommandJob> run_job()
  {
    return std::make_unique<Run>();
  }
} // namespace cdea
