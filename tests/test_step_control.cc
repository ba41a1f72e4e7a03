// The step controller's rules (numerics/step_control.h): halving on a
// failure, growth after an easy step, the cap (also moved along the path),
// the minimum step (also in another unit), the maximum number of cut-backs
// (consecutive or in total), the reason for giving up, steps computed from
// the attempted step, factors from the caller, and the landing on a
// breakpoint; the acceptance of a step by its error estimate (StepAcceptance)
// against the formulas the time stepper, the creep sensitivities and the
// periodic steady state wrote before they shared it.

#include <cdea/numerics/step_control.h>

#include "check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// A reproducible sequence in [0, 1) (a linear congruential generator).
  class Sequence
  {
  public:
    double next()
    {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return double(state >> 11) / 9007199254740992.;
    }

  private:
    std::uint64_t state = 12345;
  };

  void halving_and_growth()
  {
    std::cout << "Halving and growth\n";
    StepController c(StepControlSettings(), 1.);
    check(c.step() == 1. && c.cutbacks() == 0, "the initial step, no cut-backs");
    check(c.reject(1.) && c.step() == 0.5 && c.cutbacks() == 1, "a failure halves the step");
    check(c.reject(0.5) && c.step() == 0.25 && c.cutbacks() == 2, "and again");
    c.accept(0.25, 4);
    check(c.step() == 0.5 && c.cutbacks() == 0,
          "4 iterations: the step doubles, the cut-backs are forgotten");
    c.accept(0.5, 5);
    check(c.step() == 0.5, "5 iterations: the step stays");
    check(c.reason() == StepStop::none, "no reason while going on");
  }

  void cap()
  {
    std::cout << "Cap\n";
    StepControlSettings s;
    s.max_step = 0.75;
    StepController c(s, 0.5);
    c.accept(0.5, 1);
    check(c.step() == 0.75, "growth stops at the maximum step");
    c.set_max_step(2.);
    c.accept(0.75, 1);
    check(c.step() == 1.5, "a cap moved along the path");
    c.set_max_step(1.);
    c.accept(1.5, 9);
    check(c.step() == 1.5, "a step above a lowered cap is not shortened unless it grows");
    c.accept(1.5, 1);
    check(c.step() == 1., "growth is capped again");
  }

  void minimum()
  {
    std::cout << "Minimum step\n";
    StepControlSettings s;
    s.min_step = 0.2;
    StepController c(s, 1.);
    check(!c.last_attempt(1.), "a failure at 1 would still go on");
    check(c.reject(1.) && c.step() == 0.5, "0.5 is above the minimum");
    check(c.reject(0.5) && c.step() == 0.25, "0.25 is above the minimum");
    check(c.last_attempt(0.25), "a failure at 0.25 would give up");
    check(!c.reject(0.25) && c.reason() == StepStop::below_min_step,
          "below the minimum the controller gives up, and says why");

    // The minimum as a voltage increment for a path parameter t with
    // dV/dt = 1000 V: 1e-3 V is t = 1e-6.
    StepController v(StepControlSettings(), 4e-6);
    v.set_min_step(1e-3, 1000.);
    check(v.reject(4e-6) && v.step() == 2e-6, "2e-6 in t is 2 mV: above 1 mV");
    check(v.reject(2e-6), "1e-6 in t is 1 mV: not below 1 mV");
    check(!v.reject(1e-6) && v.reason() == StepStop::below_min_step,
          "5e-7 in t is 0.5 mV: below 1 mV");
  }

  void cutbacks()
  {
    std::cout << "Maximum cut-backs\n";
    StepControlSettings s;
    s.max_cutbacks = 2;
    StepController c(s, 1.);
    check(c.reject(1.) && c.reject(0.5), "two cut-backs are allowed");
    check(c.last_attempt(0.25), "a third would give up");
    check(!c.reject(0.25) && c.reason() == StepStop::too_many_cutbacks && c.cutbacks() == 3,
          "the third gives up, and says why");

    StepController consecutive(s, 1.);
    consecutive.reject(1.);
    consecutive.reject(0.5);
    consecutive.accept(0.25, 9);
    check(consecutive.reject(0.25) && consecutive.reject(0.125),
          "consecutive: an accepted step starts the count again");

    s.cutbacks_in_total = true;
    StepController total(s, 1.);
    total.reject(1.);
    total.accept(0.5, 1);
    check(total.reject(1.) && total.cutbacks() == 2, "in total: the count goes on");
    check(!total.reject(0.5) && total.reason() == StepStop::too_many_cutbacks,
          "in total: the third cut-back on the path gives up");
    check(to_string(StepStop::below_min_step) != to_string(StepStop::too_many_cutbacks) &&
            !to_string(StepStop::below_min_step).empty(),
          "the reasons have distinct descriptions");
  }

  void attempted_base()
  {
    std::cout << "Steps from the attempted step\n";
    StepControlSettings s;
    s.after_reject = StepBase::attempted;
    s.after_accept = StepBase::attempted;
    s.max_step     = 10.;
    StepController c(s, 1.);
    check(c.reject(0.3) && c.step() == 0.15, "a failed landing of 0.3 halves 0.3");
    c.accept(0.1, 9);
    check(c.step() == 0.1, "a hard step of 0.1: the step becomes 0.1");
    c.accept(0.1, 2);
    check(c.step() == 0.2, "an easy one doubles it");

    s.after_reject = StepBase::proposed;
    StepController p(s, 1.);
    check(p.reject(0.3) && p.step() == 0.5, "from the proposed step: 0.3 attempted, 1 halved");
  }

  void factors()
  {
    std::cout << "Factors from the caller\n";
    StepControlSettings s;
    s.max_step     = 3.;
    s.min_step     = 0.05;
    s.max_cutbacks = 5;
    StepController c(s, 1.);
    check(c.reject_with_factor(1., 0.1) && c.step() == 0.1, "a cut-back by 0.1");
    check(!c.reject_with_factor(0.1, 0.1) && c.reason() == StepStop::below_min_step,
          "the same minimum applies");
    c.accept_with_factor(0.01, 500.);
    check(c.step() == 3., "growth by 500 from 0.01, capped at 3");
    c.accept_with_factor(3., 0.8);
    check(c.step() == 3. * 0.8, "an accepted step may shorten the next (0.8)");
    s.growth = 1.5;
    StepController g(s, 1.);
    g.accept(1., 0);
    check(g.step() == 1.5, "the growth factor of the settings (1.5)");
  }

  void landing()
  {
    std::cout << "Landing on a breakpoint\n";
    const StepController c(StepControlSettings(), 1.);
    check(c.step_towards(0.3) == 0.3, "within a step: all of it");
    check(c.step_towards(1. + 5e-7) == 1. + 5e-7, "within a step and 1e-6: all of it");
    check(c.step_towards(1.2) == 0.6, "within one and a half steps: half of it");
    check(c.step_towards(1.5) == 1. && c.step_towards(5.) == 1., "farther: one step");
  }

  // The rules the five paths used before they shared the controller, as
  // written there, against the controller on random attempts.
  void same_sequences()
  {
    std::cout << "The former rules, step for step\n";
    Sequence     random;
    bool         same = true;
    double       dt = 0.25, cap = 0.25;
    StepControlSettings load;
    load.max_cutbacks = 1000;
    StepController c(load, dt);
    for (int k = 0; k < 2000; ++k)
      {
        const bool     failed     = random.next() < 0.4;
        const unsigned iterations = unsigned(8 * random.next());
        cap                       = 0.1 + random.next();
        if (failed)
          {
            dt *= 0.5;
            c.reject(c.step());
          }
        else
          {
            if (iterations <= 4)
              dt = std::min(2. * dt, cap);
            c.set_max_step(cap);
            c.accept(c.step(), iterations);
          }
        same = same && c.step() == dt;
      }
    check(same, "load stepping: halve and double the increment, a moving cap");

    StepControlSettings time;
    time.after_reject = time.after_accept = StepBase::attempted;
    time.max_step                         = 0.01;
    time.max_cutbacks                     = 1000;
    StepController t(time, 0.01);
    dt   = 0.01;
    same = true;
    for (int k = 0; k < 2000; ++k)
      {
        const double   h          = dt * (random.next() < 0.3 ? random.next() : 1.);
        const bool     failed     = random.next() < 0.4;
        const unsigned iterations = unsigned(8 * random.next());
        if (failed)
          {
            dt = 0.5 * h;
            t.reject(h);
          }
        else
          {
            dt = iterations <= 4 ? std::min(2. * h, 0.01) : h;
            t.accept(h, iterations);
          }
        same = same && t.step() == dt;
      }
    check(same, "time stepping: halve and double the step taken");
  }
  void acceptance()
  {
    std::cout << "Acceptance by the error estimate\n";
    StepAcceptance a(3, true, ErrorController::elementary());
    check(a.accepts(true, 1.) && !a.accepts(true, 1.0001) && !a.accepts(false, 0.5) &&
            !a.accepts(true, std::nan("")),
          "error control: converged and the ratio at most 1 (NaN rejects)");
    const StepAcceptance fixed(3, false, ErrorController::elementary());
    check(fixed.accepts(true, 50.) && !fixed.accepts(false, 0.), "fixed steps: converged");
    check(std::abs(a.rejected(true, 16.) - 0.45) < 1e-15, "rejected at r = 16, k = 4: 0.9 / 2");
    check(a.rejected(true, 1e9) == 0.1 && a.rejected(true, 0.5) == 0.9,
          "the cut-back stays in [0.1, 0.9]");
    check(a.rejected(false, 0.) == 0.25, "a failed solve: 1/4");
    check(std::abs(a.accepted(1. / 16.) - 1.8) < 1e-15 && a.accepted(1e-30) == 5. &&
            a.accepted(1e4) == 0.2,
          "elementary: 0.9 r^(-1/k) in [0.2, 5], also right after a rejection");

    StepAcceptance pi(3, true, ErrorController::proportional_integral());
    check(std::abs(pi.accepted(0.5) - 0.9 * std::pow(0.5, -0.175)) < 1e-15,
          "PI: the first step with r_(n-1) = 1");
    check(std::abs(pi.accepted(0.25) - 0.9 * std::pow(0.25, -0.175) * std::pow(0.5, 0.1)) <
            1e-15,
          "PI: 0.9 r_n^(-0.7/k) r_(n-1)^(0.4/k)");
    pi.rejected(true, 2.);
    check(pi.accepted(1e-6) == 1., "PI: no growth right after a rejection");
    check(std::abs(pi.accepted(1e-6) - 0.9 * std::pow(1e-6, -0.075)) < 1e-14,
          "and growth again after that (2.54 at r_n = r_(n-1) = 1e-6)");

    StepControlSettings s;
    s.after_reject = s.after_accept = StepBase::attempted;
    StepController c(s, 1.);
    check(a.reject(c, 0.5, true, 16.) && std::abs(c.step() - 0.225) < 1e-15,
          "through the controller: the factor times the step attempted");
    a.accept(c, 0.2, 1. / 16., 9);
    check(std::abs(c.step() - 0.36) < 1e-15, "and the factor of an accepted step");
    StepAcceptance f(3, false, ErrorController::elementary());
    check(f.reject(c, 0.4, true, 16.) && c.step() == 0.2, "fixed steps: the controller's cut-back");
    f.accept(c, 0.2, 50., 2);
    check(c.step() == 0.4, "and its growth after an easy step");
  }

  // The error control as the three ESDIRK paths wrote it before they shared
  // StepAcceptance, factor for factor (bit for bit), on random ratios.
  void former_error_control()
  {
    std::cout << "The former error control, factor for factor\n";
    Sequence       random;
    const double   k = 4.;
    StepAcceptance time(3, true, ErrorController::proportional_integral());
    StepAcceptance other(3, true, ErrorController::elementary());
    double         last_ratio = 1.;
    bool           after_rejection = false, same = true;
    for (int n = 0; n < 4000; ++n)
      {
        const double ratio     = std::pow(10., 6. * random.next() - 4.);
        const bool   converged = random.next() < 0.9;
        if (!converged || !(ratio <= 1.))
          {
            const double expected =
              converged ? std::clamp(0.9 * std::pow(ratio, -1. / k), 0.1, 0.9) : 0.25;
            same            = same && time.rejected(converged, ratio) == expected &&
                   other.rejected(converged, ratio) == expected;
            after_rejection = true;
            continue;
          }
        const double r = std::max(ratio, 1e-10);
        const double pi_factor =
          std::clamp(0.9 * std::pow(r, -0.7 / k) * std::pow(std::max(last_ratio, 1e-10), 0.4 / k),
                     0.2, after_rejection ? 1. : 5.);
        const double elementary =
          std::clamp(0.9 * std::pow(std::max(ratio, 1e-10), -1. / k), 0.2, 5.);
        same            = same && time.accepted(ratio) == pi_factor &&
               other.accepted(ratio) == elementary;
        last_ratio      = r;
        after_rejection = false;
      }
    check(same, "the time stepper's PI controller and the creep and periodic paths' rule");
  }
} // namespace

CDEA_TEST_MAIN()
{
  halving_and_growth();
  cap();
  minimum();
  cutbacks();
  attempted_base();
  factors();
  landing();
  same_sequences();
  acceptance();
  former_error_control();
  return finish();
}
