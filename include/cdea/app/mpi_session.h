#pragma once
// MPI (and with it Trilinos) set up for the lifetime of the object. Trilinos
// needs MPI initialised even in serial runs; this keeps deal.II's mpi.h out of
// the files that only need the session.

#include <memory>

namespace cdea
{
  class MpiSession
  {
  public:
    MpiSession(int &argc, char **&argv);
    ~MpiSession();
    unsigned int rank() const;
    unsigned int size() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };
} // namespace cdea
