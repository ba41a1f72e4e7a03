#pragma once
// The smallest eigenvalue of a band tangent: the stability check of a state
// (negative: unstable with the loads held).

#include <cdea/numerics/band_matrix.h>

#include <Eigen/Core>

#include <vector>

namespace cdea
{
  /// Smallest eigenvalue of the symmetric part (A + A^T) / 2 of @p A without
  /// the rows and columns listed in @p excluded (LAPACK dsbevx on the band);
  /// NaN if LAPACK fails.
  double smallest_symmetric_eigenvalue(const BandMatrix                &A,
                                       const std::vector<unsigned int> &excluded);

  /// The same for A + k g g^T (the water's free surface couples every dof,
  /// as in ShermanMorrison): the band and the rank-one term made into one
  /// dense symmetric matrix over the dofs not excluded (Eigen's
  /// SelfAdjointEigenSolver).
  double smallest_symmetric_eigenvalue(const BandMatrix &A, double k, const Eigen::VectorXd &g,
                                       const std::vector<unsigned int> &excluded);
} // namespace cdea
