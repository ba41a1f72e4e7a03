// The viscoelastic law's derivatives with respect to its constants at a
// fixed state (stretches l and viscous stretches xi held), for sensitivities
// through time (analysis/creep_sensitivity.h). Branch k's spring (elastic
// stretches a = l / xi, nominal stress t(a) of its law at zero voltage) adds
// t_i / xi_i to the stress; its rate is
//
//   de/dt = M sigma,  sigma_i = a_i t_i,  M = [[2, -1], [-1, 2]] / (6 mu_k tau_k),
//
// so at fixed state
//   d(stress)/d mu_k = (dt/d mu_k)_i / xi_i,
//   d(rate)/d mu_k   = M (a .* dt/d mu_k) - rate / mu_k   (0 for a spring linear in mu_k),
//   d(stress)/d tau_k = 0,   d(rate)/d tau_k = -rate / tau_k,
// and every other branch's stress and rate stay. dt/d mu_k is the spring
// law's own parameter_derivative (shear modulus); a spring law without it
// is refused (false).

#include <cdea/material/two_network_gent.h>

#include <Eigen/Dense>

#include <algorithm>

namespace cdea
{
  bool TwoNetworkGentLaw::evolving_parameter_derivative(const LawInput &in, const double *stored,
                                                        const LawParameter parameter,
                                                        NominalStress &d_stress,
                                                        double        *d_rate) const
  {
    std::fill(d_rate, d_rate + n_evolving(), 0.);
    d_stress       = {0., 0.};
    const int own  = own_constant_index(parameter);
    if (own < 0)
      {
        double d_energy = 0.;
        return parameter_derivative(in, InternalStep{}, parameter, d_energy, d_stress);
      }
    const std::size_t k = std::size_t(own) / 2;
    if (k >= b.size() || !stored)
      return false;
    const ViscousNetwork &n = b[k];
    const double         *s = stored + 4 * k;
    const Eigen::Vector2d xi(s[0], s[1]);
    const Eigen::Vector2d a(in.l1 / xi[0], in.l2 / xi[1]);
    LawResponse           r;
    if (!spring[k]->evaluate({a[0], a[1], 0.}, InternalStep{}, law_stress, r))
      return false;
    Eigen::Matrix2d M;
    M << 2., -1., -1., 2.;
    M /= 6. * n.shear_modulus * n.relaxation_time;
    const Eigen::Vector2d rate = M * Eigen::Vector2d(a[0] * r.stress.s1, a[1] * r.stress.s2);
    Eigen::Vector2d       d    = -rate / n.relaxation_time;
    if (own % 2 == 0)
      {
        double        d_energy = 0.;
        NominalStress dt{0., 0.};
        if (!spring[k]->parameter_derivative({a[0], a[1], 0.}, InternalStep{},
                                             LawParameter::shear_modulus, d_energy, dt))
          return false;
        d_stress = {dt.s1 / xi[0], dt.s2 / xi[1]};
        d = M * Eigen::Vector2d(a[0] * dt.s1, a[1] * dt.s2) - rate / n.shear_modulus;
      }
    d_rate[2 * k]     = d[0];
    d_rate[2 * k + 1] = d[1];
    return true;
  }
} // namespace cdea
