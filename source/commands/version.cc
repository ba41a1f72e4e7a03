// `cdea --version`: the version of cdea and of deal.II.

#include <deal.II/base/config.h>

#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>

#include <iostream>

namespace cdea
{
  namespace
  {
    class Version final : public CommandJob
    {
    public:
      int run(Invocation &) override
      {
        std::cout << "cdea " << CDEA_VERSION << " (deal.II " << DEAL_II_PACKAGE_VERSION << ")\n";
        return exit_success;
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> version_job()
  {
    return std::make_unique<Version>();
  }
} // namespace cdea
