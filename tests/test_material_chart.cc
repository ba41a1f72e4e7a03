// The material charts of `cdea chart` (material/material_chart.h) against
// closed forms (doc/materials.md, "Material charts"):
//
// stress-stretch, nominal stress s1 at zero voltage,
//   neo-Hooke  uniaxial mu (L - L^-2), l2 = L^-1/2;  equibiaxial mu (L - L^-5)
//   Gent       the same over g = 1 - (I1 - 3) / Jlim, I1 = L^2 + 2/L (uniaxial),
//              2 L^2 + L^-4 (equibiaxial); the curves end at 99 % of the way
//              to the locking stretch, where I1 - 3 = Jlim
//   viscoelastic (two Gent networks) relaxed: network A alone;
//              instantaneous: both springs in parallel
// the DMA chart of the two-network law, the standard linear solid with
// E_A = 3 mu_A, E_B = 3 mu_B and tau of the parameters (x = w tau):
//   E' = E_A + E_B x^2 / (1 + x^2),  E'' = E_B x / (1 + x^2),
//   limits E_A (w -> 0) and E_A + E_B (w -> infinity), E'' largest (E_B / 2)
//   at x = 1, tan delta largest, E_B / (2 sqrt(E_A (E_A + E_B))), at
//   x = sqrt(E_A / (E_A + E_B)).

#include <cdea/material/material_chart.h>

#include "law_checks.h"

#include <cmath>
#include <functional>
#include <stdexcept>

