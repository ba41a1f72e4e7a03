// The full-electrode fold by the shooting model traced by its angle: t(theta0)
// has a maximum near 6.63 kV. Load stepping in voltage (the same shooting
// model) gets up to it but not past: the fold lies above the last voltage load
// stepping converges at, and close to it.

#include <cdea/shooting/angle_trace.h>
#include <cdea/shooting/shooting_model.h>

#include "check.h"
#include "scenes.h"

#include <iostream>

using namespace cdea;
using namespace cdea_test;

CDEA_TEST_MAIN()
{
  const Scene scene = paper_scene({1., 3.}, {{8.}});

  shooting::ShootingModel model(scene);
  RunResult               result;
  StepSummary             last = run_to_end(model, scene, &result);
  check(!result.completed, "load stepping in voltage stops before 8 kV (the fold)");
  const double v_stop = last.voltages[0];
  std::cout << "  load stepping stopped at " << v_stop * 1e-3 << " kV: " << result.message
            << '\n';

  // Start the angle trace from the state at 6 kV.
  shooting::ShootingModel start_model(scene);
  SteppingSettings        settings;
  LoadStepper             stepper(scene, start_model, settings);
  start_model.set_reference_state();
  start_model.solve(stepper.load(Stage::prestretch, 1.));
  for (int k = 1; k <= 10; ++k)
    start_model.solve(stepper.load(Stage::dead_load, 0.1 * k));
  for (int k = 1; k <= 24; ++k)
    start_model.solve(stepper.load(Stage::voltage, 0.75 * k / 24.));
  const shooting::AngleTrace trace(scene, shooting::ShootingOptions());
  shooting::AnglePoint       start = trace.solve(start_model.shooting_angle(), 0.75,
                                                 start_model.profile().lambda1_start);
  check(start.ok && std::abs(start.t - 0.75) < 1e-9,
        "angle trace reproduces the 6 kV state from its angle");
  std::string why;
  const auto  fold = trace.limit_point(start, 0.01, 1e-10, &why);
  check(fold.has_value(), "angle trace finds a maximum of t(theta0): " + why);
  if (fold)
    {
      const double v_fold = fold->t * 8.;
      std::cout << "  fold: " << v_fold << " kV, displacement " << fold->displacement * 1e3
                << " mm, theta0 " << fold->theta0 << '\n';
      check(v_fold * 1e3 >= v_stop - 1e-6, "fold at or above the last load-stepping voltage");
      check(v_fold * 1e3 - v_stop < 10., "fold within 10 V of where load stepping stopped");
      check(v_fold > 6.5 && v_fold < 6.8, "fold between 6.5 and 6.8 kV (model-notes: above 6.5)");
    }
  return finish();
}
