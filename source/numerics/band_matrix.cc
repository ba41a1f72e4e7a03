#include <cdea/numerics/band_matrix.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <limits>

namespace cdea
{
  void BandMatrix::reinit(const unsigned int size, const unsigned int bandwidth)
  {
    n  = size;
    bw = bandwidth;
    values.assign(std::size_t(3 * bw + 1) * n, 0.);
  }

  void BandMatrix::reshape_like(const BandMatrix &other)
  {
    n  = other.n;
    bw = other.bw;
    values.resize(other.values.size());
  }

  void BandMatrix::set_zero()
  {
    // All bits zero is +0.0; memset, where std::fill stays an element loop at -O2.
    std::memset(values.data(), 0, values.size() * sizeof(double));
  }

  double BandMatrix::entry(const unsigned int i, const unsigned int j) const
  {
    if ((i > j ? i - j : j - i) > bw)
      return 0.;
    return values[index(i, j)];
  }

  void BandMatrix::add(const double factor, const BandMatrix &other)
  {
    for (std::size_t k = 0; k < values.size(); ++k)
      values[k] += factor * other.values[k];
  }

  void BandMatrix::constrain(const unsigned int i, const double diagonal)
  {
    const unsigned int lo = i > bw ? i - bw : 0, hi = std::min(n - 1, i + bw);
    for (unsigned int j = lo; j <= hi; ++j)
      (*this)(i, j) = (*this)(j, i) = 0.;
    (*this)(i, i) = diagonal;
  }

  void BandMatrix::vmult(const double *x, double *y) const
  {
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int lo = i > bw ? i - bw : 0, hi = std::min(n - 1, i + bw);
        double             s  = 0.;
        for (unsigned int j = lo; j <= hi; ++j)
          s += (*this)(i, j) * x[j];
        y[i] = s;
      }
  }

} // namespace cdea
