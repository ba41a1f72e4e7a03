#pragma once
// The viscosity of a dashpot of network B (two_network_gent.h): Newtonian,
// eta = eta_0 = mu_k tau_k, or the shear-thinning and strain-stiffening
// viscosity of Kumar and Lopez-Pamies, J. Mech. Phys. Solids 2016 ("On the
// two-potential constitutive modeling of rubber viscoelastic materials"),
//
//   eta = eta_inf + (eta_0 - eta_inf + K1 (I1v^beta1 - 3^beta1)) / (1 + (K2 J2)^beta2),
//
// with I1v = xi1^2 + xi2^2 + xi3^2 (xi3 = 1 / (xi1 xi2)) the first invariant
// of the viscous stretch and J2 = (s1^2 + s2^2 - s1 s2) / 3 the second
// invariant of the deviator of the branch's true stress (s1, s2, 0).
//
// One set of constants serves every branch, relative to the branch's
// viscosity at rest eta_0 = mu_k tau_k: eta = eta_0 phi with
//
//   phi = r + (1 - r + k1 (I1v^beta1 - 3^beta1)) / (1 + (K2 J2)^beta2),
//   r = eta_inf / eta_0,  k1 = K1 / eta_0,
//
// so that a spectrum fitted at small strain (where phi = 1) keeps its moduli
// and relaxation times, and every branch thins by the same law. One branch
// with tau = eta_0 / mu_B is the paper's law. r = 1 and k1 = 0 (or K2 = 0
// and k1 = 0) give phi = 1: the Newtonian dashpot.

#include <cdea/material/membrane_law.h>

#include <Eigen/Core>

#include <vector>

namespace cdea
{
  class ParameterDeclarations;
  struct LawSettings;

  struct ShearThinning
  {
    bool   enabled = false; ///< Material/Viscosity = shear thinning
    double r       = 1.;    ///< eta_inf / eta_0, in (0, 1]
    double k1      = 0.;    ///< K1 / eta_0 (-)
    double beta1   = 1.;
    double k2      = 0.;    ///< K2 (1/Pa^2)
    double beta2   = 1.;

    /// phi at viscous log-strains @p e and branch stresses @p sigma (Pa),
    /// with its partial derivatives d_e (at fixed sigma, through I1v) and
    /// d_sigma (through J2; 0 where J2 = 0, whose infinite derivative for
    /// beta2 < 1/2 always multiplies a vanishing rate).
    double factor(const Eigen::Vector2d &e, const Eigen::Vector2d &sigma,
                  Eigen::Vector2d *d_e = nullptr, Eigen::Vector2d *d_sigma = nullptr) const;

    /// phi at @p e where the rate of e is @p q with viscosity eta_0 phi:
    /// q = sigma / (eta_0 phi N) (N = 2 [[2, 1], [1, 2]]), so J2 = (eta_0
    /// phi)^2 J2(N q) and phi is the root of a scalar equation whose right
    /// side falls as phi grows (bisection on [r, r + 1 - r + k1 (...)]).
    double factor_at_rate(const Eigen::Vector2d &e, const Eigen::Vector2d &q, double eta0) const;

    /// The five constants as a law's own constants (LawConstant: the entries
    /// "Shear thinning eta_inf/eta_0", "... K1/eta_0", "... beta1",
    /// "... K2 (1/kPa^2)", "... beta2" and the intervals a fit keeps them
    /// in, inside the entries' checks), in this order.
    static std::vector<LawConstant> own_constants();
    /// d phi / d(constant @p k of own_constants()), per unit of its entry, at
    /// @p e and @p sigma (fixed):
    ///   d/dr = 1 - 1/D,   d/dk1 = S / D,   d/dbeta1 = k1 (I1v^beta1 ln I1v - 3^beta1 ln 3) / D,
    ///   d/dK2 = -A beta2 p / (K2 D^2),   d/dbeta2 = -A p ln(K2 J2) / D^2,
    /// with S = I1v^beta1 - 3^beta1, A = 1 - r + k1 S, p = (K2 J2)^beta2,
    /// D = 1 + p (K2 per 1/kPa^2: 1e-6 of the per 1/Pa^2 value). NaN where it
    /// is infinite (K2 = 0 with beta2 < 1 and J2 > 0).
    double factor_derivative(unsigned int k, const Eigen::Vector2d &e,
                             const Eigen::Vector2d &sigma) const;

    /// The entries of subsection Material: "Viscosity" (newtonian or shear
    /// thinning) and "Shear thinning eta_inf/eta_0", "... K1/eta_0",
    /// "... beta1", "... K2 (1/kPa^2)", "... beta2" (defaults: VHB 4910 of
    /// Kumar and Lopez-Pamies).
    static void declare_parameters(ParameterDeclarations &prm);
    /// From those entries (read only for shear thinning), checked: an
    /// InputError names the entry and its range.
    static ShearThinning parse(const LawSettings &settings);
  };

  /// One branch's stage residual with the viscosity eta = eta_0 phi(e, s(e)),
  /// s = -W_e:
  ///   G = eta N a + W_e,  a = c (e - e0) - q0  (c = 1/dt, q0 = 0: backward
  ///   Euler; c = 2/dt and the start rate q0: trapezoidal),
  /// its Jacobian dG/de = c eta N + W_ee + (N a) (d eta/de)^T with
  /// d eta/de = eta_0 (phi_e - W_ee phi_s) (unsymmetric), and the frozen part
  /// c eta N + W_ee (symmetric: the Hessian of the incremental potential
  /// with eta held, which the condensed tangent uses).
  struct BranchResidual
  {
    double          eta = 0.;
    Eigen::Vector2d G;
    Eigen::Matrix2d jacobian, frozen;
  };
  BranchResidual branch_residual(const ShearThinning &thinning, double eta0, double c,
                                 const Eigen::Vector2d &e, const Eigen::Vector2d &e0,
                                 const Eigen::Vector2d &q0, const Eigen::Vector2d &W_e,
                                 const Eigen::Matrix2d &W_ee);
} // namespace cdea
