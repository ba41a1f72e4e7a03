#include <cdea/numerics/fixed_size.h>
#include <cdea/numerics/tangent_solver.h>

#include <algorithm>
#include <cmath>

// LAPACK: LU factorization of a general band matrix and solves with it.
extern "C" void dgbtrf_(const int *m, const int *n, const int *kl, const int *ku, double *ab,
                        const int *ldab, int *ipiv, int *info);
extern "C" void dgbtrs_(const char *trans, const int *n, const int *kl, const int *ku,
                        const int *nrhs, const double *ab, const int *ldab, const int *ipiv,
                        double *b, const int *ldb, int *info);

namespace cdea
{
  namespace
  {
    /// Up to this bandwidth LAPACK's dgbtrf takes its unblocked path
    /// (dgbtf2: ILAENV gives block size 1 for KU <= 64), which the loops
    /// below repeat operation for operation, without its BLAS calls per
    /// column (at the FE tangents' bandwidths the calls cost more than the
    /// arithmetic). Wider bands go to LAPACK.
    constexpr unsigned int widest_inline_band = 64;

    /// target[i] += column[i] * factor for i = 1..bw (BW as in band_lu()):
    /// two columns of the band, which never overlap (restrict), so that the
    /// loop vectorizes with the same operation per entry.
    template <unsigned int BW>
    inline void add_multiple(const unsigned int bw_run, const double factor,
                             const double *__restrict column, double *__restrict target)
    {
      const unsigned int bw    = BW != 0 ? BW : bw_run;
      const unsigned int first = bw % 2 == 1 ? 2 : 1; // then an even count
      if (first == 2)
        target[1] += column[1] * factor;
      for (unsigned int i = first; i <= bw; ++i)
        target[i] += column[i] * factor;
    }

    /// target[i] -= x * column[i] for i = 0..m-1 (M = m at compile time or
    /// 0), in any order: each entry gets its one operation.
    template <unsigned int M>
    inline void subtract_multiple(const unsigned int m_run, const double x,
                                  const double *__restrict column, double *__restrict target)
    {
      const unsigned int m = M != 0 ? M : m_run;
      for (unsigned int i = 0; i < m; ++i)
        target[i] -= x * column[i];
    }

    /// dgbtf2 on A(i, j) at ab[(kv + i - j) + j ld], kv = 2 bw: partial
    /// pivoting by rows, multipliers scaled by the pivot's reciprocal, the
    /// trailing band updated column by column; the rows of fill-in zeroed as
    /// they come into use. The matrix is read from @p source (same layout)
    /// a column ahead of its first use (step j touches columns j..j + kv),
    /// so that the copy and the factorization make one pass over the band,
    /// not two: beyond the caches, the band streams from memory once.
    /// Pivots 0-based; false if a pivot is zero.
    template <unsigned int BW>
    bool band_lu(const double *source, double *ab, const unsigned int n,
                 const unsigned int bw_run, int *pivots)
    {
      // BW: the bandwidth fixed at compile time (the loops over a column
      // unroll), 0: bw_run. Same operations in the same order either way.
      const unsigned int bw = BW != 0 ? BW : bw_run;
      const std::size_t  ld = 3 * bw + 1;
      const unsigned int kv = 2 * bw;
      bool               regular = true;
      std::copy_n(source, std::min(kv, n) * ld, ab);
      for (unsigned int j = bw + 1; j < std::min(kv, n); ++j)
        for (unsigned int i = kv - j; i < bw; ++i)
          ab[i + j * ld] = 0.;
      unsigned int ju = 0;
      for (unsigned int j = 0; j < n; ++j)
        {
          if (j + kv < n)
            {
              std::copy_n(source + (j + kv) * ld, ld, ab + (j + kv) * ld);
              std::fill(ab + (j + kv) * ld, ab + (j + kv) * ld + bw, 0.);
            }
          double            *column = ab + kv + j * ld; // column[i] = A(j + i, j)
          const unsigned int km     = std::min(bw, n - 1 - j);
          unsigned int       p      = 0;
          for (unsigned int i = 1; i <= km; ++i)
            if (std::abs(column[i]) > std::abs(column[p]))
              p = i;
          pivots[j] = j + p;
          if (column[p] == 0.)
            {
              regular = false;
              continue;
            }
          ju = std::max(ju, std::min(j + bw + p, n - 1));
          // Along row j: A(j + i, j + k) = column[i + k (ld - 1)].
          const std::size_t row_step = ld - 1;
          if (p != 0)
            for (std::size_t k = 0; k <= ju - j; ++k) // A(j + p, j + k) <-> A(j, j + k)
              std::swap(column[p + k * row_step], column[k * row_step]);
          if (km == 0)
            continue;
          const double reciprocal = 1. / column[0];
          for (unsigned int i = 1; i <= km; ++i)
            column[i] *= reciprocal;
          double *target = column; // target[i] = A(j + i, j + c)
          for (unsigned int c = 1; c <= ju - j; ++c)
            {
              target += row_step;
              const double factor = -target[0];
              if (factor == 0.)
                continue;
              if (km == bw)
                add_multiple<BW>(bw, factor, column, target);
              else
                for (unsigned int i = 1; i <= km; ++i)
                  target[i] += column[i] * factor;
            }
        }
      return regular;
    }

