// cdea: command-line entry point.
#include <deal.II/base/config.h>

#include <cdea/analysis/commands.h>
#include <cdea/design/fit.h>
#include <cdea/base/mpi_session.h>
#include <cdea/design/optimize.h>
#include <cdea/design/sweep.h>
#include <cdea/input/parameters.h>
#include <cdea/base/run_control.h>

#include <iostream>
#include <string>

namespace
{
  /// Commands that run one job; under an MPI launcher with several ranks each
  /// rank would run all of it into the same file.
  bool is_serial_job(const std::string &command)
  {
    return command == "run" || command == "shoot" || command == "compare" ||
           command == "recover" || command == "fit";
  }
} // namespace

int main(int argc, char **argv)
{
  const cdea::MpiSession mpi(argc, argv);
  const std::vector<std::string> args(argv + 1, argv + argc);
  // Under an MPI launcher only rank 0 speaks (and, but for sweep and optimize, works).
  const bool root = cdea::mpi::rank() == 0;
  cdea::ignore_output_signals();
  try
    {
      if (args.empty())
        {
          if (root)
            std::cerr << cdea::usage();
          return cdea::exit_input_error;
        }
      const std::string &command = args[0];
      // The commands that use several processes under an MPI launcher.
      if (command == "sweep" && args.size() == 2)
        return cdea::run_sweep(args[1]);
      if (command == "optimize" && args.size() == 2)
        return cdea::run_optimize(args[1]);
      if (cdea::mpi::size() > 1 && is_serial_job(command))
        {
          if (root)
            std::cerr << "cdea: '" << command << "' is a serial job, but an MPI launcher "
                      << "started " << cdea::mpi::size() << " processes of it (each would "
                      << "write the same results): run it without mpirun or with -np 1; "
                      << "'cdea sweep' and 'cdea optimize' use several processes\n";
          return cdea::exit_input_error;
        }
      if (!root)
        return cdea::exit_success;
      if (command == "--help" || command == "-h" || command == "help")
        {
          std::cout << cdea::usage();
          return cdea::exit_success;
        }
      if (command == "--version" && args.size() == 1)
        {
          std::cout << "cdea " << CDEA_VERSION << " (deal.II " << DEAL_II_PACKAGE_VERSION
                    << ")\n";
          return cdea::exit_success;
        }
      if (command == "print-parameters" && args.size() == 1)
        {
          std::cout << cdea::default_parameter_file();
          return cdea::exit_success;
        }
      if (command == "print-parameters" && args.size() == 2 && args[1] == "--json")
        {
          std::cout << cdea::default_parameter_file(cdea::ParameterFormat::json);
          return cdea::exit_success;
        }
      if (command == "run" && args.size() == 2)
        return cdea::run_fe(args[1]);
      if (command == "shoot" && args.size() == 2)
        return cdea::run_shooting(args[1]);
      if (command == "compare" && args.size() == 2)
        return cdea::compare(args[1]);
      if (command == "recover" && args.size() == 2)
        return cdea::recover(args[1]);
      if (command == "fit" && args.size() == 3)
        return cdea::run_fit(args[1], args[2]);
      std::cerr << "cdea: unknown command or wrong number of arguments: '" << command
                << "'\n\n"
                << cdea::usage();
      return cdea::exit_input_error;
    }
  catch (const std::exception &e)
    {
      std::cerr << "cdea: error: " << cdea::one_line_message(e) << '\n';
      return cdea::exit_input_error;
    }
}
