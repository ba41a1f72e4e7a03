// The relaxed (tension-field) law: equals the plain law where s2 >= 0; where
// s2 < 0 it has s2 = 0, its s1 is the derivative of the relaxed energy and its
// tangent the derivative of that s1 (finite differences), the natural width
// minimizes W over hoop stretches above the kinematic one, and loss of
// ellipticity is flagged where ds1_rel/dl1 <= 0.

#include <cdea/material/gent_law.h>
#include <cdea/material/tension_field.h>

#include "check.h"

#include <cmath>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// The relaxation of the Gent dielectric at one voltage.
  struct Relaxed
  {
    Relaxed(const GentDielectric &law)
      : field(std::make_shared<GentDielectricLaw>(law.constants()))
      , voltage(law.voltage())
    {}
    LawResponse evaluate(const double l1, const double l2) const
    {
      return field.relax({l1, l2, voltage});
    }
    double gent_hoop_limit(const double l1) const { return field.max_hoop_stretch(l1); }

    TensionField field;
    double       voltage;
  };
} // namespace

CDEA_TEST_MAIN()
{
  const MaterialConstants c{25.1e3, 270., 3.98e-11, 1e-3};

  {
    const GentDielectric                         law(c, 3e3);
    const Relaxed relaxed(law);
    const auto e = relaxed.evaluate(3.0, 2.5);
    check(e.tension == TensionState::taut, "taut at 3 kV, l = (3, 2.5)");
    check_close(e.stress.s1, law.stress(3.0, 2.5).s1, 0., "taut: s1 is the law's");
    check_close(e.tangent.s12, law.tangent(3.0, 2.5).s12, 0., "taut: tangent is the law's");
  }

  // 5.5 kV at the disk edge of the full-electrode actuator (l2 = lam_pre):
  // s2 < 0 there (model-notes: past the onset near 5.4 kV).
  const GentDielectric                         law(c, 5.5e3);
  const Relaxed relaxed(law);
  const double                                 l1 = 5.0, l2 = 2.5;
  check(law.stress(l1, l2).s2 < 0., "plain law compressive at 5.5 kV, l = (5.0, 2.5)");
  const auto e = relaxed.evaluate(l1, l2);
  check(e.tension == TensionState::wrinkled, "relaxed law: wrinkled");
  check(e.natural_width > l2, "natural width above the kinematic hoop stretch");
  check_close(law.stress(l1, e.natural_width).s2 / c.shear_modulus, 0., 1e-12,
              "s2(l1, natural width) = 0");
  // The natural width is the minimizer over w >= l2: scan W.
  double w_best = l2, W_best = law.energy(l1, l2);
  for (double w = l2; w < relaxed.gent_hoop_limit(l1); w += 1e-4)
    if (law.energy(l1, w) < W_best)
      {
        W_best = law.energy(l1, w);
        w_best = w;
      }
  check_close(w_best, e.natural_width, 2e-4, "natural width = argmin of W over w >= l2 (scan)");

  // Derivatives of the relaxed energy by central differences in l1 (l2 does
  // not matter while wrinkled: the energy is flat in l2).
  const double h  = 1e-6;
  const auto   ep = relaxed.evaluate(l1 + h, l2), em = relaxed.evaluate(l1 - h, l2);
  check_rel(e.stress.s1, (ep.energy - em.energy) / (2 * h), 1e-7, "s1_rel = dW_rel/dl1");
  check_rel(e.tangent.s11, (ep.stress.s1 - em.stress.s1) / (2 * h), 1e-6,
            "ds1_rel/dl1 = s11 - s12^2/s22");
  const auto e2 = relaxed.evaluate(l1, l2 + 1e-3);
  check_close((e2.energy - e.energy) / c.shear_modulus, 0., 1e-12,
              "wrinkled: W_rel does not depend on l2");
  check(!e.loses_ellipticity == (e.tangent.s11 > 0.), "ellipticity flag matches the sign");

  // A large voltage: the voltage term makes s1_rel fall with l1 somewhere:
  // find a state where the relaxed law loses ellipticity and check the flag
  // against differences of s1_rel.
  const GentDielectric                         strong(c, 8e3);
  const Relaxed relaxed_strong(strong);
  bool                                         found = false;
  for (double a = 1.5; a < 8. && !found; a += 0.05)
    {
      const auto ea = relaxed_strong.evaluate(a, 2.5);
      if (ea.tension == TensionState::wrinkled && ea.loses_ellipticity)
        {
          const auto p = relaxed_strong.evaluate(a + 1e-6, 2.5);
          const auto m = relaxed_strong.evaluate(a - 1e-6, 2.5);
          check(p.stress.s1 - m.stress.s1 <= 1e-9 * c.shear_modulus,
                "8 kV: flagged state has ds1_rel/dl1 <= 0 (l1 = " + std::to_string(a) + ")");
          found = true;
        }
    }
  check(found, "8 kV: loss of ellipticity of the relaxed law occurs in l1 < 8");

  // The Gent hoop limit is where g = 0.
  const double w_lim = relaxed.gent_hoop_limit(l1);
  check_close(law.gent_margin(l1, w_lim), 0., 1e-12, "gent_hoop_limit: g = 0 there");
  return finish();
}
