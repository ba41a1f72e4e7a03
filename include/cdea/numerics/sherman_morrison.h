#pragma once
// A rank-one update of a factored tangent: the water's free surface couples
// every dof through the enclosed volume, K + k g g^T with g = dV/dx, which
// would fill the band; Sherman-Morrison solves it with the factorization of K.

#include <cdea/numerics/tangent_solver.h>

namespace cdea
{
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
