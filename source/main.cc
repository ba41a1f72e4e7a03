// cdea: command-line entry point.
#include <cdea/app/commands.h>
#include <cdea/app/fit.h>
#include <cdea/app/mpi_session.h>
#include <cdea/app/optimize.h>
#include <cdea/app/sweep.h>
#include <cdea/app/parameters.h>

#include <iostream>
#include <string>

int main(int argc, char **argv)
{
  const cdea::MpiSession mpi(argc, argv);
  const std::vector<std::string> args(argv + 1, argv + argc);
  try
    {
      if (args.empty())
        {
          std::cerr << cdea::usage();
          return cdea::exit_input_error;
        }
      const std::string &command = args[0];
      if (command == "--help" || command == "-h" || command == "help")
        {
          std::cout << cdea::usage();
          return cdea::exit_success;
        }
      if (command == "print-parameters" && args.size() == 1)
        {
          std::cout << cdea::default_parameter_file();
          return cdea::exit_success;
        }
      if (command == "run" && args.size() == 2)
        return cdea::run_fe(args[1]);
      if (command == "shoot" && args.size() == 2)
        return cdea::run_shooting(args[1]);
      if (command == "compare" && args.size() == 2)
        return cdea::compare(args[1]);
      if (command == "sweep" && args.size() == 2)
        return cdea::run_sweep(args[1]);
      if (command == "optimize" && args.size() == 2)
        return cdea::run_optimize(args[1], mpi);
      if (command == "fit" && args.size() == 3)
        return cdea::run_fit(args[1], args[2]);
      std::cerr << "cdea: unknown command or wrong number of arguments: '" << command
                << "'\n\n"
                << cdea::usage();
      return cdea::exit_input_error;
    }
  catch (const std::exception &e)
    {
      std::cerr << "cdea: error: " << e.what() << '\n';
      return cdea::exit_input_error;
    }
}
