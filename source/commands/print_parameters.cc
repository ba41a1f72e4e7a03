// `cdea print-parameters [--json]`: every parameter with its default and
// documentation, as a .prm file or as deal.II's JSON.

#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>

#include <iostream>

namespace cdea
{
  namespace
  {
    class PrintParameters final : public CommandJob
    {
    public:
      int run(Invocation &invocation) override
      {
        const bool json = !invocation.arguments.empty(); // the form "--json"
        std::cout << default_parameter_file(json ? ParameterFormat::json : ParameterFormat::prm);
        return exit_success;
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> print_parameters_job()
  {
    return std::make_unique<PrintParameters>();
  }
} // namespace cdea
