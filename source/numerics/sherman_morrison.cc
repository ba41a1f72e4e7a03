#include <cdea/numerics/sherman_morrison.h>

namespace cdea
{
  bool ShermanMorrison::prepare(const TangentSolver &solver, const double k_in,
                                const Eigen::VectorXd &g_in)
  {
    k       = k_in;
    g       = g_in;
    K_inv_g = g;
    return solver.solve(K_inv_g);
  }

  bool ShermanMorrison::solve(const TangentSolver &solver, Eigen::VectorXd &b) const
  {
    if (!solver.solve(b))
      return false;
    if (k != 0.)
      b -= (k * g.dot(b) / (1. + k * g.dot(K_inv_g))) * K_inv_g;
    return true;
  }
} // namespace cdea
