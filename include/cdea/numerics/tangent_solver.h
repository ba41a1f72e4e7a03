#pragma once
// Direct solvers of the tangent systems K u = b behind one interface: LAPACK's
// band LU (the default) and, in fe/trilinos_solver.h, Trilinos' KLU. A rank-one
// update K + k g g^T is solved with either by Sherman-Morrison
// (sherman_morrison.h).

#include <cdea/numerics/band_matrix.h>

#include <Eigen/Core>

#include <memory>

namespace cdea
{
  /// How the tangent systems are solved.
  enum class LinearSolver
  {
    banded_lu,
    trilinos_klu
  };

  class TangentSolver
  {
  public:
    virtual ~TangentSolver() = default;
    /// Factorize @p K; false if it is singular.
    virtual bool factorize(const BandMatrix &K) = 0;
    /// b <- K^-1 b with the last factorization; false if that failed.
    virtual bool solve(Eigen::VectorXd &b) const = 0;
  };

  /// LAPACK dgbtrf/dgbtrs: O(n bw^2) to factor, O(n bw) per solve.
  class BandedLU final : public TangentSolver
  {
  public:
    bool factorize(const BandMatrix &K) override;
    bool solve(Eigen::VectorXd &b) const override;

  private:
    BandMatrix       lu;
    std::vector<int> pivots;
    bool             factorized = false;
  };
} // namespace cdea
