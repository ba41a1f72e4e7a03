// Every elastic law of the library against the textbook closed forms of the
// incompressible isotropic film (doc/materials.md, "Closed forms"):
//
// uniaxial tension l1 = L, l2 = l3 = L^-1/2 (s2 = 0 by symmetry, no
// voltage), nominal stress
//   neo-Hooke      mu (L - L^-2)                                 (Treloar)
//   Mooney-Rivlin  (mu + 2 C2 / L) (L - L^-2)                    (Rivlin)
//   Ogden          sum_p mu_p (L^(a_p - 1) - L^(-a_p / 2 - 1))   (Ogden)
//   Gent           mu (L - L^-2) / (1 - (I1 - 3) / Jlim)         (Gent)
//   Gent-Gent      (L - L^-2) (mu / (1 - (I1 - 3) / Jlim) + 2 C2 / (L I2))
// with I1 = L^2 + 2 / L, I2 = 2 L + L^-2; equibiaxial l1 = l2 = L under
// voltage Phi (I1 = 2 L^2 + L^-4, I2 = 2 L^-2 + L^4, e = eps Phi^2 / H^2)
//   neo-Hooke      mu (L - L^-5) - e L^3
//   Mooney-Rivlin  (L - L^-5) (mu + 2 C2 L^2) - e L^3
//   Ogden          sum_p mu_p (L^(a_p - 1) - L^(-2 a_p - 1)) - e L^3
//   Gent           mu (L - L^-5) / (1 - (I1 - 3) / Jlim) - e L^3
//   Gent-Gent      (L - L^-5) (mu / (1 - (I1 - 3) / Jlim) + 2 C2 L^2 / I2) - e L^3.
// The formulas are the test's own, independent of the laws' invariant and
// principal-stretch code.

#include <cdea/material/gent_law.h>

#include "law_checks.h"

#include <cmath>
#include <functional>

using namespace cdea;
using namespace cdea_test;

namespace
{
  struct ClosedForm
  {
    std::string                                  name;
    std::shared_ptr<const MembraneLaw>           law;
    std::function<double(double)>                uniaxial;
    std::function<double(double)>                equibiaxial_elastic; // without the voltage
  };

  void check_closed_form(const ClosedForm &c, const MaterialConstants &film)
  {
    double       worst_uni = 0., worst_s2 = 0., worst_equi = 0.;
    bool         all_in = true;
    const double mu     = film.shear_modulus;
    for (const double L : {1.05, 1.5, 2., 3., 4.5})
      {
        LawResponse r;
        all_in = respond(*c.law, L, 1. / std::sqrt(L), 0., r) && all_in;
        const double s = c.uniaxial(L);
        worst_uni      = std::max(worst_uni, std::abs(r.stress.s1 - s) / (std::abs(s) + mu));
        worst_s2  = std::max(worst_s2, std::abs(r.stress.s2) / mu);
        for (const double phi : {0., 3e3})
          {
            const double e = film.permittivity * phi * phi / (film.thickness * film.thickness);
            const double s = c.equibiaxial_elastic(L) - e * L * L * L;
            LawResponse q;
            all_in = respond(*c.law, L, L, phi, q) && all_in;
            worst_equi = std::max({worst_equi, std::abs(q.stress.s1 - s) / (std::abs(s) + mu),
                                   std::abs(q.stress.s2 - s) / (std::abs(s) + mu)});
          }
      }
    check(all_in, c.name + ": every state (L from 1.05 to 4.5) inside the law's range");
    check_close(worst_uni, 0., 1e-13, c.name + ": uniaxial s1 vs closed form (rel.)");
    check_close(worst_s2, 0., 1e-13, c.name + ": uniaxial s2 = 0 (over mu)");
    check_close(worst_equi, 0., 1e-13, c.name + ": equibiaxial s1 = s2 vs closed form (rel.)");
  }
} // namespace

CDEA_TEST_MAIN()
{
  const MaterialConstants film = paper_film();
  const double            mu = film.shear_modulus, jlim = film.jlim;
  const double            c2 = 5e3;                               // Pa
  const double            m2 = -3e3, a2 = -2., m3 = 0.5e3, a3 = 5.; // Ogden terms 2, 3 (Pa)
  const double            a1 = 1.3;

  const auto gent_factor_uni = [=](const double L) {
    return 1. / (1. - (L * L + 2. / L - 3.) / jlim);
  };
  const auto gent_factor_equi = [=](const double L) {
    return 1. / (1. - (2. * L * L + std::pow(L, -4) - 3.) / jlim);
  };
  const auto ogden_uni = [=](const double m, const double a, const double L) {
    return m * (std::pow(L, a - 1.) - std::pow(L, -0.5 * a - 1.));
  };
  const auto ogden_equi = [=](const double m, const double a, const double L) {
    return m * (std::pow(L, a - 1.) - std::pow(L, -2. * a - 1.));
  };

  const std::vector<ClosedForm> forms{
    {"neo-hooke", law_named("neo-hooke", film),
     [=](double L) { return mu * (L - 1. / (L * L)); },
     [=](double L) { return mu * (L - std::pow(L, -5)); }},
    {"mooney-rivlin", law_named("mooney-rivlin", film, {{"Mooney-Rivlin C2 (kPa)", c2 * 1e-3}}),
     [=](double L) { return (mu + 2. * c2 / L) * (L - 1. / (L * L)); },
     [=](double L) { return (L - std::pow(L, -5)) * (mu + 2. * c2 * L * L); }},
    {"ogden",
     law_named("ogden", film,
               {{"Ogden alpha 1", a1}, {"Ogden mu 2 (kPa)", m2 * 1e-3}, {"Ogden alpha 2", a2},
                {"Ogden mu 3 (kPa)", m3 * 1e-3}, {"Ogden alpha 3", a3}}),
     [=](double L) { return ogden_uni(mu, a1, L) + ogden_uni(m2, a2, L) + ogden_uni(m3, a3, L); },
     [=](double L) {
       return ogden_equi(mu, a1, L) + ogden_equi(m2, a2, L) + ogden_equi(m3, a3, L);
     }},
    {"elastic (Gent)", law_named("elastic", film),
     [=](double L) { return mu * (L - 1. / (L * L)) * gent_factor_uni(L); },
     [=](double L) { return mu * (L - std::pow(L, -5)) * gent_factor_equi(L); }},
    {"gent-gent", law_named("gent-gent", film, {{"Gent-Gent C2 (kPa)", c2 * 1e-3}}),
     [=](double L) {
       const double I2 = 2. * L + 1. / (L * L);
       return (L - 1. / (L * L)) * (mu * gent_factor_uni(L) + 2. * c2 / (L * I2));
     },
     [=](double L) {
       const double I2 = 2. / (L * L) + std::pow(L, 4);
       return (L - std::pow(L, -5)) * (mu * gent_factor_equi(L) + 2. * c2 * L * L / I2);
     }}};
  for (const ClosedForm &c : forms)
    check_closed_form(c, film);

  // A number to read: the neo-Hookean uniaxial stress at L = 2 is 7/4 mu.
  LawResponse r;
  respond(*forms.front().law, 2., 1. / std::sqrt(2.), 0., r);
  check_rel(r.stress.s1, 1.75 * mu, 1e-14, "neo-hooke: s1(L = 2) = 7/4 mu = 43.925 kPa");
  return finish();
}
