#pragma once
// Singly diagonally implicit Runge-Kutta methods with an explicit first stage
// (ESDIRK) and an embedded error estimate, for the time integration of
// doc/time.md. Each is a Butcher tableau (A, b = last row of A, c) with
//
//   Y_1 = y_n,  Y_i = y_n + h sum_{j<i} a_ij K_j + h gamma K_i,  K_i = f(t_n + c_i h, Y_i),
//   y_{n+1} = Y_s,  error estimate  h sum_j (b_j - bhat_j) K_j,
//
// so that every implicit stage is a backward Euler step of length gamma h from
// the start Yhat_i = y_n + h sum_{j<i} a_ij K_j, and the last stage is the
// solution (stiffly accurate: an index-1 DAE such as the membrane's massless
// unknowns is solved exactly at every stage). K_1 is the rate at the end of
// the last step. Both methods are L-stable and have stage order 2
// (sum_j a_ij c_j = c_i^2 / 2).
//
//  - esdirk3: 3 implicit stages, order 3, embedded order 2. gamma is the root
//    of x^3 - 3 x^2 + 3/2 x - 1/6 near 0.4359 (R(-inf) = 0), c = (0, 2 gamma,
//    3/5, 1); a3j from the row sum and the stage order, b from the order
//    conditions (the tableau of Kennedy and Carpenter's ESDIRK3(2)4L[2]SA,
//    NASA/TM-2001-211038). Embedded: sum (b - bhat) = 0, (b - bhat).c = 0,
//    (b - bhat).c^2 = -1/6 and bhat bounded at z -> -inf.
//  - esdirk4: 5 implicit stages, order 4, embedded order 3, gamma = 1/4,
//    c = (0, 1/2, (2 - sqrt 2)/4, 5/8, 26/25, 1) as in Kennedy and
//    Carpenter's ESDIRK4(3)6L[2]SA; a42 = -0.101 and a52 = -0.607 chosen, the
//    other a_ij from the row sums and the stage order, b from the five order
//    conditions left (sum b c^k = 1/(k+1), k < 4, b.A c^2 = 1/12), a53 from
//    R(-inf) = 0. Embedded: order 3 with (b - bhat).c^3 = -1/10, bounded and
//    L-stable (Rhat(-inf) = 0).
// The coefficients were computed for this project at 40 digits (the
// derivation is in tests/test_esdirk.cc's comment); the test checks the order
// conditions, the stage order, L-stability and the order of convergence.

#include <string>
#include <vector>

namespace cdea
{
  /// How a time run steps: the fixed-step schemes of earlier versions (the
  /// dashpots by backward Euler or the trapezoidal rule, the masses by
  /// Newmark's average acceleration) or an ESDIRK tableau for all of it.
  enum class TimeMethod
  {
    backward_euler,
    trapezoidal,
    esdirk3,
    esdirk4
  };

  /// Steps of an ESDIRK method: from its error estimate against the
  /// tolerances, or fixed (at most the maximum step, landing on breakpoints).
  enum class TimeStepControl
  {
    error,
    fixed
  };

  struct EsdirkTableau
  {
    std::string name;
    /// Lower triangle by rows, a[i][j] for j <= i (a[0] = {0}).
    std::vector<std::vector<double>> a;
    std::vector<double>              b_hat; ///< embedded weights
    std::vector<double>              c;
    double                           gamma = 0.;
    unsigned int                     order = 0, embedded_order = 0;

    unsigned int stages() const { return static_cast<unsigned int>(c.size()); }
    /// b_j = a[s - 1][j] (stiffly accurate).
    double b(const unsigned int j) const { return a.back()[j]; }
    /// b_j - bhat_j: the weights of the error estimate.
    double error_weight(const unsigned int j) const { return b(j) - b_hat[j]; }
  };

  const EsdirkTableau &esdirk3();
  const EsdirkTableau &esdirk4();
  /// The tableau of @p method; nullptr for the fixed-step schemes.
  const EsdirkTableau *esdirk_tableau(TimeMethod method);
} // namespace cdea
