#include <deal.II/base/mpi.h>

#include <cdea/app/mpi_session.h>

namespace cdea
{
  struct MpiSession::Impl
  {
    Impl(int &argc, char **&argv)
      : mpi(argc, argv, 1)
    {}
    dealii::Utilities::MPI::MPI_InitFinalize mpi;
  };

  MpiSession::MpiSession(int &argc, char **&argv)
    : impl(std::make_unique<Impl>(argc, argv))
  {}

  MpiSession::~MpiSession() = default;

  unsigned int MpiSession::rank() const
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  }

  unsigned int MpiSession::size() const
  {
    return dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  }
} // namespace cdea
