// The start-up floor of a deal.II program on this machine: a main() that does
// nothing, linked exactly like the cdea executable (libdeal.ii and its ~200
// libraries are loaded and relocated before main() runs). With --mpi it also
// initialises and finalises MPI through deal.II, as every cdea process did
// before MPI became optional. Used by bench_startup.
#include <deal.II/base/mpi.h>

#include <cstring>

int main(int argc, char **argv)
{
  if (argc > 1 && std::strcmp(argv[1], "--mpi") == 0)
    {
      // The reference to deal.II also keeps the library linked under --as-needed.
      const dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      return 0;
    }
  return 0;
}
