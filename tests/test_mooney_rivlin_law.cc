// The Mooney-Rivlin law (Material/Model = mooney-rivlin): energy, stresses and
// tangent against Sacado and differences, its parameter derivatives (Shear
// modulus, its own Mooney-Rivlin C2, permittivity), the natural width, the
// limit C2 = 0 (the neo-Hookean law, exactly) and the range check of C2.

#include <cdea/base/text.h>

#include "law_checks.h"

using namespace cdea;
using namespace cdea_test;

CDEA_TEST_MAIN()
{
  const MaterialConstants film = paper_film();
  const double            mu = film.shear_modulus, eps = film.permittivity, H = film.thickness;
  const double            c2_kPa = 5.;
  const auto law = law_named("mooney-rivlin", film, {{"Mooney-Rivlin C2 (kPa)", c2_kPa}});

  check_against_ad(*law,
                   [&](const Fad2 &l1, const Fad2 &l2, const double phi) -> Fad2 {
                     const Fad2 q = 1. / (l1 * l1 * l2 * l2);
                     const Fad2 I1 = l1 * l1 + l2 * l2 + q;
                     const Fad2 I2 = 1. / (l1 * l1) + 1. / (l2 * l2) + 1. / q;
                     return 0.5 * mu * (I1 - 3.) + 1e3 * c2_kPa * (I2 - 3.) -
                            0.5 * eps * phi * phi / (H * H) * l1 * l1 * l2 * l2;
                   },
                   mu, "mooney-rivlin");

  const auto make = [&](const double m, const double c2, const double e) {
    MaterialConstants f = film;
    f.shear_modulus     = m;
    f.permittivity      = e;
    return law_named("mooney-rivlin", f, {{"Mooney-Rivlin C2 (kPa)", c2}});
  };
  check_parameter_derivative([&](double v) { return make(v, c2_kPa, eps); },
                             LawParameter::shear_modulus, mu, "d/dmu");
  check_parameter_derivative([&](double v) { return make(mu, v, eps); }, own_constant(0), c2_kPa,
                             "d/dC2 (per kPa)");
  check_parameter_derivative([&](double v) { return make(mu, c2_kPa, v); },
                             LawParameter::permittivity, eps, "d/deps");
  check(law->own_constants().size() == 1 &&
          law->own_constants()[0].entry == "Mooney-Rivlin C2 (kPa)" &&
          law->own_constants()[0].lower == 0. && !law->depends_on(LawParameter::jlim),
        "one constant of its own, C2 >= 0; no Jlim");

  check_natural_width(law, 4., 0.45, 6e3, "mooney-rivlin");

  // C2 = 0: the neo-Hookean law, bit for bit (the I2 term adds zeros).
  const auto zero = make(mu, 0., eps), nh = law_named("neo-hooke", film);
  bool       same = true;
  for (const double l1 : {1.1, 2.5, 4.})
    for (const double l2 : {0.9, 2.5, 3.5})
      {
        LawResponse a, b;
        respond(*zero, l1, l2, 5e3, a);
        respond(*nh, l1, l2, 5e3, b);
        same = same && a.energy == b.energy && a.stress.s1 == b.stress.s1 &&
               a.stress.s2 == b.stress.s2 && a.tangent.s11 == b.tangent.s11 &&
               a.tangent.s12 == b.tangent.s12 && a.tangent.s22 == b.tangent.s22;
      }
  check(same, "C2 = 0 is the neo-Hookean law exactly");

  std::string refused;
  try
    {
      make(mu, -1., eps);
    }
  catch (const InputError &e)
    {
      refused = e.what();
    }
  check(refused == "Material/Mooney-Rivlin C2 (kPa) must be between 0 and 1e9, got -1",
        "negative C2 refused: " + refused);
  return finish();
}
