#include <cdea/numerics/symmetric_band.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cdea
{
  void SymmetricBand::reinit(const unsigned int size, const unsigned int bandwidth)
  {
    n  = size;
    kd = bandwidth;
    ab.assign(std::size_t(kd + 1) * n, 0.);
    free.assign(n, 1);
  }

  void SymmetricBand::set(const unsigned int i, const unsigned int j, const double value)
  {
    const unsigned int lo = std::min(i, j), hi = std::max(i, j);
    ab[(kd + lo - hi) + std::size_t(hi) * (kd + 1)] = value;
  }

  double SymmetricBand::entry(const unsigned int i, const unsigned int j) const
  {
    const unsigned int lo = std::min(i, j), hi = std::max(i, j);
    return hi - lo > kd ? 0. : ab[(kd + lo - hi) + std::size_t(hi) * (kd + 1)];
  }

  void SymmetricBand::assign(const BandMatrix &A, const std::vector<unsigned int> &excluded)
  {
    const unsigned int size = A.size(), bw = A.bandwidth();
    if (n != size || kd != bw)
      reinit(size, bw);
    std::fill(free.begin(), free.end(), 1);
    for (const unsigned int e : excluded)
      free[e] = 0;
    // A(i, j) at a[(2 bw + i - j) + j ld] (BandMatrix's layout).
    const double     *a        = A.data();
    const std::size_t ld       = A.leading_dimension();
    double            diagonal = 0.;
    for (unsigned int j = 0; j < n; ++j)
      {
        double *column = ab.data() + std::size_t(j) * (kd + 1) + kd - j;
        for (unsigned int i = j > kd ? j - kd : 0; i <= j; ++i)
          column[i] = free[i] && free[j] ?
                        0.5 * (a[(2 * kd + i - j) + j * ld] + a[(2 * kd + j - i) + i * ld]) :
                        0.;
        diagonal = std::max(diagonal, std::abs(column[j]));
      }
    // Any positive diagonal keeps an excluded dof out of the inertia and out
    // of the Krylov spaces (its row and column are zero); the matrix's own
    // scale keeps the factorizations well scaled.
    for (const unsigned int e : excluded)
      ab[kd + std::size_t(e) * (kd + 1)] = diagonal > 0. ? diagonal : 1.;
  }

  void SymmetricBand::vmult(const double *x, double *y) const
  {
    std::fill(y, y + n, 0.);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double *column = ab.data() + std::size_t(j) * (kd + 1) + kd - j;
        const unsigned int lo = j > kd ? j - kd : 0;
        double             yj = column[j] * x[j];
        for (unsigned int i = lo; i < j; ++i)
          {
            y[i] += column[i] * x[j];
            yj += column[i] * x[i];
          }
        y[j] += yj;
      }
  }

  namespace
  {
    /// Row sums of |S| without the diagonal, and the diagonal.
    template <typename F>
    void for_each_row(const double *ab, const unsigned int n, const unsigned int kd,
                      F &&f)
    {
      std::vector<double> off(n, 0.);
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = j > kd ? j - kd : 0; i < j; ++i)
          {
            const double s = std::abs(ab[(kd + i - j) + std::size_t(j) * (kd + 1)]);
            off[i] += s;
            off[j] += s;
          }
      for (unsigned int i = 0; i < n; ++i)
        f(ab[kd + std::size_t(i) * (kd + 1)], off[i]);
    }
  } // namespace

  double SymmetricBand::gershgorin_lower() const
  {
    double lower = std::numeric_limits<double>::infinity();
    for_each_row(ab.data(), n, kd, [&](const double d, const double off) { lower = std::min(lower, d - off); });
    return lower;
  }

  double SymmetricBand::gershgorin_upper() const
  {
    double upper = -std::numeric_limits<double>::infinity();
    for_each_row(ab.data(), n, kd, [&](const double d, const double off) { upper = std::max(upper, d + off); });
    return upper;
  }

  std::pair<double, double> SymmetricBand::gershgorin_bounds() const
  {
    double lower = std::numeric_limits<double>::infinity();
    double upper = -lower;
    for_each_row(ab.data(), n, kd, [&](const double d, const double off) {
      lower = std::min(lower, d - off);
      upper = std::max(upper, d + off);
    });
    return {lower, upper};
  }

  namespace
  {
    /// The bandwidth of a kernel: KD if it is fixed at compile time (the FE
    /// tangents' bandwidths 2p + 1, so that the loops over a column unroll),
    /// else the run-time @p kd (KD = 0). Same operations in the same order
    /// either way.
    template <unsigned int KD>
    unsigned int band_width(const unsigned int kd)
    {
      return KD != 0 ? KD : kd;
    }

    /// Column j's step of cholesky_in_place() after its pivot @p root: the
    /// row of U right of the diagonal over root, then the trailing block
    /// less u_j u_j^T. U(j + i, j + c) at diagonal[c kd + i], c = 1..kn.
    /// K: kn = kd fixed at compile time (a full band), else 0 (run time).
    template <unsigned int K>
    void update_trailing(double *diagonal, const unsigned int kn_run, const unsigned int kd_run,
                         const double root, double *r)
    {
      const unsigned int kn = K != 0 ? K : kn_run, kd = K != 0 ? K : kd_run;
      for (unsigned int c = 1; c <= kn; ++c)
        r[c] = diagonal[c * kd] /= root;
      for (unsigned int c = 1; c <= kn; ++c)
        {
          double *column = diagonal + c * kd; // column[i] = U(j + i, j + c)
          for (unsigned int i = 1; i <= c; ++i)
            column[i] -= r[i] * r[c];
        }
    }

    /// Right-looking, as LAPACK's dpbtf2: u_jj = sqrt(a_jj), the row of U
    /// right of it a_jk / u_jj, then the trailing block less u_j u_j^T.
    /// U(i, j) at ab[(kd + i - j) + j (kd + 1)].
    template <unsigned int KD>
    bool cholesky_in_place(double *ab, const unsigned int n, const unsigned int kd_run,
                           const double shift, double *r)
    {
      const unsigned int kd = band_width<KD>(kd_run);
      const std::size_t  ld = kd + 1;
      for (unsigned int j = 0; j < n; ++j)
        {
          double      *diagonal = ab + kd + j * ld;
          const double d        = *diagonal - shift;
          if (!(d > 0.))
            return false;
          const double root = std::sqrt(d);
          *diagonal         = root;
          const unsigned int kn = std::min(kd, n - 1 - j);
          // A full band (all but the last kd columns) with KD fixed: the
          // same updates with compile-time trip counts, which unroll.
          if (KD != 0 && kn == KD)
            update_trailing<KD>(diagonal, KD, KD, root, r);
          else
            update_trailing<0>(diagonal, kn, kd, root, r);
        }
      return true;
    }

    /// U^T y = b (column j of U holds U(j - kd .. j, j): a dot product per
    /// row), then U x = y from the last row up (an update per column).
    template <unsigned int KD>
    void cholesky_solve(const double *ab, const unsigned int n, const unsigned int kd_run,
                        double *b)
    {
      const unsigned int kd = band_width<KD>(kd_run);
      const std::size_t  ld = kd + 1;
      for (unsigned int j = 0; j < n; ++j)
        {
          const double *column = ab + j * ld + kd - j; // column[i] = U(i, j)
          double        sum    = b[j];
          if (j >= kd)
            for (unsigned int i = j - kd; i < j; ++i)
              sum -= column[i] * b[i];
          else
            for (unsigned int i = 0; i < j; ++i)
              sum -= column[i] * b[i];
          b[j] = sum / column[j];
        }
      for (unsigned int j = n; j-- > 0;)
        {
          const double *column = ab + j * ld + kd - j;
          const double  x      = b[j] / column[j];
          b[j]                 = x;
          if (j >= kd)
            for (unsigned int i = j - kd; i < j; ++i)
              b[i] -= column[i] * x;
          else
            for (unsigned int i = 0; i < j; ++i)
              b[i] -= column[i] * x;
        }
    }
  } // namespace

  bool BandCholesky::factorize(const SymmetricBand &S, const double shift)
  {
    n      = S.size();
    kd     = S.bandwidth();
    shift_ = shift;
    ab.assign(S.data(), S.data() + std::size_t(kd + 1) * n);
    work.resize(kd + 1);
    switch (kd)
      {
        case 5:
          return cholesky_in_place<5>(ab.data(), n, kd, shift, work.data());
        case 7:
          return cholesky_in_place<7>(ab.data(), n, kd, shift, work.data());
        case 9:
          return cholesky_in_place<9>(ab.data(), n, kd, shift, work.data());
        case 11:
          return cholesky_in_place<11>(ab.data(), n, kd, shift, work.data());
        default:
          return cholesky_in_place<0>(ab.data(), n, kd, shift, work.data());
      }
  }

  void BandCholesky::solve(double *b) const
  {
    switch (kd)
      {
        case 5:
          return cholesky_solve<5>(ab.data(), n, kd, b);
        case 7:
          return cholesky_solve<7>(ab.data(), n, kd, b);
        case 9:
          return cholesky_solve<9>(ab.data(), n, kd, b);
        case 11:
          return cholesky_solve<11>(ab.data(), n, kd, b);
        default:
          return cholesky_solve<0>(ab.data(), n, kd, b);
      }
  }

  // Right-looking LDL^T on the lower band L(i, j) = S(i, j), i >= j: pivot
  // d_j, multipliers l_ij = L(i, j) / d_j, then L(m, i) -= l_mj d_j l_ij.
  Inertia band_inertia(const SymmetricBand &S, const double shift)
  {
    const unsigned int  n = S.size(), kd = S.bandwidth(), ld = kd + 1;
    std::vector<double> L(std::size_t(ld) * n);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = j; i <= std::min(n - 1, j + kd); ++i)
        L[(i - j) + std::size_t(j) * ld] = S.entry(i, j) - (i == j ? shift : 0.);
    double scale = 0.;
    for (const double v : L)
      scale = std::max(scale, std::abs(v));
    // A pivot exactly zero is a zero eigenvalue; it is replaced by a
    // positive one at round-off level, so the rest is counted as for
    // S - shift I + delta e_j e_j^T with delta -> 0+.
    const double tiny = std::numeric_limits<double>::epsilon() * (scale > 0. ? scale : 1.);
    Inertia             inertia;
    std::vector<double> l(kd + 1);
    for (unsigned int j = 0; j < n; ++j)
      {
        double d = L[std::size_t(j) * ld];
        if (d == 0.)
          {
            ++inertia.zero;
            d = tiny;
          }
        else
          ++(d < 0. ? inertia.negative : inertia.positive);
        const unsigned int last = std::min(n - 1, j + kd);
        for (unsigned int i = j + 1; i <= last; ++i)
          l[i - j] = L[(i - j) + std::size_t(j) * ld] / d;
        for (unsigned int i = j + 1; i <= last; ++i)
          {
            const double f = l[i - j] * d;
            double      *column = &L[std::size_t(i) * ld];
            for (unsigned int m = i; m <= last; ++m)
              column[m - i] -= l[m - j] * f;
          }
      }
    return inertia;
  }
} // namespace cdea
