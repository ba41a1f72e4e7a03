#include <cdea/numerics/complex_band.h>

// LAPACK: LU factorization of a complex band matrix and solves with it.
extern "C" void zgbtrf_(const int *m, const int *n, const int *kl, const int *ku, void *ab,
                        const int *ldab, int *ipiv, int *info);
extern "C" void zgbtrs_(const char *trans, const int *n, const int *kl, const int *ku,
                        const int *nrhs, const void *ab, const int *ldab, const int *ipiv,
                        void *b, const int *ldb, int *info);

namespace cdea
{
  void ComplexBandLU::reinit(const unsigned int size, const unsigned int bandwidth)
  {
    n  = size;
    bw = bandwidth;
    values.assign(std::size_t(3 * bw + 1) * n, 0.);
    factorized = false;
  }

  void ComplexBandLU::assign(const BandMatrix &real)
  {
    reinit(real.size(), real.bandwidth());
    const double *r = real.data();
    for (std::size_t i = 0; i < values.size(); ++i)
      values[i] = r[i];
  }

  bool ComplexBandLU::factorize(const Complex coupling, const Eigen::VectorXd &gradient)
  {
    const int ni = n, kl = bw, ldab = 3 * bw + 1;
    pivots.resize(n);
    int info = 0;
    zgbtrf_(&ni, &ni, &kl, &kl, values.data(), &ldab, pivots.data(), &info);
    factorized = info == 0;
    k          = coupling;
    if (!factorized || k == 0.)
      return factorized;
    // Sherman-Morrison: remember g and A^-1 g.
    g = gradient.cast<Complex>();
    Eigen::MatrixXcd column = g;
    factorized = solve_plain(column);
    A_inv_g    = column;
    return factorized && std::abs(1. + k * (g.transpose() * A_inv_g)(0, 0)) > 0.;
  }

  bool ComplexBandLU::solve_plain(Eigen::MatrixXcd &b) const
  {
    const int  ni = n, kl = bw, ldab = 3 * bw + 1, nrhs = static_cast<int>(b.cols());
    const char trans = 'N';
    int        info  = 0;
    zgbtrs_(&trans, &ni, &kl, &kl, &nrhs, values.data(), &ldab, pivots.data(), b.data(), &ni,
            &info);
    return info == 0;
  }

  // (A + k g g^T)^-1 b = A^-1 b - k (g^T A^-1 b) / (1 + k g^T A^-1 g) A^-1 g
  // (g^T without conjugation: the update is symmetric, not Hermitian).
  bool ComplexBandLU::solve(Eigen::MatrixXcd &b) const
  {
    if (!factorized || !solve_plain(b))
      return false;
    if (k == 0.)
      return true;
    const Complex denominator = 1. + k * (g.transpose() * A_inv_g)(0, 0);
    for (Eigen::Index c = 0; c < b.cols(); ++c)
      {
        const Complex gb = (g.transpose() * b.col(c))(0, 0);
        b.col(c) -= (k * gb / denominator) * A_inv_g;
      }
    return true;
  }
} // namespace cdea
