#pragma once
// The program's one MPI wrapper. MPI (OpenMPI's singleton start-up costs about
// 0.35 s per process) is initialised only when it is needed: when the process
// was started by an MPI launcher (mpirun, mpiexec, srun), or when a feature
// asks for it (a Trilinos matrix needs MPI when it is constructed; call
// mpi::ensure_initialized() first). Everything else runs without it. This
// header keeps deal.II's mpi.h out of the files that use it.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

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

    /// The items (of @p n, by index) that rank @p rank of @p size works on:
    /// dealt round-robin, item i to rank i mod size.
    std::vector<std::size_t> items_of_rank(std::size_t n, unsigned int rank, unsigned int size);

    /// Every rank's @p bytes on rank 0, one string per rank in rank order
    /// (bit for bit); the other ranks get an empty vector. Without MPI, or
    /// on one rank: {bytes}. Collective.
    std::vector<std::string> gather_bytes(const std::string &bytes);

    /// Rank 0's @p value on every rank (nothing to do without MPI or on one
    /// rank). Collective.
    void broadcast(int &value);

    /// Counts that the other ranks send to rank 0 while they work (progress),
    /// without waiting for rank 0 to take them. Tagged with @p tag.
    class CountChannel
    {
    public:
      explicit CountChannel(int tag);
      ~CountChannel();
      CountChannel(const CountChannel &)            = delete;
      CountChannel &operator=(const CountChannel &) = delete;

      /// Not on rank 0: send @p count to rank 0 and return at once.
      void send(std::uint64_t count);
      /// Not on rank 0: wait until every count sent has left.
      void wait_for_sends();
      /// On rank 0: a count that has arrived from any rank, if there is one.
      bool try_receive(std::uint64_t &count);
      /// On rank 0: the next count from any rank (waits for it).
      std::uint64_t receive();

    private:
      struct Pending; ///< the buffers and requests of the sends under way
      const int                tag;
      std::unique_ptr<Pending> pending;
    };
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
