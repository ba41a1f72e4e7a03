// The viscoelastic law's derivatives with respect to its constants at a
// fixed state (stretches l and viscous stretches xi held), for sensitivities
// through time (analysis/creep_sensitivity.h, material/material_point.h).
// Branch k's spring (elastic stretches a = l / xi, nominal stress t(a) of its
// law at zero voltage) adds t_i / xi_i to the stress; its rate is
//
//   de/dt = M sigma,  sigma_i = a_i t_i,  M = [[2, -1], [-1, 2]] / (6 eta),
//   eta = mu_k tau_k phi(e, sigma)   (phi = 1: the Newtonian dashpot),
//
// so at fixed state
//   d(stress)/d mu_k = (dt/d mu_k)_i / xi_i,
//   d(rate)/d mu_k   = M dsigma - rate / mu_k - rate (phi_sigma . dsigma) / phi,
//                      dsigma = a .* dt/d mu_k   (0 for a spring linear in mu_k),
//   d(stress)/d tau_k = 0,   d(rate)/d tau_k = -rate / tau_k,
//   d(stress)/d c = 0,       d(rate_k)/d c = -rate_k (d phi_k / d c) / phi_k
// for a constant c of the shear-thinning viscosity (every branch), and every
// other branch's stress and rate stay. dt/d mu_k is the spring law's own
// parameter_derivative (shear modulus); a spring law without it is refused
// (false).

#include <cdea/material/two_network_gent.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace cdea
{
  namespace
  {
    /// Branch @p n's state at stretches @p in and its four @p stored numbers:
    /// a = l / xi, the spring's stress t(a), sigma = a .* t, e = ln xi, the
    /// viscosity factor phi (with d phi / d sigma) and the rate M(eta) sigma.
    struct BranchState
    {
      Eigen::Vector2d xi, a, t, sigma, e, phi_s = Eigen::Vector2d::Zero(), rate;
      Eigen::Matrix2d M;
      double          phi = 1.;

      bool evaluate(const MembraneLaw &spring, const ViscousNetwork &n,
                    const ShearThinning &thinning, const LawInput &in, const double *stored)
      {
        xi = Eigen::Vector2d(stored[0], stored[1]);
        a  = Eigen::Vector2d(in.l1 / xi[0], in.l2 / xi[1]);
        LawResponse r;
        if (!spring.evaluate({a[0], a[1], 0.}, InternalStep{}, law_stress, r))
          return false;
        t     = Eigen::Vector2d(r.stress.s1, r.stress.s2);
        sigma = a.cwiseProduct(t);
        e     = Eigen::Vector2d(std::log(xi[0]), std::log(xi[1]));
        if (thinning.enabled)
          phi = thinning.factor(e, sigma, nullptr, &phi_s);
        M << 2., -1., -1., 2.;
        M /= 6. * n.shear_modulus * n.relaxation_time * phi;
        rate = M * sigma;
        return true;
      }
    };
  } // namespace

  bool TwoNetworkGentLaw::evolving_parameter_derivative(const LawInput &in, const double *stored,
                                                        const LawParameter parameter,
                                                        NominalStress &d_stress,
                                                        double        *d_rate) const
  {
    std::fill(d_rate, d_rate + n_evolving(), 0.);
    d_stress      = {0., 0.};
    const int own = own_constant_index(parameter);
    if (own < 0)
      {
        double d_energy = 0.;
        return parameter_derivative(in, InternalStep{}, parameter, d_energy, d_stress);
      }
    if (!stored)
      return false;
    if (std::size_t(own) >= 2 * b.size())
      {
        const std::size_t viscosity_constant = std::size_t(own) - 2 * b.size();
        if (!thinning.enabled || viscosity_constant >= ShearThinning::own_constants().size())
          return false;
        for (std::size_t k = 0; k < b.size(); ++k)
          {
            BranchState s;
            if (!s.evaluate(*spring[k], b[k], thinning, in, stored + 4 * k))
              return false;
            const double dphi = thinning.factor_derivative(unsigned(viscosity_constant), s.e, s.sigma);
            if (!std::isfinite(dphi))
              return false;
            d_rate[2 * k]     = -s.rate[0] * dphi / s.phi;
            d_rate[2 * k + 1] = -s.rate[1] * dphi / s.phi;
          }
        return true;
      }
    const std::size_t     k = std::size_t(own) / 2;
    const ViscousNetwork &n = b[k];
    BranchState           s;
    if (!s.evaluate(*spring[k], n, thinning, in, stored + 4 * k))
      return false;
    Eigen::Vector2d d = -s.rate / n.relaxation_time;
    if (own % 2 == 0)
      {
        double        d_energy = 0.;
        NominalStress dt{0., 0.};
        if (!spring[k]->parameter_derivative({s.a[0], s.a[1], 0.}, InternalStep{},
                                             LawParameter::shear_modulus, d_energy, dt))
          return false;
        d_stress                   = {dt.s1 / s.xi[0], dt.s2 / s.xi[1]};
        const Eigen::Vector2d dsig = s.a.cwiseProduct(Eigen::Vector2d(dt.s1, dt.s2));
        d = s.M * dsig - s.rate / n.shear_modulus - s.rate * s.phi_s.dot(dsig) / s.phi;
      }
    d_rate[2 * k]     = d[0];
    d_rate[2 * k + 1] = d[1];
    return true;
  }
} // namespace cdea
