// The neo-Hookean law (Material/Model = neo-hooke): energy, stresses and
// tangent against Sacado and differences, its parameter derivatives, the
// natural width of the tension field (and its absence where the voltage
// term outgrows the law, which has no limiting stretch), and the limit Gent
// -> neo-Hooke as Jlim -> infinity with its order: the difference is
// O(1 / Jlim), so that ten times Jlim gives a tenth of it.

#include "law_checks.h"

#include <cmath>

using namespace cdea;
using namespace cdea_test;

CDEA_TEST_MAIN()
{
  const MaterialConstants film = paper_film();
  const auto              law  = law_named("neo-hooke", film);
  const double            mu = film.shear_modulus, eps = film.permittivity, H = film.thickness;

  check_against_ad(*law,
                   [&](const Fad2 &l1, const Fad2 &l2, const double phi) -> Fad2 {
                     const Fad2 I1 = l1 * l1 + l2 * l2 + 1. / (l1 * l1 * l2 * l2);
                     return 0.5 * mu * (I1 - 3.) -
                            0.5 * eps * phi * phi / (H * H) * l1 * l1 * l2 * l2;
                   },
                   mu, "neo-hooke");

  const auto with = [&](const LawParameter p) {
    return [film, p](const double v) {
      MaterialConstants f = film;
      if (p == LawParameter::shear_modulus)
        f.shear_modulus = v;
      if (p == LawParameter::permittivity)
        f.permittivity = v;
      return law_named("neo-hooke", f);
    };
  };
  check_parameter_derivative(with(LawParameter::shear_modulus), LawParameter::shear_modulus, mu,
                             "d/dmu");
  check_parameter_derivative(with(LawParameter::permittivity), LawParameter::permittivity, eps,
                             "d/deps");
  double       dW = 0.;
  NominalStress ds{0., 0.};
  check(!law->parameter_derivative({2., 2., 0.}, {}, LawParameter::jlim, dW, ds) &&
          !law->depends_on(LawParameter::jlim) && law->own_constants().empty(),
        "no Jlim, no constants of its own");

  // Tension field: wrinkled below the natural width 0.9216 at 6 kV, l1 = 4;
  // no natural width where e l1^2 > mu (s2 falls without bound in w).
  check_natural_width(law, 4., 0.8, 6e3, "neo-hooke");
  const LawResponse none = TensionField(law).relax({4.5, 2.5, 6e3});
  check(none.tension == TensionState::failed,
        "no natural width where eps Phi^2 l1^2 / H^2 > mu (the search ends)");

  // Gent -> neo-Hooke: |s(Gent, Jlim) - s(neo-Hooke)| ~ C / Jlim.
  std::cout << "Gent with Jlim -> infinity (l1 = 2.5, l2 = 3, 5 kV):\n";
  LawResponse nh;
  respond(*law, 2.5, 3., 5e3, nh);
  double previous = 0., order = 0.;
  for (const double jlim : {1e2, 1e3, 1e4, 1e5, 1e6})
    {
      MaterialConstants f = film;
      f.jlim              = jlim;
      LawResponse g;
      respond(*law_named("elastic", f), 2.5, 3., 5e3, g);
      const double diff = std::max({std::abs(g.stress.s1 - nh.stress.s1),
                                    std::abs(g.stress.s2 - nh.stress.s2),
                                    std::abs(g.tangent.s11 - nh.tangent.s11)}) / mu;
      if (previous > 0.)
        order = std::log10(previous / diff);
      std::cout << "  Jlim " << jlim << ": max difference / mu " << diff
                << (previous > 0. ? ", observed order " + std::to_string(order) : "") << "\n";
      previous = diff;
    }
  check_close(order, 1., 1e-3, "first-order convergence in 1 / Jlim");
  check(previous < 1e-4, "at Jlim = 1e6 the Gent law is neo-Hookean to 1e-4 mu");
  return finish();
}
