// The two-network viscoelastic law (two_network_gent.h) at single material
// points, for both schemes and a range of time steps and states:
//  - the algorithmic stress against central differences of the law's energy
//    (the incremental potential), the consistent tangent against differences
//    of the stress;
//  - an independent Sacado second-order AD of the incremental potential
//    Psi(l, e), written out here from Gent's energy: the updated e is
//    stationary, the stress is dPsi/dl and the tangent Psi_ll - Psi_le
//    Psi_ee^-1 Psi_el;
//  - the limits: dt = infinity relaxes (network A's stress), dt = 0 holds xi,
//    xi = l is a fixed point of every step;
//  - the equi-biaxial rate of Zhao, Koh and Suo (2011),
//    dxi/dt = xi mu_B / (6 eta) (l^2 xi^-2 - l^-4 xi^4) / g_B, for a small step;
//  - dissipation >= 0 and parameter derivatives equal to network A's.

#include <Sacado.hpp>

#include <cdea/material/gent_law.h>
#include <cdea/material/two_network_gent.h>

#include "check.h"

#include <cmath>
#include <limits>
#include <vector>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_close;

namespace
{
  const MaterialConstants network_a{25.1e3, 270., 3.98e-11, 1e-3};
  const ViscousNetwork    network_b{45e3, 60., 2.};

  struct Point
  {
    double l1, l2, voltage;
    double xi1, xi2, q1, q2; ///< old internal variables
  };

  LawResponse evaluate(const TwoNetworkGentLaw &law, const double l1, const double l2,
                       const Point &p, const double dt, const TimeScheme scheme,
                       std::vector<double> *current = nullptr)
  {
    const double        old[4] = {p.xi1, p.xi2, p.q1, p.q2};
    std::vector<double> scratch(4, 0.);
    LawResponse         r;
    const bool ok = law.evaluate({l1, l2, p.voltage}, {old, scratch.data(), dt, scheme},
                                 law_energy | law_stress | law_tangent, r);
    if (!ok)
      r.energy = std::numeric_limits<double>::quiet_NaN();
    if (current)
      *current = scratch;
    return r;
  }

  /// The incremental potential written independently with Sacado numbers:
  /// x = (l1, l2, e1, e2).
  template <typename Number>
  Number potential(const Number *x, const Point &p, const double dt, const TimeScheme scheme)
  {
    const GentDielectric a(network_a, p.voltage);
    const GentDielectric b({network_b.shear_modulus, network_b.jlim, 0., 1.}, 0.);
    const Number         W = a.energy(x[0], x[1]) + b.energy(Number(x[0] / exp(x[2])),
                                                           Number(x[1] / exp(x[3])));
    // M^-1 = 2 eta [[2, 1], [1, 2]]
    const double eta = network_b.shear_modulus * network_b.relaxation_time;
    const Number d1 = x[2] - std::log(p.xi1), d2 = x[3] - std::log(p.xi2);
    const Number quad = 2. * eta * (2. * d1 * d1 + 2. * d1 * d2 + 2. * d2 * d2);
    if (scheme == TimeScheme::backward_euler)
      return W + 0.5 * quad / dt;
    const double f1 = 2. * eta * (2. * p.q1 + p.q2), f2 = 2. * eta * (p.q1 + 2. * p.q2);
    return W + quad / dt - f1 * d1 - f2 * d2;
  }
} // namespace

