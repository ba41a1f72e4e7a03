#pragma once
// A square band matrix (equal lower and upper bandwidth bw) stored the way
// LAPACK's band LU wants it, so that the FE tangent is assembled straight into
// its factorization's storage: A(i, j) at data[(2 bw + i - j) + j (3 bw + 1)],
// the first bw rows of each column left for the fill-in of row pivoting.

#include <cdea/numerics/large_page_allocator.h>

#include <cstddef>
#include <vector>

namespace cdea
{
  class BandMatrix
  {
  public:
    void reinit(unsigned int n, unsigned int bandwidth);
    /// The size and bandwidth of @p other, the entries left as they are
    /// (for a matrix about to be overwritten in full).
    void reshape_like(const BandMatrix &other);
    void set_zero();

    unsigned int size() const { return n; }
    unsigned int bandwidth() const { return bw; }
    unsigned int leading_dimension() const { return 3 * bw + 1; }

    /// Entry (i, j) with |i - j| <= bandwidth (inline: the kernels and the
    /// row walks call it per entry).
    double &operator()(const unsigned int i, const unsigned int j) { return values[index(i, j)]; }
    double  operator()(const unsigned int i, const unsigned int j) const { return values[index(i, j)]; }
    /// Column j: A(i, j) = column(j)[i] for |i - j| <= bandwidth.
    double *column(const unsigned int j)
    {
      return values.data() + (std::size_t(j) * (3 * bw + 1) + 2 * bw - j);
    }
    /// Entry (i, j), zero outside the band.
    double entry(unsigned int i, unsigned int j) const;

    /// this += factor * other (same size and bandwidth).
    void add(double factor, const BandMatrix &other);

    /// A Dirichlet dof: row and column i zero, the diagonal @p diagonal.
    void constrain(unsigned int i, double diagonal);

    /// y = A x.
    void vmult(const double *x, double *y) const;

    const double *data() const { return values.data(); }
    double       *data() { return values.data(); }

  private:
    std::size_t index(const unsigned int i, const unsigned int j) const
    {
      return (2 * bw + i - j) + std::size_t(j) * (3 * bw + 1);
    }

    unsigned int        n  = 0;
    unsigned int        bw = 0;
    std::vector<double, LargePageAllocator<double>> values;
  };
} // namespace cdea
