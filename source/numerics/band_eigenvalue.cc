#include <cdea/numerics/band_eigenvalue.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    constexpr double eps = std::numeric_limits<double>::epsilon();

    /// Which end of an operator's spectrum Lanczos looks for.
    enum class End
    {
      top,
      bottom
    };

    /// An extreme eigenvalue of a symmetric operator and its vector.
    struct Ritz
    {
      double          value = nan;
      Eigen::VectorXd vector;
      bool            converged = false;
    };

    /// The Lanczos tridiagonal T: diagonal a[0..m), off-diagonal b[0..m-1).
    class Tridiagonal
    {
    public:
      Tridiagonal(const double *a, const double *b, const unsigned int m)
        : m(m)
        , a(a)
        , b(b)
      {
        for (unsigned int k = 0; k < m; ++k)
          size = std::max(size, std::abs(a[k]) + (k > 0 ? b[k - 1] : 0.) + (k + 1 < m ? b[k] : 0.));
        // The pivot floor of LAPACK's dstebz: safe minimum times max(1, |T|^2).
        floor = std::numeric_limits<double>::min() * std::max(1., size * size);
      }

      /// How many eigenvalues lie below @p x: the negative pivots of T - x I
      /// (Sylvester's law; a pivot below the floor is taken as minus it).
      unsigned int count_below(const double x) const
      {
        unsigned int count = 0;
        double       d     = 1.;
        for (unsigned int k = 0; k < m; ++k)
          {
            d = (a[k] - x) - (k > 0 ? b[k - 1] * b[k - 1] / d : 0.);
            if (std::abs(d) < floor)
              d = -floor;
            count += d < 0.;
          }
        return count;
      }

      /// The eigenpair at @p end by Rayleigh-quotient iteration from @p y
      /// (the last step's Ritz vector, one entry longer now), checked by a
      /// count; by bisection and inverse iteration if it found another.
      double extreme(const End end, double *y, std::vector<double> &work) const
      {
        normalize(y);
        double theta = rayleigh_quotient(y);
        for (int k = 0; k < 8; ++k)
          {
            inverse_step(theta, y, work);
            const double next = rayleigh_quotient(y);
            const bool   done = std::abs(next - theta) <= 4. * eps * std::abs(next);
            theta             = next;
            if (done)
              break;
          }
        const double margin = 8. * eps * std::abs(theta) + 1e-3 * eps * size;
        if (end == End::top ? count_below(theta + margin) == m : count_below(theta - margin) == 0)
          return theta;
        theta = bisect(end == End::top ? m - 1 : 0);
        std::fill(y, y + m, 1.);
        inverse_step(theta, y, work);
        inverse_step(theta, y, work);
        return theta;
      }

      /// Is the eigenvalue next to @p theta (at @p end) at least @p gap away?
      bool separated(const End end, const double theta, const double gap) const
      {
        return end == End::top ? count_below(theta - gap) == m - 1 :
                                 count_below(theta + gap) == 1;
      }

      const unsigned int m;

    private:
      const double *a, *b;
      double        size = 0., floor = 0.;

      /// The eigenvalue with @p below eigenvalues under it, by bisection
      /// between Gershgorin bounds to round-off.
      double bisect(const unsigned int below) const
      {
        double lo = -size, hi = size;
        for (int halving = 0; halving < 128; ++halving)
          {
            const double mid = 0.5 * (lo + hi);
            if (hi - lo <= 2. * eps * std::max(std::abs(lo), std::abs(hi)) || mid <= lo ||
                mid >= hi)
              break;
            (count_below(mid) > below ? hi : lo) = mid;
          }
        return 0.5 * (lo + hi);
      }

      double rayleigh_quotient(const double *y) const
      {
        double q = 0.;
        for (unsigned int k = 0; k < m; ++k)
          q += y[k] * (a[k] * y[k] + 2. * (k + 1 < m ? b[k] * y[k + 1] : 0.));
        return q;
      }

      void normalize(double *y) const
      {
        double norm = 0.;
        for (unsigned int k = 0; k < m; ++k)
          norm += y[k] * y[k];
        norm = std::sqrt(norm);
        for (unsigned int k = 0; k < m; ++k)
          y[k] /= norm;
      }

      /// y <- (T - x I)^-1 y, normalized: elimination from the top, a pivot
      /// at round-off replaced by round-off (inverse iteration wants the
      /// near-singular solve).
      void inverse_step(const double x, double *y, std::vector<double> &d) const
      {
        const double tiny = eps * size + std::numeric_limits<double>::min();
        d.resize(m);
        for (unsigned int k = 0; k < m; ++k)
          {
            d[k] = a[k] - x;
            if (k > 0)
              {
                const double l = b[k - 1] / d[k - 1];
                d[k] -= l * b[k - 1];
                y[k] -= l * y[k - 1];
              }
            if (std::abs(d[k]) < tiny)
              d[k] = tiny;
          }
        for (unsigned int k = m; k-- > 0;)
          y[k] = (y[k] - (k + 1 < m ? b[k] * y[k + 1] : 0.)) / d[k];
        normalize(y);
      }
    };

    /// A Ritz pair (theta, y) of T has converged when its residual
    /// rho = beta |y_last| is small and its value error, at most
    /// rho^2 / gap for a symmetric operator (gap: to the next eigenvalue of
    /// T), is below 1e-12 of it.
    bool converged(const Tridiagonal &T, const End end, const double theta, const double rho)
    {
      const double size = std::abs(theta);
      return T.m > 1 && rho <= 1e-4 * size &&
             T.separated(end, theta, rho * rho / (1e-12 * size));
    }

    /// Lanczos with full reorthogonalization (twice classical Gram-Schmidt)
    /// on the symmetric operator @p apply (v <- Op v) from @p start, for the
    /// eigenvalue at @p end of Op's spectrum; @p dimension: of the space
    /// Op acts on (the free dofs), where the iteration ends exactly.
    /// Restarted from the Ritz vector when the basis (40 vectors) is full,
    /// at most @p restarts times.
    template <typename Apply>
    Ritz lanczos(Apply &&apply, const Eigen::VectorXd &start, const End end,
                 const unsigned int dimension, LanczosStorage &s, unsigned int &steps,
                 const unsigned int restarts = 25)
    {
      const unsigned int m = std::min(dimension, 40u);
      if (s.basis.rows() != start.size() || s.basis.cols() < m)
        s.basis.resize(start.size(), m);
      s.alpha.resize(m);
      s.beta.resize(m);
      s.h.resize(m);
      s.y.resize(m);
      Ritz ritz;
      ritz.vector = start.normalized();
      for (unsigned int restart = 0; restart <= restarts; ++restart)
        {
          s.basis.col(0) = ritz.vector;
          for (unsigned int j = 0; j < m; ++j)
            {
              ++steps;
              const auto Q = s.basis.leftCols(j + 1);
              s.w          = s.basis.col(j);
              apply(s.w);
              s.alpha[j] = s.basis.col(j).dot(s.w);
              for (int pass = 0; pass < 2; ++pass)
                {
                  s.h.head(j + 1).noalias() = Q.transpose() * s.w;
                  s.w.noalias() -= Q * s.h.head(j + 1);
                }
              s.beta[j] = s.w.norm();
              const Tridiagonal T(s.alpha.data(), s.beta.data(), j + 1);
              s.y[j]             = j > 0 ? 0.1 * std::abs(s.y[j - 1]) : 1.;
              const double theta = T.extreme(end, s.y.data(), s.pivots);
              const double rho   = s.beta[j] * std::abs(s.y[j]);
              const bool   exact = j + 1 == dimension || s.beta[j] <= 1e-15 * std::abs(theta);
              const bool   done  = exact || converged(T, end, theta, rho);
              if (done || j + 1 == m)
                {
                  ritz.value = theta;
                  ritz.vector.noalias() = Q * s.y.head(j + 1);
                  ritz.vector.normalize();
                  ritz.converged = done;
                  if (done)
                    return ritz;
                  break;
                }
              s.basis.col(j + 1) = s.w / s.beta[j];
            }
        }
      return ritz;
    }

    /// A start vector without favour: pseudo-random entries, zero at the
    /// excluded dofs.
    void spread_vector(const SymmetricBand &S, Eigen::VectorXd &v)
    {
      v.resize(S.size());
      for (unsigned int i = 0; i < S.size(); ++i)
        {
          const double s = std::sin(12.9898 * (i + 1) + 78.233) * 43758.5453;
          v[i]           = S.excluded(i) ? 0. : s - std::floor(s) - 0.5;
        }
      v.normalize();
    }

    unsigned int n_free(const SymmetricBand &S)
    {
      unsigned int count = 0;
      for (unsigned int i = 0; i < S.size(); ++i)
        count += !S.excluded(i);
      return count;
    }

    bool finite(const SymmetricBand &S)
    {
      const double *a = S.data();
      return std::all_of(a, a + std::size_t(S.bandwidth() + 1) * S.size(),
                         [](const double v) { return std::isfinite(v); });
    }
  } // namespace

  TangentStability StabilityCheck::compute(const BandMatrix                &A,
                                           const std::vector<unsigned int> &excluded,
                                           const double k, const Eigen::VectorXd &g,
                                           const bool with_eigenvalue)
  {
    S_own.assign(A, excluded);
    return check(S_own, k, g, with_eigenvalue ? Eigenvalue::always : Eigenvalue::never);
  }

  TangentStability StabilityCheck::compute(const SymmetricBand &S, const double k,
                                           const Eigen::VectorXd &g, const bool with_eigenvalue)
  {
    return check(S, k, g, with_eigenvalue ? Eigenvalue::always : Eigenvalue::never);
  }

  TangentStability StabilityCheck::compute_near_folds(const BandMatrix                &A,
                                                      const std::vector<unsigned int> &excluded,
                                                      const double k, const Eigen::VectorXd &g,
                                                      const bool first)
  {
    if (first)
      forget_reference();
    S_own.assign(A, excluded);
    return check(S_own, k, g, Eigenvalue::near_folds);
  }

  TangentStability StabilityCheck::compute_near_folds(const SymmetricBand &S, const double k,
                                                      const Eigen::VectorXd &g)
  {
    return check(S, k, g, Eigenvalue::near_folds);
  }

  TangentStability StabilityCheck::check(const SymmetricBand &S, const double k,
                                         const Eigen::VectorXd &g, const Eigenvalue eigenvalue)
  {
    steps = n_factorizations = 0;
    scale_of_spectrum        = nan;
    TangentStability result;
    if (S.size() == 0 || !finite(S) || (k != 0. && !g.allFinite()))
      return result;
    if (spread.size() != S.size())
      {
        spread_vector(S, spread);
        warm.resize(0);
        warm_value = nan;
      }
    result.known = true;
    bool S_definite;
    if (eigenvalue == Eigenvalue::near_folds && warm_value > 0.)
      {
        // Every eigenvalue of S + k g g^T above sigma > 0: stable, and the
        // eigenvalue has not fallen to near_fold_fraction of the last one.
        if (definite_above(S, k, g, near_fold_fraction * warm_value))
          {
            result.positive_definite = true;
            return result;
          }
        // S - sigma I is not positive definite, nor then at the warm shift
        // of compute(): on from the Cholesky at zero.
        S_definite = factor_definite(S, false);
      }
    else
      S_definite = factor_definite(S, eigenvalue != Eigenvalue::never);
    result.positive_definite = S_definite || (k > 0. && rank_one_definite(S, k, g, 0.));
    if (eigenvalue == Eigenvalue::near_folds && !result.positive_definite &&
        singular_to_round_off(S))
      {
        // The next state computes its eigenvalue: on both sides of a change
        // of the stable column one is known or zero to round-off.
        forget_reference();
        return result;
      }
    if (eigenvalue != Eigenvalue::never && n_free(S) > 0)
      result.smallest_eigenvalue = smallest_eigenvalue(S, k, g, S_definite);
    return result;
  }

  bool StabilityCheck::singular_to_round_off(const SymmetricBand &S)
  {
    // Not positive definite, yet S + delta I is (delta = round_off_fraction
    // x the spectrum's scale): every eigenvalue of S, and of S + k g g^T
    // (k >= 0), lies above -delta, and the smallest below zero to
    // round-off, as on the flat, unstretched film. Its value says nothing
    // more than zero; finding it (the search below an indefinite spectrum)
    // would cost more than the rest of the row's checks.
    ++n_factorizations;
    const double delta = round_off_fraction * spectrum_scale(S);
    return delta > 0. && cholesky.factorize(S, -delta);
  }

  void StabilityCheck::forget_reference()
  {
    warm_value = nan;
  }

  double StabilityCheck::smallest_eigenvalue(const SymmetricBand &S, const double k,
                                             const Eigen::VectorXd &g, const bool S_definite)
  {
    // The last eigenvector with a share of the spread vector, so that a
    // mode that has become the lowest is in the start.
    start = warm.size() == S.size() ? Eigen::VectorXd(warm + 1e-2 * spread) : spread;
    for (unsigned int i = 0; i < S.size(); ++i)
      if (S.excluded(i))
        start[i] = 0.;
    if (!S_definite && !shift_below_spectrum(S))
      return nan;
    // Lanczos gives an eigenvalue; the inertia below it tells whether it is
    // the smallest (a start vector that holds little of the lowest mode may
    // converge to the next one first). If not, again from the spread vector
    // with a shift below the one it missed.
    const double scale = spectrum_scale(S);
    double       lambda = nan;
    for (int round = 0; round < 4; ++round)
      {
        lambda             = smallest_above_shift(S, k, g);
        const double shift = cholesky.shift();
        const double below = lambda - (1e-8 * std::abs(lambda) + 1e-13 * scale);
        if (definite_above(S, k, g, below))
          break;
        start = spread;
        for (double distance = std::max({below - shift, 1e-13 * scale,
                                         std::numeric_limits<double>::min()});
             ;
             distance *= 4.)
          {
            ++n_factorizations;
            if (cholesky.factorize(S, below - distance) || distance > 1e3 * scale)
              break;
          }
      }
    return lambda;
  }

  double StabilityCheck::spectrum_scale(const SymmetricBand &S)
  {
    if (std::isnan(scale_of_spectrum))
      {
        const auto [lower, upper] = S.gershgorin_bounds();
        scale_of_spectrum         = std::max(std::abs(lower), std::abs(upper));
      }
    return scale_of_spectrum;
  }

  bool StabilityCheck::definite_above(const SymmetricBand &S, const double k,
                                      const Eigen::VectorXd &g, const double sigma)
  {
    ++n_factorizations;
    return cholesky.factorize(S, sigma) || (k > 0. && rank_one_definite(S, k, g, sigma));
  }

  bool StabilityCheck::factor_definite(const SymmetricBand &S, const bool warm_shift)
  {
    // Lanczos on (S - sigma I)^-1 gains (lambda_2 - sigma) / (lambda_1 - sigma)
    // per step: a shift just below lambda_1 makes it converge in a few steps,
    // and a Cholesky that succeeds at sigma > 0 proves S positive definite.
    if (warm_shift && warm_value > 0.)
      {
        ++n_factorizations;
        if (cholesky.factorize(S, near_fold_fraction * warm_value))
          return true;
      }
    ++n_factorizations;
    return cholesky.factorize(S, 0.);
  }

  bool StabilityCheck::factor_lu(const SymmetricBand &S, const double shift)
  {
    const unsigned int kd = S.bandwidth();
    full.reinit(S.size(), kd);
    for (unsigned int j = 0; j < S.size(); ++j)
      for (unsigned int i = j > kd ? j - kd : 0; i <= j; ++i)
        full(i, j) = full(j, i) = S.entry(i, j) - (i == j ? shift : 0.);
    ++n_factorizations;
    return lu.factorize(full);
  }

  bool StabilityCheck::rank_one_definite(const SymmetricBand &S, const double k,
                                         const Eigen::VectorXd &g, const double sigma)
  {
    // B = S - sigma I: B + k g g^T (k > 0) has as many negative eigenvalues
    // as B or one fewer; det(B + k g g^T) = det(B) (1 + k g^T B^-1 g). With
    // exactly one eigenvalue of B below zero it is positive definite iff
    // 1 + k g^T B^-1 g < 0. A singular B is taken as B - delta I, delta at
    // round-off: its zero eigenvalue becomes negative, and a positive
    // definite B + k g g^T stays so.
    const double scale = spectrum_scale(S);
    for (const double delta : {0., 1e2 * eps * scale + std::numeric_limits<double>::min()})
      {
        ++n_factorizations;
        const Inertia inertia = band_inertia(S, sigma + delta);
        if (inertia.negative + inertia.zero != 1)
          return false;
        Eigen::VectorXd B_inv_g = g;
        if (factor_lu(S, sigma + delta) && lu.solve(B_inv_g))
          return 1. + k * g.dot(B_inv_g) < 0.;
      }
    return false;
  }

  bool StabilityCheck::shift_below_spectrum(const SymmetricBand &S)
  {
    // An estimate of the smallest eigenvalue: the last state's if that was
    // negative, else the negative eigenvalue of S nearest zero (the bottom
    // of S^-1 by its LU, if Lanczos finds it within two bases; near a fold,
    // where S is singular to round-off, it need not). A Cholesky below the
    // estimate succeeds exactly when no eigenvalue lies below its shift.
    double estimate = warm_value < 0. ? warm_value : 0.;
    if (!(warm_value < 0.) && factor_lu(S, 0.))
      {
        const Ritz bottom = lanczos([&](Eigen::VectorXd &v) { lu.solve(v); }, start,
                                    End::bottom, n_free(S), storage, steps, 1);
        if (bottom.converged && bottom.value < 0.)
          {
            estimate = 1. / bottom.value;
            start    = bottom.vector + 1e-2 * spread;
          }
      }
    const double scale = spectrum_scale(S);
    double distance = std::max({1e-3 * std::abs(estimate), 1e-13 * scale,
                                std::numeric_limits<double>::min()});
    for (int attempt = 0; attempt < 64; ++attempt, distance *= 16.)
      {
        ++n_factorizations;
        if (cholesky.factorize(S, estimate - distance))
          return true;
      }
    return false;
  }

  double StabilityCheck::smallest_above_shift(const SymmetricBand &S, const double k,
                                              const Eigen::VectorXd &g)
  {
    // (S - sigma I + k g g^T)^-1 by Sherman-Morrison on the Cholesky factors
    // of B = S - sigma I; its largest eigenvalue is 1 / (lambda_min - sigma).
    // Where g excites a mode that B nearly lacks, gamma = k g^T B^-1 g is
    // large and the two terms of Sherman-Morrison cancel to 1 / gamma of
    // their size: the shift moves down until gamma <= 1e3 (round-off
    // amplified at most that much).
    double gamma = 0.;
    if (k != 0.)
      {
        const double scale = spectrum_scale(S) + k * g.squaredNorm();
        double distance = std::max(1e-13 * scale, std::abs(cholesky.shift()));
        for (int attempt = 0; attempt < 64; ++attempt, distance *= 8.)
          {
            B_inv_g = g;
            cholesky.solve(B_inv_g.data());
            gamma = k * g.dot(B_inv_g);
            if (gamma <= 1e3)
              break;
            ++n_factorizations;
            if (!cholesky.factorize(S, cholesky.shift() - distance))
              break;
          }
      }
    const auto apply = [&](Eigen::VectorXd &v) {
      cholesky.solve(v.data());
      if (k != 0.)
        v -= (k * g.dot(v) / (1. + gamma)) * B_inv_g;
    };
    const Ritz top = lanczos(apply, start, End::top, n_free(S), storage, steps);
    warm           = top.vector;
    warm_value     = cholesky.shift() + 1. / top.value;
    return warm_value;
  }

  double smallest_symmetric_eigenvalue(const BandMatrix                &A,
                                       const std::vector<unsigned int> &excluded)
  {
    return StabilityCheck().compute(A, excluded, 0., Eigen::VectorXd(), true).smallest_eigenvalue;
  }

  double smallest_symmetric_eigenvalue(const BandMatrix &A, const double k,
                                       const Eigen::VectorXd           &g,
                                       const std::vector<unsigned int> &excluded)
  {
    return StabilityCheck().compute(A, excluded, k, g, true).smallest_eigenvalue;
  }
} // namespace cdea
