#pragma once
// The symmetric part of a band tangent and its factorizations, for the
// stability check: a state is stable when the tangent (with the loads held
// and the prescribed dofs removed) is positive definite, which by Sylvester's
// law of inertia is what a symmetric factorization tells at O(n kd^2)
// without any eigenvalue. A banded Cholesky (LAPACK dpbtrf) succeeds exactly
// when the matrix is positive definite; an LDL^T without pivoting counts the
// negative eigenvalues (its negative pivots).

#include <cdea/numerics/band_matrix.h>

#include <utility>
#include <vector>

namespace cdea
{
  /// S = (A + A^T) / 2 of a BandMatrix A in LAPACK's upper band storage,
  /// ab[(kd + i - j) + j (kd + 1)] = S(i, j) for j - kd <= i <= j. Excluded
  /// dofs are decoupled: row and column zero, a positive diagonal (the
  /// largest |S_ii|), so that they add positive pivots to any factorization
  /// of S - shift I with the shift below the rest's smallest eigenvalue
  /// (which is at most every S_ii) and stay out of every Krylov space
  /// started without them.
  class SymmetricBand
  {
  public:
    /// The symmetric part of @p A without the dofs in @p excluded.
    void assign(const BandMatrix &A, const std::vector<unsigned int> &excluded);
    /// An n x n symmetric band matrix of bandwidth kd, all zero (then fill with set()).
    void reinit(unsigned int n, unsigned int kd);
    /// S(i, j) = S(j, i) = @p value, |i - j| <= kd.
    void set(unsigned int i, unsigned int j, double value);
    /// S(i, j), zero outside the band.
    double entry(unsigned int i, unsigned int j) const;

    unsigned int size() const { return n; }
    unsigned int bandwidth() const { return kd; }
    const double *data() const { return ab.data(); }
    /// Whether dof i is one of the excluded (decoupled) dofs.
    bool excluded(const unsigned int i) const { return !free[i]; }

    /// y = S x.
    void vmult(const double *x, double *y) const;
    /// Gershgorin bounds: every eigenvalue lies in [lower, upper].
    double gershgorin_lower() const;
    double gershgorin_upper() const;
    /// Both, in one pass: {lower, upper}.
    std::pair<double, double> gershgorin_bounds() const;

  private:
    unsigned int                                    n = 0, kd = 0;
    std::vector<double, LargePageAllocator<double>> ab;
    std::vector<char>                               free;
  };

  /// Banded Cholesky S - shift I = U^T U, in place in the band storage (the
  /// algorithm of LAPACK's dpbtf2/dpbtrs, without its calls per column: at
  /// the bandwidths of the FE tangents those calls cost more than the
  /// arithmetic).
  class BandCholesky
  {
  public:
    /// Factor S - @p shift I; true exactly when it is positive definite (to
    /// working precision: a pivot at round-off level may go either way).
    bool factorize(const SymmetricBand &S, double shift);
    /// b <- (S - shift I)^-1 b with the last successful factorization.
    void solve(double *b) const;
    double shift() const { return shift_; }

  private:
    unsigned int                                    n = 0, kd = 0;
    double                                          shift_ = 0.;
    std::vector<double, LargePageAllocator<double>> ab;
    std::vector<double>                             work;
  };

  /// Inertia of S - shift I: how many eigenvalues are negative, zero
  /// (a pivot exactly zero) and positive.
  struct Inertia
  {
    unsigned int negative = 0, zero = 0, positive = 0;
  };

  /// The inertia of S - @p shift I from the pivots of its LDL^T without
  /// pivoting (Sylvester's law: D has as many negative entries as S - shift I
  /// has negative eigenvalues). O(n kd^2). Exact for the factored matrix;
  /// without pivoting a tiny pivot may amplify round-off, so it is used where
  /// a Cholesky cannot answer (more than zero negative eigenvalues).
  Inertia band_inertia(const SymmetricBand &S, double shift);
} // namespace cdea