CDEA_TEST_MAIN()
{
  const TwoNetworkGentLaw law(network_a, network_b);
  const std::vector<Point> points = {
    {2.5, 2.5, 0., 2.5, 2.5, 0., 0.},           // relaxed, no voltage
    {3.1, 2.2, 5e3, 2.7, 2.4, 0.05, -0.02},     // stretched beyond xi, charged
    {1.6, 3.4, 3e3, 2.0, 2.9, -0.1, 0.08},      // compressed meridian
    {4.0, 1.8, 6e3, 3.2, 1.5, 0.0, 0.3}};       // far from relaxed

  double worst_fd_stress = 0., worst_fd_tangent = 0., worst_ad = 0., worst_stationary = 0.;
  const double scale = 10. * network_a.shear_modulus;
  for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::trapezoidal})
    for (const double dt : {1e-3, 0.05, 1., 30.})
      for (const Point &p : points)
        {
          std::vector<double> current;
          const LawResponse   r = evaluate(law, p.l1, p.l2, p, dt, scheme, &current);
          if (!check(std::isfinite(r.energy), "law evaluates"))
            continue;

          // Central differences of the energy and of the stress.
          const double h  = 1e-6;
          const auto   at = [&](const double a, const double b) {
            return evaluate(law, a, b, p, dt, scheme);
          };
          const double ds1 = (at(p.l1 + h, p.l2).energy - at(p.l1 - h, p.l2).energy) / (2 * h);
          const double ds2 = (at(p.l1, p.l2 + h).energy - at(p.l1, p.l2 - h).energy) / (2 * h);
          const LawResponse r1p = at(p.l1 + h, p.l2), r1m = at(p.l1 - h, p.l2);
          const LawResponse r2p = at(p.l1, p.l2 + h), r2m = at(p.l1, p.l2 - h);
          for (const double e : {r.stress.s1 - ds1, r.stress.s2 - ds2})
            worst_fd_stress = std::max(worst_fd_stress, std::abs(e) / scale);
          for (const double e : {r.tangent.s11 - (r1p.stress.s1 - r1m.stress.s1) / (2 * h),
                                 r.tangent.s12 - (r2p.stress.s1 - r2m.stress.s1) / (2 * h),
                                 r.tangent.s12 - (r1p.stress.s2 - r1m.stress.s2) / (2 * h),
                                 r.tangent.s22 - (r2p.stress.s2 - r2m.stress.s2) / (2 * h)})
            worst_fd_tangent = std::max(worst_fd_tangent, std::abs(e) / scale);

          // Sacado: Psi(l, e) at the law's updated e.
          using Fad  = Sacado::Fad::DFad<double>;
          using Fad2 = Sacado::Fad::DFad<Fad>;
          const double values[4] = {p.l1, p.l2, std::log(current[0]), std::log(current[1])};
          Fad2         x[4];
          for (int i = 0; i < 4; ++i)
            x[i] = Fad2(4, i, Fad(4, i, values[i]));
          const Fad2 psi = potential(x, p, dt, scheme);
          // Stationary in e (G = dPsi/de = 0), relative to mu_B.
          for (int i = 2; i < 4; ++i)
            worst_stationary =
              std::max(worst_stationary, std::abs(psi.dx(i).val()) / network_b.shear_modulus);
          // Condensed tangent.
          double Pee[2][2], Ple[2][2], Pll[2][2];
          for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
              {
                Pll[i][j] = psi.dx(i).dx(j);
                Ple[i][j] = psi.dx(i).dx(2 + j);
                Pee[i][j] = psi.dx(2 + i).dx(2 + j);
              }
          const double det     = Pee[0][0] * Pee[1][1] - Pee[0][1] * Pee[1][0];
          const double inv[2][2] = {{Pee[1][1] / det, -Pee[0][1] / det},
                                    {-Pee[1][0] / det, Pee[0][0] / det}};
          double K[2][2];
          for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
              {
                K[i][j] = Pll[i][j];
                for (int k = 0; k < 2; ++k)
                  for (int l = 0; l < 2; ++l)
                    K[i][j] -= Ple[i][k] * inv[k][l] * Ple[j][l];
              }
          for (const double e : {r.stress.s1 - psi.dx(0).val(), r.stress.s2 - psi.dx(1).val(),
                                 r.tangent.s11 - K[0][0], r.tangent.s12 - K[0][1],
                                 r.tangent.s22 - K[1][1]})
            worst_ad = std::max(worst_ad, std::abs(e) / scale);
          check(law.dissipation({nullptr, nullptr, dt, scheme}) == 0., "no dissipation without state");
          const double old[4] = {p.xi1, p.xi2, p.q1, p.q2};
          check(law.dissipation({old, current.data(), dt, scheme}) >= 0., "dissipation >= 0");
        }
  check_close(worst_fd_stress, 0., 1e-7, "stress vs differences of the incremental potential");
  check_close(worst_fd_tangent, 0., 1e-6, "consistent tangent vs differences of the stress");
  check_close(worst_stationary, 0., 1e-11, "updated xi makes the potential stationary (Sacado)");
  check_close(worst_ad, 0., 1e-11, "stress and condensed tangent vs Sacado AD");

  // Limits.
  const Point          p{3.1, 2.2, 5e3, 2.7, 2.4, 0.05, -0.02};
  const GentDielectric a(network_a, p.voltage);
  std::vector<double>  current;
  LawResponse          r = evaluate(law, p.l1, p.l2, p, std::numeric_limits<double>::infinity(),
                                    TimeScheme::backward_euler, &current);
  check_close(r.stress.s1, a.stress(p.l1, p.l2).s1, 1e-12 * scale, "dt = inf: network A's s1");
  check_close(r.stress.s2, a.stress(p.l1, p.l2).s2, 1e-12 * scale, "dt = inf: network A's s2");
  check(current[0] == p.l1 && current[1] == p.l2 && current[2] == 0. && current[3] == 0.,
        "dt = inf: xi = l, no rate");
  double relaxed[4];
  law.relaxed_internal_variables({p.l1, p.l2, p.voltage}, relaxed);
  check(relaxed[0] == p.l1 && relaxed[1] == p.l2, "relaxed_internal_variables gives xi = l");

  r = evaluate(law, p.l1, p.l2, p, 0., TimeScheme::trapezoidal, &current);
  check(current[0] == p.xi1 && current[1] == p.xi2, "dt = 0 holds xi");
  {
    // Spring B's own nominal stress at a = l / xi, over xi.
    const GentDielectric b({network_b.shear_modulus, network_b.jlim, 0., 1.}, 0.);
    const NominalStress  sb = b.stress(p.l1 / p.xi1, p.l2 / p.xi2);
    check_close(r.stress.s1, a.stress(p.l1, p.l2).s1 + sb.s1 / p.xi1, 1e-12 * scale,
                "dt = 0: s1 = s1_A + s1_B(l / xi) / xi1");
  }

  for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::trapezoidal})
    {
      const Point rest{2.8, 2.1, 4e3, 2.8, 2.1, 0., 0.};
      r = evaluate(law, rest.l1, rest.l2, rest, 0.3, scheme, &current);
      check_close(std::abs(current[0] - rest.l1) + std::abs(current[1] - rest.l2), 0., 1e-14,
                  "xi = l stays (spring B unstrained is an equilibrium)");
      check_close(r.stress.s1, GentDielectric(network_a, rest.voltage).stress(rest.l1, rest.l2).s1,
                  1e-9 * scale, "and the stress is network A's");
    }

  // Equi-biaxial rate against the closed form of Zhao, Koh and Suo.
  {
    const double lam = 3.0, xi = 2.6, dt = 1e-7;
    const Point  e{lam, lam, 0., xi, xi, 0., 0.};
    evaluate(law, lam, lam, e, dt, TimeScheme::backward_euler, &current);
    const double eta   = network_b.shear_modulus * network_b.relaxation_time;
    const double gB    = 1. - (2. * lam * lam / (xi * xi) + std::pow(xi / lam, 4) - 3.) /
                              network_b.jlim;
    const double rate  = xi * network_b.shear_modulus / (6. * eta) *
                        (lam * lam / (xi * xi) - std::pow(xi, 4) / std::pow(lam, 4)) / gB;
    check_close((current[0] - xi) / dt / rate, 1., 1e-5, "equi-biaxial dxi/dt (xi1)");
    check_close((current[1] - xi) / dt / rate, 1., 1e-5, "equi-biaxial dxi/dt (xi2)");
    check_close(current[2] * xi / rate, 1., 1e-5, "stored rate q = dln xi / dt");
  }

  // Parameter derivatives are network A's.
  {
    const GentDielectricLaw elastic(network_a);
    const double            old[4] = {p.xi1, p.xi2, p.q1, p.q2};
    double                  s[4]   = {0., 0., 0., 0.};
    for (const LawParameter q : {LawParameter::shear_modulus, LawParameter::jlim,
                                 LawParameter::permittivity, LawParameter::voltage})
      {
        double        dW = 0., dW_a = 0.;
        NominalStress ds{0., 0.}, ds_a{0., 0.};
        const bool    ok = law.parameter_derivative({p.l1, p.l2, p.voltage}, {old, s, 0.05},
                                                    q, dW, ds);
        elastic.parameter_derivative({p.l1, p.l2, p.voltage}, {}, q, dW_a, ds_a);
        check(ok && dW == dW_a && ds.s1 == ds_a.s1 && ds.s2 == ds_a.s2,
              "parameter derivative equals network A's");
      }
  }
  return cdea_test::finish();
}
