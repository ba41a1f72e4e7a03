#include <cdea/numerics/tangent_solver.h>

// LAPACK: LU factorization of a general band matrix and solves with it.
extern "C" void dgbtrf_(const int *m, const int *n, const int *kl, const int *ku, double *ab,
                        const int *ldab, int *ipiv, int *info);
extern "C" void dgbtrs_(const char *trans, const int *n, const int *kl, const int *ku,
                        const int *nrhs, const double *ab, const int *ldab, const int *ipiv,
                        double *b, const int *ldb, int *info);

namespace cdea
{
  bool BandedLU::factorize(const BandMatrix &K)
  {
    lu = K;
    const int n = K.size(), kl = K.bandwidth(), ldab = K.leading_dimension();
    pivots.resize(n);
    int info = 0;
    dgbtrf_(&n, &n, &kl, &kl, lu.data(), &ldab, pivots.data(),
            &info);
    factorized = info == 0;
    return factorized;
  }

  bool BandedLU::solve(Eigen::VectorXd &b) const
  {
    if (!factorized)
      return false;
    const int  n = lu.size(), kl = lu.bandwidth(), ldab = lu.leading_dimension(), nrhs = 1;
    const char trans = 'N';
    int        info  = 0;
    dgbtrs_(&trans, &n, &kl, &kl, &nrhs, lu.data(), &ldab, pivots.data(), b.data(), &n,
            &info);
    return info == 0;
  }

} // namespace cdea
