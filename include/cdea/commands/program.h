#pragma once
// The whole of the cdea program as one function: main() is only a call of
// it, so that the tests' fork server (tests/cdea_fork_server.cc) runs the
// same entry point in each of its forks.

namespace cdea
{
  /// What main() does: closed standard streams reopened, the MPI session
  /// (MPI only under an MPI launcher), the command line through the command
  /// front, and the exit code, 2 if standard output or error could not be
  /// written. argv[0] is the program's name.
  int run_program(int argc, char **argv);
} // namespace cdea
