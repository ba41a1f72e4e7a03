// The Ogden law of up to three terms (Material/Model = ogden; Ogden 1972):
// energy, stresses and tangent against Sacado and differences, the
// parameter derivatives in the Shear modulus (mu_1) and its five own
// constants, the natural width, Ogden's condition mu_p alpha_p >= 0 as a
// range check, and its exact limits: one term alpha = 2 is the neo-Hookean
// law, alpha = (2, -2) the Mooney-Rivlin law with C2 = -mu_2 / 2, to round-off.

#include <cdea/base/text.h>

#include "law_checks.h"

using namespace cdea;
using namespace cdea_test;

namespace
{
  const std::vector<std::string> entries{"Ogden alpha 1", "Ogden mu 2 (kPa)", "Ogden alpha 2",
                                         "Ogden mu 3 (kPa)", "Ogden alpha 3"};

  std::map<std::string, double> constants(const std::vector<double> &v)
  {
    std::map<std::string, double> c;
    for (std::size_t k = 0; k < entries.size(); ++k)
      c[entries[k]] = v[k];
    return c;
  }

  /// The largest difference of two laws' responses relative to |value| + mu.
  double difference(const MembraneLaw &a, const MembraneLaw &b, const double mu)
  {
    double worst = 0.;
    for (const double phi : {0., 5e3})
      for (const double l1 : {0.8, 2.5, 4.})
        for (const double l2 : {0.9, 2.5, 3.5})
          {
            LawResponse x, y;
            respond(a, l1, l2, phi, x);
            respond(b, l1, l2, phi, y);
            for (const auto &[p, q] : {std::pair{x.energy, y.energy}, {x.stress.s1, y.stress.s1},
                                      {x.stress.s2, y.stress.s2}, {x.tangent.s11, y.tangent.s11},
                                      {x.tangent.s12, y.tangent.s12},
                                      {x.tangent.s22, y.tangent.s22}})
              worst = std::max(worst, std::abs(p - q) / (std::abs(q) + mu));
          }
    return worst;
  }
} // namespace

CDEA_TEST_MAIN()
{
  const MaterialConstants   film = paper_film();
  const double              mu = film.shear_modulus, eps = film.permittivity, H = film.thickness;
  const std::vector<double> v{1.3, 0.5, 5., -2., -2.}; // alpha_1, mu_2, alpha_2, mu_3, alpha_3
  const auto                law = law_named("ogden", film, constants(v));

  check_against_ad(*law,
                   [&](const Fad2 &l1, const Fad2 &l2, const double phi) -> Fad2 {
                     using std::pow;
                     const Fad2 l3 = 1. / (l1 * l2);
                     const auto term = [&](const double m, const double a) -> Fad2 {
                       return m / a * (pow(l1, a) + pow(l2, a) + pow(l3, a) - 3.);
                     };
                     return term(mu, v[0]) + term(1e3 * v[1], v[2]) + term(1e3 * v[3], v[4]) -
                            0.5 * eps * phi * phi / (H * H) * l1 * l1 * l2 * l2;
                   },
                   mu, "ogden, three terms");

  const auto make = [&](const int k, const double value) {
    MaterialConstants   f = film;
    std::vector<double> w = v;
    if (k < 0)
      f.shear_modulus = value;
    else
      w[k] = value;
    return law_named("ogden", f, constants(w));
  };
  check_parameter_derivative([&](double x) { return make(-1, x); }, LawParameter::shear_modulus,
                             mu, "d/dmu_1");
  for (unsigned int k = 0; k < entries.size(); ++k)
    check_parameter_derivative([&](double x) { return make(int(k), x); }, own_constant(k), v[k],
                               "d/d" + entries[k]);
  bool names = law->own_constants().size() == entries.size();
  for (std::size_t k = 0; names && k < entries.size(); ++k)
    names = law->own_constants()[k].entry == entries[k];
  check(names && !law->depends_on(LawParameter::jlim), "its five constants in order; no Jlim");

  check_natural_width(law, 4., 0.45, 6e3, "ogden");

  // Exact limits.
  const auto one_term = law_named("ogden", film, constants({2., 0., -2., 0., 5.}));
  check_close(difference(*one_term, *law_named("neo-hooke", film), mu), 0., 1e-14,
              "one term alpha = 2 is the neo-Hookean law");
  const auto two_terms = law_named("ogden", film, constants({2., -8., -2., 0., 5.}));
  check_close(difference(*two_terms,
                         *law_named("mooney-rivlin", film, {{"Mooney-Rivlin C2 (kPa)", 4.}}), mu),
              0., 1e-14, "alpha = (2, -2), mu_2 = -8 kPa is Mooney-Rivlin with C2 = 4 kPa");

  // Ogden's condition.
  const auto refusal = [&](const std::vector<double> &w) {
    try
      {
        law_named("ogden", film, constants(w));
      }
    catch (const InputError &e)
      {
        return std::string(e.what());
      }
    return std::string();
  };
  const std::string sign = refusal({2., 1., -2., 0., 5.});
  check(sign == "Material/Ogden mu 2 (kPa) must have the sign of Ogden alpha 2 (Ogden's "
                "condition mu_p alpha_p >= 0) and be at most 1e9 in size, got 1 with alpha -2",
        "mu_2 alpha_2 < 0 refused: " + sign);
  check(refusal({-1., 0., -2., 0., 5.}).find("Material/Ogden alpha 1 must be above 0") == 0,
        "alpha_1 <= 0 refused (mu_1 > 0)");
  check(refusal({2., 0., 0., 0., 5.}).find("Material/Ogden alpha 2 must not be 0") == 0,
        "alpha_2 = 0 refused");
  return finish();
}