    /// dgbtrs for one right-hand side: the row interchanges and L column by
    /// column, then U from the last row up (dtbsv).
    template <unsigned int BW>
    void band_lu_solve(const double *ab, const unsigned int n, const unsigned int bw_run,
                       const int *pivots, double *b)
    {
      const unsigned int bw = BW != 0 ? BW : bw_run;
      const std::size_t  ld = 3 * bw + 1;
      const unsigned int kv = 2 * bw;
      for (unsigned int j = 0; j + 1 < n; ++j)
        {
          const unsigned int lm = std::min(bw, n - 1 - j);
          if (unsigned(pivots[j]) != j)
            std::swap(b[pivots[j]], b[j]);
          const double  factor = -b[j];
          const double *column = ab + kv + j * ld; // column[i] = L(j + i, j)
          if (factor != 0. && lm == bw)
            add_multiple<BW>(bw, factor, column, b + j);
          else if (factor != 0.)
            for (unsigned int i = 1; i <= lm; ++i)
              b[j + i] += column[i] * factor;
        }
      for (unsigned int j = n; j-- > 0;)
        if (b[j] != 0.)
          {
            const double *column = ab + (j * ld + kv - j); // column[i] = U(i, j)
            b[j] /= column[j];
            const unsigned int lo = j > kv ? j - kv : 0;
            if (j - lo == kv)
              subtract_multiple<2 * BW>(kv, b[j], column + lo, b + lo);
            else
              for (unsigned int i = j; i-- > lo;)
                b[i] -= b[j] * column[i];
          }
    }

    /// f with the bandwidth fixed at compile time for the bandwidths 5, 7, 9
    /// and 11 of the FE tangents of low degree, else at run time
    /// (numerics/fixed_size.h).
    template <typename F>
    void with_bandwidth(const unsigned int bw, F &&f)
    {
      with_fixed_size<5, 7, 9, 11>(bw, std::forward<F>(f));
    }
  } // namespace

  bool BandedLU::factorize(const BandMatrix &K)
  {
    const int n = K.size(), kl = K.bandwidth(), ldab = K.leading_dimension();
    pivots.resize(n);
    if (K.bandwidth() <= widest_inline_band)
      {
        lu.reshape_like(K);
        with_bandwidth(kl, [&](auto bw_fixed) {
          factorized = band_lu<bw_fixed()>(K.data(), lu.data(), n, kl, pivots.data());
        });
        return factorized;
      }
    lu = K;
    int info = 0;
    dgbtrf_(&n, &n, &kl, &kl, lu.data(), &ldab, pivots.data(), &info);
    factorized = info == 0;
    return factorized;
  }

  bool BandedLU::solve(Eigen::VectorXd &b) const
  {
    if (!factorized)
      return false;
    if (lu.bandwidth() <= widest_inline_band)
      {
        const unsigned int n = lu.size(), bw = lu.bandwidth();
        with_bandwidth(bw, [&](auto bw_fixed) {
          band_lu_solve<bw_fixed()>(lu.data(), n, bw, pivots.data(), b.data());
        });
        return true;
      }
    const int  n = lu.size(), kl = lu.bandwidth(), ldab = lu.leading_dimension(), nrhs = 1;
    const char trans = 'N';
    int        info  = 0;
    dgbtrs_(&trans, &n, &kl, &kl, &nrhs, lu.data(), &ldab, pivots.data(), b.data(), &n,
            &info);
    return info == 0;
  }

} // namespace cdea
