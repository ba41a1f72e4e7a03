#pragma once
// A complex square band matrix in LAPACK's band layout (as BandMatrix) and
// its LU factorization (zgbtrf/zgbtrs), with a rank-one update
// A + k g g^T solved by Sherman-Morrison: the small-signal system
// K(omega) - omega^2 M of the frequency response (fe/linear_dynamics.h).

#include <cdea/numerics/band_matrix.h>

#include <Eigen/Core>

#include <complex>
#include <vector>

namespace cdea
{
  class ComplexBandLU
  {
  public:
    using Complex = std::complex<double>;

    /// A zero matrix of size @p n and bandwidth @p bw.
    void reinit(unsigned int n, unsigned int bw);
    /// this = @p real (same size and bandwidth); the imaginary part zero.
    void assign(const BandMatrix &real);
    /// Entry (i, j) with |i - j| <= bandwidth.
    Complex &operator()(const unsigned int i, const unsigned int j)
    {
      return values[(2 * bw + i - j) + std::size_t(j) * (3 * bw + 1)];
    }

    /// Factor A + k g g^T (k = 0: A alone); false if singular.
    bool factorize(Complex k = 0., const Eigen::VectorXd &g = Eigen::VectorXd());
    /// b <- (A + k g g^T)^-1 b for every column of @p b.
    bool solve(Eigen::MatrixXcd &b) const;

  private:
    unsigned int         n = 0, bw = 0;
    std::vector<Complex> values;
    std::vector<int>     pivots;
    Complex              k = 0.;
    Eigen::VectorXcd     g, A_inv_g;
    bool                 factorized = false;

    bool solve_plain(Eigen::MatrixXcd &b) const;
  };
} // namespace cdea
