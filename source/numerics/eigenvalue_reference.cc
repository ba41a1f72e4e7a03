#include <cdea/numerics/eigenvalue_reference.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

// LAPACK: selected eigenvalues of a symmetric band matrix.
extern "C" void dsbevx_(const char *jobz, const char *range, const char *uplo, const int *n,
                        const int *kd, double *ab, const int *ldab, double *q, const int *ldq,
                        const double *vl, const double *vu, const int *il, const int *iu,
                        const double *abstol, int *m, double *w, double *z, const int *ldz,
                        double *work, int *iwork, int *ifail, int *info);

namespace cdea::reference
{
  // The excluded dofs are decoupled with a diagonal above every eigenvalue of
  // the rest (a Gershgorin bound), so the smallest eigenvalue is the rest's.
  double smallest_symmetric_eigenvalue(const BandMatrix                &A,
                                       const std::vector<unsigned int> &excluded)
  {
    const int n = A.size(), kd = A.bandwidth(), ldab = kd + 1;
    if (n == 0)
      return std::numeric_limits<double>::quiet_NaN();
    // Upper band storage of the symmetric part: ab(kd + i - j, j) = S(i, j), i <= j.
    std::vector<double> ab(std::size_t(ldab) * n, 0.);
    const double       *a  = A.data();
    const std::size_t   ld = A.leading_dimension();
    const auto at = [&](const int i, const int j) { return a[(2 * kd + i - j) + j * ld]; };
    std::vector<double> row_sum(n, 0.);
    for (int j = 0; j < n; ++j)
      for (int i = std::max(0, j - kd); i <= j; ++i)
        {
          const double s = 0.5 * (at(i, j) + at(j, i));
          ab[(kd + i - j) + std::size_t(j) * ldab] = s;
          row_sum[i] += std::abs(s);
          if (i != j)
            row_sum[j] += std::abs(s);
        }
    const double bound = *std::max_element(row_sum.begin(), row_sum.end());
    for (const unsigned int e : excluded)
      {
        const int i = e;
        for (int j = std::max(0, i - kd); j <= std::min(n - 1, i + kd); ++j)
          ab[(kd + std::min(i, j) - std::max(i, j)) + std::size_t(std::max(i, j)) * ldab] = 0.;
        ab[kd + std::size_t(i) * ldab] = 2. * bound + 1.;
      }
    const char          jobz = 'N', range = 'I', uplo = 'U';
    const int           il = 1, iu = 1, ldq = 1, ldz = 1;
    const double        vl = 0., vu = 0., abstol = 0.;
    int                 found = 0, info = 0;
    double              q = 0., z = 0.;
    std::vector<double> w(n), work(7 * n);
    std::vector<int>    iwork(5 * n), ifail(n);
    dsbevx_(&jobz, &range, &uplo, &n, &kd, ab.data(), &ldab, &q, &ldq, &vl, &vu, &il, &iu,
            &abstol, &found, w.data(), &z, &ldz, work.data(), iwork.data(), ifail.data(), &info);
    return info == 0 && found == 1 ? w[0] : std::numeric_limits<double>::quiet_NaN();
  }

  double smallest_symmetric_eigenvalue(const BandMatrix &A, const double k,
                                       const Eigen::VectorXd           &g,
                                       const std::vector<unsigned int> &excluded)
  {
    std::vector<unsigned int> kept;
    for (unsigned int i = 0; i < A.size(); ++i)
      if (std::find(excluded.begin(), excluded.end(), i) == excluded.end())
        kept.push_back(i);
    const int       n = kept.size();
    Eigen::MatrixXd S(n, n);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        {
          const unsigned int i = kept[a], j = kept[b];
          S(a, b) = 0.5 * ((A.entry(i, j) + k * g[i] * g[j]) + (A.entry(j, i) + k * g[j] * g[i]));
        }
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S, Eigen::EigenvaluesOnly)
      .eigenvalues()(0);
  }
} // namespace cdea::reference
