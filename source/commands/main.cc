// cdea: the command-line entry point; the program is run_program()
// (commands/program.h), which the tests' fork server calls too.

#include <cdea/commands/program.h>

int main(int argc, char **argv)
{
  return cdea::run_program(argc, argv);
}
