#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <cdea/app/mpi_session.h>

#include <cstdlib>
#include <memory>

namespace cdea
{
  namespace
  {
    /// What ensure_initialized() needs: main's arguments (MPI and PETSc may
    /// read them) and the deal.II object that owns MPI once it is started.
    struct State
    {
      int    argc = 1;
      char   program_name[5] = "cdea";
      char  *default_argv[2] = {program_name, nullptr};
      char **argv            = default_argv;
      std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
    };

    State &state()
    {
      static State s;
      return s;
    }

    bool has_variable(const char *name)
    {
      const char *value = std::getenv(name);
      return value != nullptr && *value != '\0';
    }
  } // namespace

  namespace mpi
  {
    bool launched_by_mpirun()
    {
      return has_variable("OMPI_COMM_WORLD_SIZE") || has_variable("PMIX_RANK") ||
             has_variable("PMI_RANK") ||
             (has_variable("SLURM_STEP_ID") && has_variable("SLURM_PROCID"));
    }

    void ensure_initialized()
    {
      State &s = state();
      if (!s.mpi && !dealii::Utilities::MPI::job_supports_mpi())
        s.mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(s.argc, s.argv, 1);
    }

    bool initialized()
    {
      return dealii::Utilities::MPI::job_supports_mpi();
    }

    unsigned int rank()
    {
      return initialized() ? dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) : 0;
    }

    unsigned int size()
    {
      return initialized() ? dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) : 1;
    }
  } // namespace mpi

  MpiSession::MpiSession(int &argc, char **&argv)
  {
    // One thread, as the MPI_InitFinalize of earlier versions set it: the 1D
    // model gains nothing from more, and runs stay reproducible.
    dealii::MultithreadInfo::set_thread_limit(1);
    state().argc = argc;
    state().argv = argv;
    if (mpi::launched_by_mpirun())
      mpi::ensure_initialized();
  }

  MpiSession::~MpiSession()
  {
    state().mpi.reset();
  }
} // namespace cdea
