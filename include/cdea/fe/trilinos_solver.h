#pragma once
// The tangent solver chosen by Solver/Linear solver. Trilinos' KLU (through
// deal.II's wrappers) copies the band into a sparse matrix and needs MPI: the
// matrix is created on first use, not before.

#include <cdea/numerics/tangent_solver.h>

#include <memory>

namespace cdea
{
  std::unique_ptr<TangentSolver> make_tangent_solver(LinearSolver choice);
} // namespace cdea