using namespace cdea;
using namespace cdea_test;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  /// Largest |s1 - closed form| / (|closed form| + mu) over the curve; the
  /// transverse stretch against @p l2.
  void check_curve(const StressStretchCurve &c, const std::vector<double> &stress,
                   const std::function<double(double)> &s,
                   const std::function<double(double)> &l2, const double mu,
                   const std::string &what)
  {
    double worst = 0., worst_l2 = 0.;
    for (std::size_t k = 0; k < c.stretch.size(); ++k)
      {
        const double L = c.stretch[k];
        worst          = std::max(worst, std::abs(stress[k] - s(L)) / (std::abs(s(L)) + mu));
        if (l2)
          worst_l2 = std::max(worst_l2, std::abs(c.transverse_stretch[k] - l2(L)) / l2(L));
      }
    check(c.stretch.size() == 51 && c.stretch.front() == 1., what + ": 51 points from 1");
    check_close(worst, 0., 1e-10, what + ": s1 vs closed form (rel.)");
    if (l2)
      check_close(worst_l2, 0., 1e-12, what + ": transverse stretch vs closed form (rel.)");
  }

  double gent_factor(const double I1, const double jlim)
  {
    return 1. / (1. - (I1 - 3.) / jlim);
  }

  double uniaxial_I1(const double L) { return L * L + 2. / L; }
  double equibiaxial_I1(const double L) { return 2. * L * L + std::pow(L, -4); }

  /// The stretch above 1 where I1(L) - 3 = Jlim, by bisection.
  double lock(const std::function<double(double)> &I1, const double jlim)
  {
    double lo = 1., hi = 100.;
    for (int i = 0; i < 200; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (I1(mid) - 3. < jlim ? lo : hi) = mid;
      }
    return lo;
  }

  void check_neo_hooke(const MaterialConstants &film)
  {
    const double        mu  = film.shear_modulus;
    const auto          law = law_named("neo-hooke", film);
    const ChartSettings settings;
    const auto u = stress_stretch_curve(*law, ChartPath::uniaxial, settings);
    const auto e = stress_stretch_curve(*law, ChartPath::equibiaxial, settings);
    check(std::isinf(u.locking_stretch) && u.stretch.back() == 6. && e.stretch.back() == 6.,
          "neo-hooke: no locking, both curves end at 6");
    check_curve(u, u.nominal_stress, [=](double L) { return mu * (L - 1. / (L * L)); },
                [](double L) { return 1. / std::sqrt(L); }, mu, "neo-hooke uniaxial");
    check_curve(e, e.nominal_stress, [=](double L) { return mu * (L - std::pow(L, -5)); },
                [](double L) { return L; }, mu, "neo-hooke equibiaxial");
    check(u.instantaneous_stress.empty(), "neo-hooke: no instantaneous curve");
    const SmallStrainModuli m = small_strain_moduli(*law);
    check_rel(m.relaxed, 3. * mu, 1e-13, "neo-hooke: small-strain modulus 3 mu");
    check(m.instantaneous == m.relaxed && m.relaxation_time == 0.,
          "neo-hooke: elastic, no relaxation time");
    bool refused = false;
    try
      {
        dma_chart(*law, settings);
      }
    catch (const std::invalid_argument &)
      {
        refused = true;
      }
    check(refused, "neo-hooke: no DMA chart for an elastic law");
  }

  void check_gent(MaterialConstants film)
  {
    film.jlim           = 10.;
    const double mu     = film.shear_modulus, J = film.jlim;
    const auto   law    = law_named("elastic", film);
    const ChartSettings settings;
    const auto u = stress_stretch_curve(*law, ChartPath::uniaxial, settings);
    const auto e = stress_stretch_curve(*law, ChartPath::equibiaxial, settings);
    const double lock_u = lock(uniaxial_I1, J), lock_e = lock(equibiaxial_I1, J);
    check_rel(u.locking_stretch, lock_u, 1e-11, "Gent Jlim = 10: uniaxial locking stretch");
    check_rel(e.locking_stretch, lock_e, 1e-11, "Gent Jlim = 10: equibiaxial locking stretch");
    check_rel(u.stretch.back(), 1. + 0.99 * (u.locking_stretch - 1.), 1e-15,
              "Gent: the uniaxial curve ends 99 % of the way to the lock");
    check_curve(u, u.nominal_stress,
                [=](double L) { return mu * (L - 1. / (L * L)) * gent_factor(uniaxial_I1(L), J); },
                [](double L) { return 1. / std::sqrt(L); }, mu, "Gent Jlim = 10 uniaxial");
    check_curve(e, e.nominal_stress,
                [=](double L) {
                  return mu * (L - std::pow(L, -5)) * gent_factor(equibiaxial_I1(L), J);
                },
                [](double L) { return L; }, mu, "Gent Jlim = 10 equibiaxial");
    const auto paper = law_named("elastic", MaterialConstants{mu, 270., 3.98e-11, 1e-3});
    check(std::isinf(stress_stretch_curve(*paper, ChartPath::uniaxial, settings).locking_stretch),
          "Gent Jlim = 270: no locking below 6");
  }

  void check_two_network(const MaterialConstants &film, const double tau)
  {
    const double mu_A = film.shear_modulus, mu_B = 45e3, J = film.jlim;
    const auto   law  = law_named("viscoelastic", film,
                                  {{"Network B shear modulus (kPa)", mu_B * 1e-3},
                                   {"Network B Jlim", J},
                                   {"Relaxation time (s)", tau}});
    const std::string       name = "two networks, tau = " + std::to_string(tau) + " s";
    const SmallStrainModuli m    = small_strain_moduli(*law);
    const double            E_A = 3. * mu_A, E_B = 3. * mu_B, E = E_A + E_B;
    check_rel(m.relaxed, E_A, 1e-12, name + ": relaxed modulus 3 mu_A");
    check_rel(m.instantaneous, E, 1e-12, name + ": instantaneous modulus 3 (mu_A + mu_B)");
    check_rel(m.relaxation_time, tau, 1e-10, name + ": relaxation time from the tangent");

    ChartSettings settings;
    const DmaChart d = dma_chart(*law, settings);
    double         worst = 0.;
    for (std::size_t k = 0; k < d.frequency.size(); ++k)
      {
        const double x = 2. * pi * d.frequency[k] * tau;
        const double storage = E_A + E_B * x * x / (1. + x * x), loss = E_B * x / (1. + x * x);
        worst = std::max({worst, std::abs(d.storage[k] - storage) / storage,
                          std::abs(d.loss[k] - loss) / loss,
                          std::abs(d.loss_factor[k] - loss / storage) / (loss / storage)});
      }
    check(d.frequency.size() == 61, name + ": 61 frequencies");
    check_rel(d.frequency.front(), 1e-3, 1e-15, name + ": from 1e-3 Hz");
    check_rel(d.frequency.back(), 1e3, 1e-13, name + ": to 1e3 Hz");
    check_close(worst, 0., 1e-10, name + ": E', E'', tan delta vs the standard linear solid");

    double storage, loss;
    const auto at = [&](const double x) {
      standard_linear_solid(m, x / (2. * pi * tau), storage, loss);
      return loss / storage;
    };
    at(1e-9);
    check_rel(storage, E_A, 1e-12, name + ": E' -> E_A as w -> 0");
    at(1e9);
    check_rel(storage, E, 1e-12, name + ": E' -> E_A + E_B as w -> infinity");
    at(1.);
    check_rel(loss, E_B / 2., 1e-10, name + ": E'' = E_B / 2 at w tau = 1");
    const double x_peak = std::sqrt(E_A / E), peak = at(x_peak);
    check_rel(peak, E_B / (2. * std::sqrt(E_A * E)), 1e-10,
              name + ": tan delta = E_B / (2 sqrt(E_A (E_A + E_B))) at w tau = sqrt(E_A / E)");
    check(peak > at(x_peak * (1. + 1e-4)) && peak > at(x_peak * (1. - 1e-4)),
          name + ": that is the largest loss factor");
  }

  void check_two_network_curves(const MaterialConstants &film)
  {
    const double mu_A = film.shear_modulus, mu_B = 45e3, J = film.jlim;
    const auto   law  = law_named("viscoelastic", film,
                                  {{"Network B shear modulus (kPa)", mu_B * 1e-3},
                                   {"Network B Jlim", J},
                                   {"Relaxation time (s)", 2.}});
    const auto u = stress_stretch_curve(*law, ChartPath::uniaxial, ChartSettings());
    const auto e = stress_stretch_curve(*law, ChartPath::equibiaxial, ChartSettings());
    const auto uni = [=](const double mu) {
      return [=](double L) { return mu * (L - 1. / (L * L)) * gent_factor(uniaxial_I1(L), J); };
    };
    const auto equi = [=](const double mu) {
      return [=](double L) {
        return mu * (L - std::pow(L, -5)) * gent_factor(equibiaxial_I1(L), J);
      };
    };
    const auto root_L = [](double L) { return 1. / std::sqrt(L); };
    check_curve(u, u.nominal_stress, uni(mu_A), root_L, mu_A, "two networks uniaxial relaxed");
    check_curve(u, u.instantaneous_stress, uni(mu_A + mu_B), nullptr, mu_A,
                "two networks uniaxial instantaneous");
    check_curve(e, e.nominal_stress, equi(mu_A), nullptr, mu_A, "two networks equibiaxial relaxed");
    check_curve(e, e.instantaneous_stress, equi(mu_A + mu_B), nullptr, mu_A,
                "two networks equibiaxial instantaneous");
  }
} // namespace

CDEA_TEST_MAIN()
{
  const MaterialConstants film = paper_film();
  check_neo_hooke(film);
  check_gent(film);
  for (const double tau : {2., 1e-6, 1e6})
    check_two_network(film, tau);
  check_two_network_curves(film);
  return finish();
}
