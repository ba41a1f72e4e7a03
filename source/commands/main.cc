// cdea: the command-line entry point. MPI (if an MPI launcher started the
// process) lives as long as main(); everything else is the command front
// (commands/command.h).

#include <cdea/base/mpi_session.h>
#include <cdea/commands/command.h>

int main(int argc, char **argv)
{
  const cdea::MpiSession mpi(argc, argv);
  return cdea::run_command_line({argv + 1, argv + argc});
}
