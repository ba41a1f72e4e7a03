#pragma once
// Viscoelastic ideal dielectric: the two-network (rheological) model of Hong,
// J. Mech. Phys. Solids 59 (2011) 637, and Zhao, Koh and Suo, Int. J. Appl.
// Mech. 3 (2011) 203, for an incompressible membrane.
//
// Network A, a Gent spring (mu_A, Jlim_A), carries the long-time response; in
// parallel, network B is a Gent spring (mu_B, Jlim_B) in series with a
// Newtonian dashpot of viscosity eta. The dashpot's stretches xi1, xi2
// (xi3 = 1 / (xi1 xi2)) are internal variables; spring B sees the elastic
// stretches a_i = l_i / xi_i. With the voltage term of the ideal dielectric,
//
//   W = W_A(l1, l2) + W_B(a1, a2) - (eps / 2) (Phi l1 l2 / H)^2.
//
// A relaxation spectrum: network B may be several such branches k in
// parallel (a Prony series), each its own spring (any elastic law of the
// library at zero voltage, with mu_k and Jlim_k; Gent by default), its own
// dashpot (eta_k = mu_k tau_k) and its own xi; W sums W_k(l / xi_k), and
// every formula below holds branch by branch (the branches couple only
// through l). One branch is the two-network model.
//
// Evolution: the dashpot's deviatoric rate equals its deviatoric stress over
// 2 eta, with spring B's in-plane true stresses sigma_i = a_i dW_B/da_i
// (sigma_3 = 0). In the viscous log-strains e_i = ln xi_i this is
//
//   de/dt = M sigma,   M = [[2, -1], [-1, 2]] / (6 eta),   eta = mu_B tau,
//
// which for the equi-biaxial film is Zhao, Koh and Suo's
// dxi/dt = xi (mu_B / 6 eta) (l^2 xi^-2 - l^-4 xi^4) / g_B. Since sigma = -dW_B/de,
// the flow is a gradient flow, dissipating sigma . M sigma >= 0.
//
// Time integration over a step dt (InternalStep), as minimisation of an
// incremental potential over e, so that the algorithmic stress is
// dPsi/dl and the consistent tangent is symmetric:
//   backward Euler:  Psi = W + (e - e0)^T M^-1 (e - e0) / (2 dt);
//   trapezoidal:     Psi = W + (e - e0)^T M^-1 (e - e0) / dt - (M^-1 q0) . (e - e0),
// where q0 = de/dt at the start of the step (second order; not L-stable, so
// a relaxation time much shorter than dt leaves an oscillating error).
// Stationarity G(e) = dPsi/de = 0 is solved at every point by Newton's
// method on the 2 x 2 system; then
//   stress = dW/dl at e,   tangent = W_ll - W_le H^-1 W_el,   H = dG/de.
// dt = 0 holds xi fixed (instantaneous, "glassy" response); dt = +infinity
// relaxes network B completely (xi = l, W_B = 0: network A alone).
//
// Internal variables per point (declared in the constructor), four per
// branch: xi1, xi2 (the results hold them) and q1, q2 with q = de/dt at the
// end of the step (1/s), which the trapezoidal rule needs; the first branch's
// are named xi1, xi2, q1, q2, branch k's (k >= 2) xi1_bk, xi2_bk, q1_bk, q2_bk.
//
// Registered as Material/Model = viscoelastic (law_factory.h): network A is
// the film's Gent law, network B's constants are entries of subsection
// Material that the law declares itself (one branch, or the lists of
// "Branch shear moduli (kPa)" etc.).
//
// Optionally every dashpot's viscosity thins with the branch's stress and
// stiffens with its viscous stretch (viscosity.h, Material/Viscosity = shear
// thinning). The local update then solves the exact stage residual (no longer
// stationarity of a potential), and the tangent is the condensed one above
// with eta held at the update's value: symmetric but inexact, so the global
// Newton converges linearly (tangent_is_exact() false); evaluate()'s energy
// is then Psi with eta held, not a potential of the stress.

