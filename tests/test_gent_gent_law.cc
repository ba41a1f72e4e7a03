// The Gent-Gent law (Material/Model = gent-gent; Pucci and Saccomandi 2002):
// energy, stresses and tangent against Sacado and differences, its parameter
// derivatives (Shear modulus, Jlim, its own Gent-Gent C2, permittivity), the
// range (the Gent limit), the natural width, and the limit C2 = 0: the Gent
// law, to round-off.

#include <cdea/material/gent_law.h>

#include "law_checks.h"

using namespace cdea;
using namespace cdea_test;

CDEA_TEST_MAIN()
{
  const MaterialConstants film = paper_film();
  const double mu = film.shear_modulus, jlim = film.jlim, eps = film.permittivity;
  const double H = film.thickness, c2_kPa = 3.;
  const auto   law = law_named("gent-gent", film, {{"Gent-Gent C2 (kPa)", c2_kPa}});

  check_against_ad(*law,
                   [&](const Fad2 &l1, const Fad2 &l2, const double phi) -> Fad2 {
                     using std::log;
                     const Fad2 q = 1. / (l1 * l1 * l2 * l2);
                     const Fad2 I1 = l1 * l1 + l2 * l2 + q;
                     const Fad2 I2 = 1. / (l1 * l1) + 1. / (l2 * l2) + 1. / q;
                     return -0.5 * mu * jlim * log(1. - (I1 - 3.) / jlim) +
                            1e3 * c2_kPa * log(I2 / 3.) -
                            0.5 * eps * phi * phi / (H * H) * l1 * l1 * l2 * l2;
                   },
                   mu, "gent-gent");

  const auto make = [&](const double m, const double J, const double c2) {
    MaterialConstants f = film;
    f.shear_modulus     = m;
    f.jlim              = J;
    return law_named("gent-gent", f, {{"Gent-Gent C2 (kPa)", c2}});
  };
  check_parameter_derivative([&](double v) { return make(v, jlim, c2_kPa); },
                             LawParameter::shear_modulus, mu, "d/dmu");
  check_parameter_derivative([&](double v) { return make(mu, v, c2_kPa); }, LawParameter::jlim,
                             jlim, "d/dJlim");
  check_parameter_derivative([&](double v) { return make(mu, jlim, v); }, own_constant(0),
                             c2_kPa, "d/dC2 (per kPa)");

  // The range is the Gent law's.
  const GentDielectricLaw gent(film);
  LawResponse             r;
  const double            l2 = 3., edge = gent.meridian_stretch_range(l2).second;
  check(law->meridian_stretch_range(l2) == gent.meridian_stretch_range(l2) &&
          law->max_hoop_stretch(2.) == gent.max_hoop_stretch(2.) &&
          respond(*law, 0.999 * edge, l2, 0., r) && !respond(*law, 1.001 * edge, l2, 0., r) &&
          law->limit().name == "the Gent limit",
        "the range of the Gent limit");

  check_natural_width(law, 4.5, 2.5, 6e3, "gent-gent");

  // C2 = 0: the Gent law to round-off (the chain rule through I1 rounds differently).
  const auto zero = make(mu, jlim, 0.);
  double     worst = 0.;
  for (const double phi : {0., 5e3})
    for (const double l1 : {1.1, 2.5, 4., 8.})
      for (const double l2 : {0.9, 2.5, 3.5})
        {
          LawResponse a, b;
          if (!respond(*zero, l1, l2, phi, a) || !respond(gent, l1, l2, phi, b))
            continue;
          for (const auto &[x, y] : {std::pair{a.energy, b.energy}, {a.stress.s1, b.stress.s1},
                                    {a.stress.s2, b.stress.s2}, {a.tangent.s11, b.tangent.s11},
                                    {a.tangent.s12, b.tangent.s12},
                                    {a.tangent.s22, b.tangent.s22}})
            worst = std::max(worst, std::abs(x - y) / (std::abs(y) + mu));
        }
  check_close(worst, 0., 1e-14, "C2 = 0 is the Gent law (rel. to |value| + mu)");
  return finish();
}
