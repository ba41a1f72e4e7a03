// Issue 21's check of the default time settings: a time run that names no
// scheme, step control, tolerance or step (the parameter file's defaults:
// ESDIRK4, error control at relative 1e-6, steps capped at 0.01 s) is within
// 1e-5 relative in displacement of a converged reference on ramp-holds of
// the viscoelastic film (the default actuator at 5 kV, mu_B = 45 kPa,
// tau = 2 s), with and without the disk's inertia. The reference is ESDIRK4
// at relative tolerance 1e-11, absolute 1e-9 mm and steps of at most 5 ms,
// its estimate below 1e-7 of the displacement. The default is 9e-7 off at
// most (ramp 0.2 s with inertia; 2.2e-6 on the default 20 s hold, too long
// for a test). The old default, backward Euler at fixed 0.01 s, is printed
// beside it: 3.4e-5 and 5.4e-5 off without inertia, 1.8e-4 and 8.8e-3 with
// it (the disk's ringing, whose phase the first-order step shifts).

#include <cdea/analysis/time_run.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>

#include "check.h"

#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_rel;

namespace
{
  using Overrides = std::vector<std::pair<std::string, std::string>>;

  struct Outcome
  {
    double       displacement = 0.; ///< m, at the end of the hold
    unsigned int steps        = 0;
    double       estimate     = 0.; ///< m
  };

  /// The viscoelastic film on the parameter file's defaults (the default
  /// actuator at 5 kV) through a ramp-hold, with @p extra set after it.
  Outcome run(const Overrides &ramp_hold, const Overrides &extra)
  {
    ParameterInput input = ParameterInput::text("");
    input.overrides      = {{"Material/Model", "viscoelastic"}, {"Time/Enabled", "true"}};
    for (const auto &o : ramp_hold)
      input.overrides.push_back(o);
    for (const auto &o : extra)
      input.overrides.push_back(o);
    const Parameters p     = read_parameters(input);
    const Scene      scene = p.scene();
    TimeRunSetup     setup = set_up_time_run(p, scene);
    Outcome          o;
    setup.stepper->on_step = [&](const StepSummary &s) { o.displacement = s.displacement; };
    const RunResult r      = setup.stepper->run();
    if (!check(r.completed, "time run completes"))
      std::cout << r.message << '\n';
    o.steps    = r.time_steps;
    o.estimate = r.error_estimate;
    return o;
  }
} // namespace

CDEA_TEST_MAIN()
{
  const Parameters defaults = read_parameters(ParameterInput::text(""));
  check(defaults.time.scheme == TimeMethod::esdirk4, "the default scheme is ESDIRK4");
  check(defaults.time.step_control == TimeStepControl::error, "with error control");

  const Overrides tight = {{"Time/Relative tolerance", "1e-11"}, {"Time/Time step (s)", "0.005"},
                           {"Time/Absolute tolerance (mm)", "1e-9"}};
  const Overrides old   = {{"Time/Scheme", "backward Euler"}, {"Time/Step control", "fixed"}};
  for (const std::string inertia : {"false", "true"})
    for (const Overrides &ramp_hold :
         {Overrides{{"Time/Ramp time (s)", "1"}, {"Time/Hold time (s)", "1"}},
          Overrides{{"Time/Ramp time (s)", "0.2"}, {"Time/Hold time (s)", "0.8"}}})
      {
        Overrides with_inertia = ramp_hold;
        with_inertia.push_back({"Time/Inertia", inertia});
        const Outcome reference = run(with_inertia, tight);
        const Outcome fresh     = run(with_inertia, {});
        const Outcome before    = run(with_inertia, old);
        const std::string what  = "ramp " + ramp_hold[0].second + " s, hold " +
                                 ramp_hold[1].second + " s, inertia " + inertia;
        std::cout << what << ": reference " << reference.displacement * 1e3 << " mm ("
                  << reference.steps << " steps, estimate " << reference.estimate * 1e3
                  << " mm); default " << fresh.steps << " steps, estimate "
                  << fresh.estimate * 1e3 << " mm; backward Euler 0.01 s off by "
                  << std::abs(before.displacement / reference.displacement - 1.) << '\n';
        check(reference.estimate < 1e-7 * reference.displacement, what + ": the reference's estimate");
        check_rel(fresh.displacement, reference.displacement, 1e-5,
                  what + ": default settings against the reference");
      }
  return cdea_test::finish();
}
