// Newton near the Gent limit (issue 19, item 5). As (I - 3) / Jlim nears 1
// the stiffness, and with it the round-off level of the residual, grows
// without bound; with NewtonSettings::converge_at_round_off Newton counts a
// state at that level (with an update below its tolerance) as converged; by
// default it stops there, and says the Gent limit is the cause. The paper's
// cone with Jlim lowered towards
// the pre-stretch's own I - 3 = 2 lam^2 + lam^-4 - 3 = 9.526 (lam = 2.5):
//
//   - down to Jlim = 9.53 (within 0.05 % of the limit in the pre-stretched
//     film) the whole run completes (before: Jlim = 9.6 stalled in the
//     pre-stretch stage, and a 300 kg load at Jlim = 10), the dead load's
//     displacement shrinking with Jlim as the film stiffens; without the
//     setting Jlim = 9.6 stops with a message naming the limit;
//   - at Jlim = 9.5 (the pre-stretch alone beyond the limit) the run fails
//     with a message that names the Gent limit as the cause.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <iostream>
#include <limits>
#include <string>

using namespace cdea;
using namespace cdea_test;

namespace
{
  RunResult run(const double jlim, const double mass, double &displacement,
                const bool at_round_off = true)
  {
    NewtonSettings newton;
    newton.converge_at_round_off = at_round_off;
    Scene scene         = paper_scene({1., 3.}, {{5.}});
    scene.material.jlim = jlim;
    scene.mass          = mass;
    MembraneModel model(scene, discretization(2, 40), newton);
    RunResult     result;
    run_to_end(model, scene, &result);
    displacement = model.displacement();
    return result;
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);

  std::cout << "Close to the limit: the run completes\n";
  double previous = std::numeric_limits<double>::infinity();
  for (const double jlim : {11., 10., 9.6, 9.55, 9.53})
    {
      double          displacement = 0.;
      const RunResult r            = run(jlim, 0.28, displacement);
      check(r.completed, "Jlim = " + std::to_string(jlim) + ": completes " + r.message);
      check(displacement > 0. && displacement < previous,
            "  the displacement shrinks as the film stiffens: " + std::to_string(displacement));
      previous = displacement;
    }
  {
    double          displacement = 0.;
    const RunResult r            = run(10., 300., displacement);
    check(r.completed, "Jlim = 10, 300 kg: completes " + r.message);
  }

  std::cout << "Without converge_at_round_off (the default): stalls, naming the limit\n";
  {
    double          displacement = 0.;
    const RunResult r            = run(9.6, 0.28, displacement, false);
    std::cout << "  " << r.message << '\n';
    check(!r.completed, "Jlim = 9.6: fails");
    check(r.message.find("% of the Gent limit (I1 - 3 = ") != std::string::npos &&
            r.message.find("Jlim = 9.6 ") != std::string::npos,
          "  the message names the Gent limit and Jlim");
  }

  std::cout << "Beyond the limit: the message names it\n";
  {
    double          displacement = 0.;
    const RunResult r            = run(9.5, 0.28, displacement);
    std::cout << "  " << r.message << '\n';
    check(!r.completed, "Jlim = 9.5: fails");
    check(r.message.find("the Gent limit (I1 - 3 = ") != std::string::npos &&
            r.message.find("Jlim = 9.5 ") != std::string::npos,
          "  the message names the Gent limit and Jlim");
  }
  return finish();
}
