// cdea: the command-line entry point. MPI (if an MPI launcher started the
// process) lives as long as main(); everything else is the command front
// (commands/command.h), whose exit code turns 2 if standard output or error
// could not be written.

#include <cdea/base/mpi_session.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>

int main(int argc, char **argv)
{
  cdea::reopen_closed_standard_streams();
  const cdea::MpiSession mpi(argc, argv);
  // A write error on stdout or stderr is an error of the command (exit 2).
  return cdea::exit_code_after_output(cdea::run_command_line({argv + 1, argv + argc}));
}
