#pragma once
// The program's one MPI wrapper. MPI (OpenMPI's singleton start-up costs about
// 0.35 s per process) is initialised only when it is needed: when the process
// was started by an MPI launcher (mpirun, mpiexec, srun), or when a feature
// asks for it (a Trilinos matrix needs MPI when it is constructed; call
// mpi::ensure_initialized() first). Everything else runs without it. This
// header keeps deal.II's mpi.h out of the files that use it.

namespace cdea
{
  namespace mpi
  {
    /// True if an MPI launcher started this process: OpenMPI's mpirun
    /// (OMPI_COMM_WORLD_SIZE), a PMI or PMIx launcher such as MPICH's hydra or
    /// srun --mpi=pmix (PMI_RANK, PMIX_RANK), or a Slurm job step (srun sets
    /// SLURM_STEP_ID and SLURM_PROCID). Reads the environment only.
    bool launched_by_mpirun();

    /// Initialise MPI (through deal.II, so that Trilinos and PETSc are set up
    /// too) unless that has happened already. It is finalised when the
    /// MpiSession ends, or at the end of the program without one.
    void ensure_initialized();

    /// MPI is initialised and not yet finalised.
    bool initialized();

    /// Rank and size in MPI_COMM_WORLD; 0 and 1 while MPI is not initialised.
    unsigned int rank();
    unsigned int size();
  } // namespace mpi

  /// Kept by main() (and by test and benchmark programs) for the lifetime of
  /// the program: limits deal.II to one thread, initialises MPI if an MPI
  /// launcher started the process, and finalises MPI at its end if anything
  /// initialised it.
  class MpiSession
  {
  public:
    MpiSession(int &argc, char **&argv);
    ~MpiSession();
    MpiSession(const MpiSession &)            = delete;
    MpiSession &operator=(const MpiSession &) = delete;
  };
} // namespace cdea
