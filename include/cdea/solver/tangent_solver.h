#pragma once
// Direct solvers of the tangent systems K u = b behind one interface: LAPACK's
// band LU (the default) and, in fe/trilinos_solver.h, Trilinos' KLU. A rank-one
// update K + k g g^T (the water's free surface couples every dof) is solved
// with the factorization of K by Sherman-Morrison.

#include <cdea/solver/band_matrix.h>

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

  /// (K + k g g^T)^-1 b = K^-1 b - k (g . K^-1 b) / (1 + k g . K^-1 g) K^-1 g.
  class ShermanMorrison
  {
  public:
    /// With the factorization of K in @p solver: remember k, g and K^-1 g.
    bool prepare(const TangentSolver &solver, double k, const Eigen::VectorXd &g);
    /// b <- (K + k g g^T)^-1 b.
    bool solve(const TangentSolver &solver, Eigen::VectorXd &b) const;

  private:
    double          k = 0.;
    Eigen::VectorXd g, K_inv_g;
  };
} // namespace cdea
