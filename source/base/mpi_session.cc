#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <cdea/base/mpi_session.h>

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <memory>
#include <numeric>
#include <vector>

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

    std::vector<std::size_t> items_of_rank(const std::size_t n, const unsigned int rank,
                                           const unsigned int size)
    {
      std::vector<std::size_t> items;
      for (std::size_t i = rank; i < n; i += std::max(1u, size))
        items.push_back(i);
      return items;
    }

    std::vector<std::string> gather_bytes(const std::string &bytes)
    {
      if (size() == 1)
        return {bytes};
      const unsigned int n      = size();
      const bool         root   = rank() == 0;
      int                length = int(bytes.size());
      std::vector<int>   lengths(root ? n : 0), offsets(root ? n : 0, 0);
      MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
      if (root)
        std::partial_sum(lengths.begin(), lengths.end() - 1, offsets.begin() + 1);
      // At least one byte, so that data() is a valid buffer on every rank.
      std::string all(root ? std::size_t(std::max(1, offsets.back() + lengths.back())) : 1, '\0');
      MPI_Gatherv(bytes.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                  MPI_CHAR, 0, MPI_COMM_WORLD);
      std::vector<std::string> per_rank;
      if (root)
        for (unsigned int r = 0; r < n; ++r)
          per_rank.push_back(all.substr(std::size_t(offsets[r]), std::size_t(lengths[r])));
      return per_rank;
    }

    void broadcast(int &value)
    {
      if (size() > 1)
        MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    }

    struct CountChannel::Pending
    {
      std::deque<std::uint64_t> counts; ///< a deque: the buffers must not move
      std::vector<MPI_Request>  requests;
    };

    CountChannel::CountChannel(const int tag)
      : tag(tag)
      , pending(std::make_unique<Pending>())
    {}

    CountChannel::~CountChannel() = default;

    void CountChannel::send(const std::uint64_t count)
    {
      pending->counts.push_back(count);
      pending->requests.emplace_back();
      MPI_Isend(&pending->counts.back(), 1, MPI_UINT64_T, 0, tag, MPI_COMM_WORLD,
                &pending->requests.back());
    }

    void CountChannel::wait_for_sends()
    {
      if (!pending->requests.empty())
        MPI_Waitall(int(pending->requests.size()), pending->requests.data(),
                    MPI_STATUSES_IGNORE);
      pending->requests.clear();
      pending->counts.clear();
    }

    bool CountChannel::try_receive(std::uint64_t &count)
    {
      int        flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &status);
      if (!flag)
        return false;
      MPI_Recv(&count, 1, MPI_UINT64_T, status.MPI_SOURCE, tag, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      return true;
    }

    std::uint64_t CountChannel::receive()
    {
      std::uint64_t count = 0;
      MPI_Recv(&count, 1, MPI_UINT64_T, MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return count;
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
