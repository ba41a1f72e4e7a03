#include <cdea/app/commands.h>
#include <cdea/app/sweep.h>

#include <iostream>

namespace cdea
{
  int run_sweep(const std::string &)
  {
    std::cerr << "cdea: sweep is not available in this build yet\n";
    return exit_input_error;
  }
} // namespace cdea
