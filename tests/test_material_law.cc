// The Gent dielectric law: hand-derived stresses and tangent against central
// finite differences of the energy and against Sacado's forward-mode AD, over
// a grid of stretches and voltages; and the closed-form equi-biaxial stress.

#include <Sacado.hpp>

#include <cdea/material/gent_dielectric.h>

#include "check.h"

#include <cmath>
#include <sstream>

using namespace cdea;
using cdea_test::check_close;

CDEA_TEST_MAIN()
{
  const MaterialConstants c{25.1e3, 270., 3.98e-11, 1e-3};
  using Fad  = Sacado::Fad::DFad<double>;
  using Fad2 = Sacado::Fad::DFad<Fad>;

  double worst_fd = 0., worst_ad = 0.;
  for (const double phi : {0., 3e3, 6e3})
    for (const double l1 : {1.2, 2.5, 4.0})
      for (const double l2 : {1.5, 2.5, 3.5})
        {
          const GentDielectric law(c, phi);
          const NominalStress  s = law.stress(l1, l2);
          const StressTangent  t = law.tangent(l1, l2);

          // Central differences, step h: error O(h^2) ~ 1e-8 relative.
          const double h  = 1e-5;
          auto         W  = [&](double a, double b) { return law.energy(a, b); };
          auto         S1 = [&](double a, double b) { return law.stress(a, b).s1; };
          auto         S2 = [&](double a, double b) { return law.stress(a, b).s2; };
          const double fd_s1  = (W(l1 + h, l2) - W(l1 - h, l2)) / (2 * h);
          const double fd_s2  = (W(l1, l2 + h) - W(l1, l2 - h)) / (2 * h);
          const double fd_s11 = (S1(l1 + h, l2) - S1(l1 - h, l2)) / (2 * h);
          const double fd_s12 = (S1(l1, l2 + h) - S1(l1, l2 - h)) / (2 * h);
          const double fd_s21 = (S2(l1 + h, l2) - S2(l1 - h, l2)) / (2 * h);
          const double fd_s22 = (S2(l1, l2 + h) - S2(l1, l2 - h)) / (2 * h);
          const double scale  = c.shear_modulus * 10.;
          for (const double e : {s.s1 - fd_s1, s.s2 - fd_s2, t.s11 - fd_s11, t.s12 - fd_s12,
                                 t.s12 - fd_s21, t.s22 - fd_s22})
            worst_fd = std::max(worst_fd, std::abs(e) / scale);

          // Second-order forward AD of the same energy template.
          Fad2 a1(2, 0, Fad(2, 0, l1)), a2(2, 1, Fad(2, 1, l2));
          const Fad2 w = law.energy(a1, a2);
          for (const double e : {s.s1 - w.dx(0).val(), s.s2 - w.dx(1).val(),
                                 t.s11 - w.dx(0).dx(0), t.s12 - w.dx(0).dx(1),
                                 t.s12 - w.dx(1).dx(0), t.s22 - w.dx(1).dx(1)})
            worst_ad = std::max(worst_ad, std::abs(e) / scale);
        }
  check_close(worst_fd, 0., 1e-7, "stress and tangent vs central differences (rel. to 10 mu)");
  check_close(worst_ad, 0., 1e-13, "stress and tangent vs Sacado AD (rel. to 10 mu)");

  // Equi-biaxial stretch lam, no voltage: s = mu (lam - lam^-5) / g,
  // g = 1 - (2 lam^2 + lam^-4 - 3) / Jlim.
  const double         lam = 2.5;
  const GentDielectric law(c, 0.);
  const double g = 1. - (2 * lam * lam + std::pow(lam, -4) - 3.) / c.jlim;
  const double s_exact = c.shear_modulus * (lam - std::pow(lam, -5)) / g;
  check_close(law.stress(lam, lam).s1 / s_exact, 1., 1e-14, "equi-biaxial s1 closed form");
  check_close(law.stress(lam, lam).s2 / s_exact, 1., 1e-14, "equi-biaxial s2 closed form");

  // True stress with voltage: sigma1 = l1 s1 = mu (l1^2 - l1^-2 l2^-2) / g - eps E^2
  // (Guo et al. 2025, eqs. 10-12).
  const GentDielectric charged(c, 5e3);
  const double         l1 = 3.1, l2 = 2.2;
  const double         E  = charged.electric_field(l1, l2);
  const double         I  = l1 * l1 + l2 * l2 + 1. / (l1 * l1 * l2 * l2);
  const double sigma1 = c.shear_modulus * (l1 * l1 - 1. / (l1 * l1 * l2 * l2)) /
                          (1. - (I - 3.) / c.jlim) - c.permittivity * E * E;
  check_close(l1 * charged.stress(l1, l2).s1 / sigma1, 1., 1e-13, "true stress, eq. 10");
  return cdea_test::finish();
}