#include <cdea/material/membrane_law.h>
#include <cdea/material/viscosity.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  struct LawSettings;

  /// Spring B and the dashpot: one branch of network B.
  struct ViscousNetwork
  {
    double shear_modulus   = 0.; ///< mu_B (Pa)
    double jlim            = 0.; ///< Jlim_B (-)
    double relaxation_time = 0.; ///< tau = eta / mu_B (s)
  };

  /// An elastic law as a branch's spring, evaluated at zero voltage.
  using SpringLaw = std::shared_ptr<const MembraneLaw>;

  /// At most this many branches (the entries' check): 4 internal variables
  /// each at every quadrature point.
  constexpr unsigned int max_viscous_branches = 20;

  /// The name of branch @p k's (from 1) modulus ("Branch 1 shear modulus
  /// (Pa)") or relaxation time ("Branch 1 relaxation time (s)") as a law
  /// constant (LawSettings::constants, a fit's free parameter).
  std::string branch_constant_entry(unsigned int k, bool relaxation_time);

  /// @p branches with the values of branch_constant_entry() that @p
  /// constants holds (SI), each checked as the list entries are; InputError
  /// for a branch beyond the list.
  void set_branch_constants(const std::map<std::string, double> &constants,
                            double network_a_shear_modulus, std::vector<ViscousNetwork> &branches);

  class TwoNetworkGentLaw final : public MembraneLaw
  {
  public:
    /// @p network_a: mu_A, Jlim_A and the dielectric (permittivity, thickness).
    TwoNetworkGentLaw(const MaterialConstants &network_a, const ViscousNetwork &network_b);
    /// Network B as @p branches in parallel (at least one), with @p springs
    /// (one per branch; empty: the Gent law of each branch's mu and Jlim).
    TwoNetworkGentLaw(const MaterialConstants &network_a, std::vector<ViscousNetwork> branches,
                      std::vector<SpringLaw> springs = {}, ShearThinning thinning = {});

    /// Network B's entries of subsection Material: "Network B shear modulus
    /// (kPa)", "Network B Jlim", "Relaxation time (s)" (one branch), or the
    /// lists "Branch shear moduli (kPa)", "Branch relaxation times (s)",
    /// "Branch Jlim" (branches; empty: the one branch), and "Branch law".
    static void declare_parameters(ParameterDeclarations &prm);
    /// Network B from those entries (checked: InputError naming the entry
    /// and its range), network A the film's Gent law.
    static std::shared_ptr<const MembraneLaw> create(const LawSettings &settings);

    /// Energy is the incremental potential Psi of the step (W itself for
    /// dt = 0); false outside either Gent limit or if the local update fails.
    bool evaluate(const LawInput &input, const InternalStep &step, unsigned int request,
                  LawResponse &response) const override;

    /// Network A's constants, the permittivity and the voltage: spring B and
    /// the update of e do not depend on them, so these are network A's.
    bool parameter_derivative(const LawInput &input, const InternalStep &step,
                              LawParameter parameter, double &d_energy,
                              NominalStress &d_stress) const override;

    /// The branches' moduli and relaxation times in the order [mu_1 (Pa),
    /// tau_1 (s), mu_2, tau_2, ...]: own_constant(2 (k - 1)) is mu_k,
    /// own_constant(2 (k - 1) + 1) tau_k (two_network_constants.cc); with a
    /// shear-thinning viscosity then its five constants (viscosity.h).
    std::vector<LawConstant> own_constants() const override;

    /// Network A's limit (spring B's depends on the viscous stretches).
    double max_hoop_stretch(double l1) const override;

    /// False with a shear-thinning viscosity (the tangent holds eta fixed).
    bool tangent_is_exact() const override { return !thinning.enabled; }

    /// (e - e0)^T M^-1 (e - e0) / dt: the dashpot's work over a step of
    /// either scheme (exact rate times dt for backward Euler, the mean of the
    /// end rates for the trapezoidal rule); 0 for dt = 0 or infinity.
    double dissipation(const InternalStep &step) const override;

    /// y = (ln xi1, ln xi2) of each branch, rate (q1, q2) as stored at the
    /// end of a step.
    unsigned int n_evolving() const override { return 2 * n_branches(); }
    void         evolving_state(const double *stored, double *y, double *rate) const override;
    void         set_evolving_state(const double *y, double *stored) const override;
    /// q^T M^-1 q: the dashpot's power at the stored rate.
    double dissipation_rate(const double *stored) const override;
    /// With W the total energy at the stored xi: instantaneous = W_ll,
    /// stress_y = W_le, rate_y = -M W_ee, rate_l = -M W_el (de/dt = -M W_e);
    /// rate_y is block diagonal, a 2 x 2 block per branch.
    bool linearize(const LawInput &input, const double *stored,
                   InternalLinearization &out) const override;
    /// Network A's constants as parameter_derivative(), no rate; branch k's
    /// mu_k = own_constant(2(k-1)) (Pa) and tau_k = own_constant(2(k-1)+1)
    /// (s), and the shear-thinning constants (no stress, every branch's
    /// rate): source/material/two_network_parameters.cc.
    bool evolving_parameter_derivative(const LawInput &input, const double *stored,
                                       LawParameter parameter, NominalStress &d_stress,
                                       double *d_rate) const override;

    const MaterialConstants &network_a() const { return a; }
    /// The first branch (network B of the two-network model).
    const ViscousNetwork              &network_b() const { return b.front(); }
    const std::vector<ViscousNetwork> &branches() const { return b; }
    unsigned int n_branches() const { return static_cast<unsigned int>(b.size()); }

  private:
    /// Branch @p k's dashpot power q^T M^-1 q at its four @p stored numbers.
    double branch_power(std::size_t k, const double *stored) const;

    MaterialConstants           a;
    std::vector<ViscousNetwork> b;
    std::vector<SpringLaw>      spring; ///< of each branch
    ShearThinning               thinning;
  };
} // namespace cdea
