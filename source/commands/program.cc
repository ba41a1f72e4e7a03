// The body of the cdea program (commands/program.h): MPI (if an MPI
// launcher started the process) lives as long as this call; everything else
// is the command front (commands/command.h), whose exit code turns 2 if
// standard output or error could not be written.

#include <cdea/base/mpi_session.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/commands/program.h>

namespace cdea
{
  int run_program(int argc, char **argv)
  {
    reopen_closed_standard_streams();
    const MpiSession mpi(argc, argv);
    // A write error on stdout or stderr is an error of the command (exit 2).
    return exit_code_after_output(run_command_line({argv + 1, argv + argc}));
  }
} // namespace cdea
