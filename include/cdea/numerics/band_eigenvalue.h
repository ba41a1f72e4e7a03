#pragma once
// The stability check of a state: is the band tangent (its symmetric part,
// the prescribed dofs removed, plus the water's rank-one coupling k g g^T if
// any) positive definite, and what is its smallest eigenvalue (negative:
// unstable with the loads held)?
//
// The decision comes from the inertia of a factorization (Sylvester's law):
// the banded Cholesky of S - sigma I with sigma >= 0 succeeds only when S is
// positive definite, and fails at sigma = 0 exactly when it is not; with
// k > 0 an LDL^T's count of negative pivots and the determinant lemma decide
// for S + k g g^T. The eigenvalue comes from shift-invert Lanczos on the
// same banded Cholesky factors (sigma just below the last state's
// eigenvalue, 0, or below the smallest eigenvalue of an indefinite S), the
// rank-one term by Sherman-Morrison: O(n kd^2) to factor, O(n kd) per
// Lanczos step, where LAPACK's dsbevx (numerics/eigenvalue_reference.h)
// reduces the whole band at O(n^2 kd).

#include <cdea/numerics/band_matrix.h>
#include <cdea/numerics/symmetric_band.h>
#include <cdea/numerics/tangent_solver.h>

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace cdea
{
  /// The stability of a tangent.
  struct TangentStability
  {
    /// Whether the matrix was finite (otherwise the check has no answer).
    bool known = false;
    /// Positive definite, by the inertia of a factorization.
    bool positive_definite = false;
    /// The smallest eigenvalue (NaN when not asked for or not finite).
    double smallest_eigenvalue = std::numeric_limits<double>::quiet_NaN();
  };

  /// Work storage of the Lanczos iterations, kept across calls.
  struct LanczosStorage
  {
    Eigen::MatrixXd     basis;
    Eigen::VectorXd     alpha, beta, w, h, y;
    std::vector<double> pivots;
  };

  /// The check, with its factors, work storage and the last eigenpair kept
  /// across calls: the eigenvector of one state starts the Lanczos iteration
  /// of the next, and the eigenvalue sets its shift (a step along a path
  /// changes both little).
  class StabilityCheck
  {
  public:
    /// The stability of S + k g g^T (k >= 0; g zero at S's excluded dofs,
    /// ignored if k = 0), with its smallest eigenvalue if @p with_eigenvalue.
    TangentStability compute(const SymmetricBand &S, double k, const Eigen::VectorXd &g,
                             bool with_eigenvalue);
    /// The symmetric part of @p A without the rows and columns @p excluded,
    /// plus k g g^T: compute() on it.
    TangentStability compute(const BandMatrix &A, const std::vector<unsigned int> &excluded,
                             double k, const Eigen::VectorXd &g, bool with_eigenvalue);

    /// The stability of S + k g g^T with its smallest eigenvalue only where
    /// it matters: where the state is not positive definite or near a fold.
    /// One Cholesky of S - sigma I at sigma = near_fold_fraction x the last
    /// computed eigenvalue (if that is positive) decides: if it succeeds
    /// (with k > 0: or the inertia and the determinant lemma say that
    /// S + k g g^T - sigma I is positive definite), every eigenvalue is
    /// above sigma > 0: stable, far from a fold, the eigenvalue not computed
    /// (NaN). Otherwise, and before the first eigenvalue, as
    /// compute(..., true), which renews the reference; except where the
    /// state is not positive definite and singular to round-off
    /// (round_off_fraction): eigenvalue NaN, the reference forgotten.
    TangentStability compute_near_folds(const SymmetricBand &S, double k,
                                        const Eigen::VectorXd &g);
    /// The same on the symmetric part of @p A without @p excluded; @p first:
    /// the first state of a run, the reference eigenvalue and the last
    /// answer forgotten.
    TangentStability compute_near_folds(const BandMatrix &A,
                                        const std::vector<unsigned int> &excluded, double k,
                                        const Eigen::VectorXd &g, bool first = false);

    /// The fraction of the last computed eigenvalue below which the
    /// eigenvalue is computed again (compute_near_folds()), and the shift of
    /// the first Cholesky of compute(..., true): 0.8. The same number, so
    /// that where the sign test fails its factorization is the one the
    /// eigenvalue's computation would have started with (nothing is
    /// factored twice); and near a fold, where lambda ~ sqrt(distance to
    /// it), the eigenvalue is reported every time it has fallen by 20 %.
    static constexpr double near_fold_fraction = 0.8;
    /// Near folds, a state that is not positive definite but whose S + delta I
    /// is, delta = round_off_fraction x max |Gershgorin bound| of S, has a
    /// smallest eigenvalue in (-delta, 0]: zero to round-off. It is reported
    /// unstable without the eigenvalue (NaN), and the reference is kept.
    static constexpr double round_off_fraction = 1e-12;

    /// Of the last compute(): Lanczos steps and factorizations (Cholesky,
    /// LDL^T, LU) it took.
    unsigned int lanczos_steps() const { return steps; }
    unsigned int factorizations() const { return n_factorizations; }

  private:
    SymmetricBand   S_own;
    BandCholesky    cholesky;
    BandedLU        lu;
    BandMatrix      full;
    LanczosStorage  storage;
    Eigen::VectorXd spread, start, B_inv_g;
    /// The last eigenpair (empty, NaN before the first).
    Eigen::VectorXd warm;
    double          warm_value = std::numeric_limits<double>::quiet_NaN();
    unsigned int    steps = 0, n_factorizations = 0;
    /// max(|lower|, |upper|) of S's Gershgorin bounds, once per compute()
    /// (NaN until asked for).
    double scale_of_spectrum = std::numeric_limits<double>::quiet_NaN();
    double spectrum_scale(const SymmetricBand &S);

    /// When check() computes the smallest eigenvalue.
    enum class Eigenvalue
    {
      never,
      always,
      near_folds
    };
    /// compute() and compute_near_folds().
    TangentStability check(const SymmetricBand &S, double k, const Eigen::VectorXd &g,
                           Eigenvalue eigenvalue);
    /// Factor S - sigma I (Cholesky) for a sigma that is >= 0 if S is
    /// positive definite: near_fold_fraction x the last eigenvalue if that
    /// is positive, @p warm_shift and the factorization succeeds there, else
    /// 0. Whether S is positive definite.
    bool factor_definite(const SymmetricBand &S, bool warm_shift);
    /// S - shift I as a general band matrix, LU-factored in lu; false if
    /// singular.
    bool factor_lu(const SymmetricBand &S, double shift);
    /// Is S + k g g^T - sigma I positive definite when S - sigma I is not
    /// (k > 0)? By the inertia of S - sigma I and the determinant lemma.
    bool rank_one_definite(const SymmetricBand &S, double k, const Eigen::VectorXd &g,
                           double sigma);
    /// Near folds, for an S + k g g^T that is not positive definite: is
    /// S + delta I positive definite (delta = round_off_fraction x the
    /// spectrum's scale), the smallest eigenvalue then zero to round-off?
    bool singular_to_round_off(const SymmetricBand &S);
    /// Forget the last eigenvalue (near folds: the next
    /// state computes its eigenvalue; the last eigenvector still starts
    /// Lanczos, which changes only the last digits).
    void forget_reference();
    /// Are all eigenvalues of S + k g g^T above @p sigma?
    bool definite_above(const SymmetricBand &S, double k, const Eigen::VectorXd &g,
                        double sigma);
    /// The smallest eigenvalue of S + k g g^T, certified by the inertia just
    /// below it; S_definite: whether cholesky holds the factors of S - sigma I
    /// with sigma below the smallest eigenvalue of S.
    double smallest_eigenvalue(const SymmetricBand &S, double k, const Eigen::VectorXd &g,
                               bool S_definite);
    /// For an S that is not positive definite: the Cholesky factors of
    /// S - sigma I with sigma below its smallest eigenvalue, and the start
    /// vector turned towards that eigenvector; false if none was found.
    bool shift_below_spectrum(const SymmetricBand &S);
    /// The smallest eigenvalue of S + k g g^T from the factors in cholesky
    /// (S - sigma I positive definite), starting from the start vector.
    double smallest_above_shift(const SymmetricBand &S, double k, const Eigen::VectorXd &g);
  };

  /// The smallest eigenvalue of (A + A^T) / 2 without the rows and columns
  /// listed in @p excluded (NaN if not finite); a fresh StabilityCheck.
  double smallest_symmetric_eigenvalue(const BandMatrix                &A,
                                       const std::vector<unsigned int> &excluded);

  /// The same for A + k g g^T (the water's free surface couples every dof,
  /// as in ShermanMorrison), k >= 0.
  double smallest_symmetric_eigenvalue(const BandMatrix &A, double k, const Eigen::VectorXd &g,
                                       const std::vector<unsigned int> &excluded);
} // namespace cdea
