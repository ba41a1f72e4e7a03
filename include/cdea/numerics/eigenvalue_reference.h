#pragma once
// The full-spectrum solvers the stability check used before its
// factorization and Lanczos (numerics/band_eigenvalue.h): LAPACK's dsbevx on
// the whole band, O(n^2 kd), and a dense symmetric eigensolver for the
// rank-one term, O(n^3). Kept as the independent reference of the tests and
// the benchmarks; no run uses them.

#include <cdea/numerics/band_matrix.h>

#include <Eigen/Core>

#include <vector>

namespace cdea::reference
{
  /// Smallest eigenvalue of the symmetric part (A + A^T) / 2 of @p A without
  /// the rows and columns listed in @p excluded (LAPACK dsbevx on the band);
  /// NaN if LAPACK fails.
  double smallest_symmetric_eigenvalue(const BandMatrix                &A,
                                       const std::vector<unsigned int> &excluded);

  /// The same for A + k g g^T: the band and the rank-one term made into one
  /// dense symmetric matrix over the dofs not excluded (Eigen's
  /// SelfAdjointEigenSolver).
  double smallest_symmetric_eigenvalue(const BandMatrix &A, double k, const Eigen::VectorXd &g,
                                       const std::vector<unsigned int> &excluded);
} // namespace cdea::reference
