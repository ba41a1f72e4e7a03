// The band LU's loops at every bandwidth path (compile-time 5, 7, 9, 11 with
// their odd-count peel, run-time others) and at the matrix's last columns
// (fewer than bw rows below the diagonal), against dense Eigen LU; the band
// storage's column pointer; the dispatch on the dofs per cell. A band large
// enough for huge pages: its storage aligned to 2 MiB, left unchanged by the
// factorization (which reads it a column ahead), solved to round-off, and
// solved the same again by a second factorization into the same storage.

#include <cdea/fe/discretization.h>
#include <cdea/numerics/band_matrix.h>
#include <cdea/numerics/tangent_solver.h>

#include <Eigen/Dense>

#include "check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// Unsymmetric, not diagonally dominant: rows get swapped.
  double entry(const unsigned int i, const unsigned int j)
  {
    return (i == j ? 0.3 + 0.05 * i : 1. / (1. + i + 2. * j)) * ((i + j) % 3 ? 1. : -1.);
  }

  void check_bandwidth(const unsigned int n, const unsigned int bw)
  {
    const std::string name = "n " + std::to_string(n) + ", bw " + std::to_string(bw);
    BandMatrix        K;
    K.reinit(n, bw);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
    bool            columns_match = true;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > bw ? i - bw : 0); j <= std::min(n - 1, i + bw); ++j)
        {
          K(i, j) = D(i, j) = entry(i, j);
          columns_match = columns_match && &K.column(j)[i] == &K(i, j);
        }
    check(columns_match, name + ": column(j)[i] is entry (i, j)");
    Eigen::VectorXd b(n);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = std::sin(1. + i);
    BandedLU lu;
    check(lu.factorize(K), name + ": factorizes");
    Eigen::VectorXd x = b;
    check(lu.solve(x), name + ": solves");
    const Eigen::VectorXd dense = D.partialPivLu().solve(b);
    check_close((x - dense).norm() / dense.norm(), 0., 1e-12, name + ": band LU = dense LU");
  }

  void check_large_band()
  {
    const unsigned int n = 20000, bw = 9; // 28 x 20000 doubles: 4.3 MiB
    BandMatrix         K;
    K.reinit(n, bw);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > bw ? i - bw : 0); j <= std::min(n - 1, i + bw); ++j)
        K(i, j) = entry(i % 97, j + (i % 97) - i) + (i == j ? 1. : 0.);
    check(reinterpret_cast<std::uintptr_t>(K.data()) % (std::uintptr_t(2) << 20) == 0,
          "large band: storage aligned to 2 MiB");
    const std::vector<double> before(K.data(), K.data() + std::size_t(3 * bw + 1) * n);
    Eigen::VectorXd           b(n);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = std::sin(1. + i);
    BandedLU        lu;
    Eigen::VectorXd x = b;
    check(lu.factorize(K) && lu.solve(x), "large band: factorizes and solves");
    check(std::equal(before.begin(), before.end(), K.data()),
          "large band: the factorization leaves the matrix as it was");
    Eigen::VectorXd Kx(n);
    K.vmult(x.data(), Kx.data());
    check_close((Kx - b).norm() / b.norm(), 0., 1e-13, "large band: residual |K x - b| / |b|");
    Eigen::VectorXd again = b;
    check(lu.factorize(K) && lu.solve(again) && again == x,
          "large band: a second factorization in the same storage solves the same");
  }
} // namespace

CDEA_TEST_MAIN()
{
  for (const unsigned int bw : {2u, 4u, 5u, 7u, 9u, 11u, 13u})
    for (const unsigned int n : {bw + 3, 5 * bw + 2})
      check_bandwidth(n, bw);
  check_large_band();

  unsigned int dispatched = 0;
  for (unsigned int n = 1; n <= 20; ++n)
    with_dofs_per_cell(n, [&](auto n_fixed) {
      if (n_fixed() != 0)
        dispatched += n_fixed() == n;
      else
        dispatched += n % 2 == 1 || n < 4 || n > 18;
    });
  check(dispatched == 20, "with_dofs_per_cell: n fixed for n = 4, 6, ..., 18, else 0");
  return failures() == 0 ? 0 : 1;
}
