// Newton's residual-alone trials (NewtonSettings::residual_alone_at_backtracks
// and residual_alone_when_converging) change nothing but the work: with them
// on and off, the same runs give bit for bit the same states, Newton
// iterations, eigenvalues and tangents, for each elastic law, with and
// without a converged tangent asked for after every solve (the stability
// check), and through line searches that shorten the step (a voltage beyond
// the path's fold in one step).

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/model/load_state.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// What a sequence of solves leaves: every state, iteration count and
  /// eigenvalue, and the last tangent.
  struct Trace
  {
    std::vector<double>              numbers;
    std::vector<std::vector<double>> tangent;
  };

  Trace trace(const Scene &scene, const bool residual_alone, const bool with_stability)
  {
    NewtonSettings newton;
    newton.residual_alone_at_backtracks   = residual_alone;
    newton.residual_alone_when_converging = residual_alone;
    MembraneModel model(scene, discretization(4, 6), newton);
    Trace         t;
    const auto    solve = [&](const LoadState &load) {
      const SolveReport r = model.solve(load);
      t.numbers.push_back(r.converged);
      t.numbers.push_back(r.iterations);
      const ModelState s = model.state();
      t.numbers.insert(t.numbers.end(), s.unknowns.begin(), s.unknowns.end());
      if (with_stability)
        t.numbers.push_back(model.min_tangent_eigenvalue());
    };
    LoadState load;
    load.voltages.assign(scene.n_rings(), 0.);
    for (int k = 1; k <= 4; ++k)
      {
        load.stretch = 1. + (scene.prestretch - 1.) * k / 4.;
        solve(load);
      }
    // The dead load and 5 kV at once: the line search shortens the first
    // steps; then back and along the path in steps.
    solve(full_load(scene, {5e3}, 1.));
    // 12 kV at once, beyond the fold of the voltage path: the line search
    // shortens Newton's steps many times (about 25 shortened trials here).
    solve(full_load(scene, {12e3}, 1.));
    for (int k = 0; k <= 8; ++k)
      solve(full_load(scene, {5e3 * k / 8.}, k / 8.));
    t.tangent = model.tangent_matrix();
    return t;
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  // Each law with constants as in test_law_agreement.
  const std::vector<std::pair<std::string, std::map<std::string, double>>> laws = {
    {"elastic", {}},
    {"neo-hooke", {}},
    {"mooney-rivlin", {{"Mooney-Rivlin C2 (kPa)", 5.}}},
    {"ogden",
     {{"Ogden alpha 1", 1.5},
      {"Ogden mu 2 (kPa)", -2.},
      {"Ogden alpha 2", -2.},
      {"Ogden mu 3 (kPa)", 0.01},
      {"Ogden alpha 3", 5.}}},
    {"gent-gent", {{"Gent-Gent C2 (kPa)", 5.}}}};
  for (const auto &[law, constants] : laws)
    for (const bool with_stability : {false, true})
      {
        Scene scene          = paper_scene({1., 3.}, {{5.}});
        scene.material_model = law;
        scene.law_constants  = constants;
        const Trace on  = trace(scene, true, with_stability);
        const Trace off = trace(scene, false, with_stability);
        const std::string what =
          law + (with_stability ? ", stability after every solve" : ", no stability check");
        check(on.numbers.size() == off.numbers.size() && on.numbers == off.numbers,
              what + ": states, iterations and eigenvalues identical");
        check(on.tangent == off.tangent, what + ": the last tangent identical");
        std::cout << what << ": " << on.numbers.size() << " numbers identical\n";
      }
  return finish();
}
