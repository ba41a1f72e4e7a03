// The FE model and the independent shooting solver with the laws of the
// library other than Gent (issue 20, item 1; doc/materials.md, "FE and
// shooting"): neo-Hooke, Mooney-Rivlin (C2 = 5 kPa), a three-term Ogden law
// and Gent-Gent (C2 = 5 kPa), each on the twelve validation scenes of
// tests/test_validation_agreement.cc with the same discretizations (FE p = 4,
// 32 graded elements per ring; shooting tolerance 1e-12) and tolerances: the
// disk displacement to 1e-7 relative, s2/mu at each ring's inner edge to
// 1e-5 (absolute 1e-7 where |s2/mu| < 0.01), the profile (r, z) to 1e-8 a,
// and the wrinkling onset found by both or neither, within 0.01 V.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/shooting_model.h>

#include "check.h"
#include "validation_scenes.h"

#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace cdea;
using namespace cdea_test;

namespace
{
  struct LawCase
  {
    std::string                   model;
    std::map<std::string, double> constants;
  };

  void compare(const Case &c, const LawCase &law)
  {
    Scene scene          = c.scene;
    scene.material_model = law.model;
    scene.law_constants  = law.constants;
    const double mu      = scene.material.shear_modulus;

    FeDiscretization refined;
    refined.degree            = 4;
    refined.elements_per_ring = 16;
    refined.refinements       = 1;
    shooting::ShootingOptions tight;
    tight.tolerance = 1e-12;
    MembraneModel           fe_model(scene, refined, NewtonSettings());
    shooting::ShootingModel sh_model(scene, tight);
    const Run               fe = run(fe_model, scene);
    const Run               sh = run(sh_model, scene);
    if (!fe.result.completed || !sh.result.completed)
      {
        // A law without a limiting stretch meets the pull-in fold on some
        // paths: both models stop there, at the same voltage.
        const double v_fe = fe.last.voltages.back(), v_sh = sh.last.voltages.back();
        std::cout << "  stopped: FE at " << v_fe << " V (" << fe.result.message.substr(0, 60)
                  << "...), shooting at " << v_sh << " V (" << sh.result.message.substr(0, 60)
                  << "...)\n";
        check(!fe.result.completed && !sh.result.completed, "both models stop before the end");
        check_rel(v_fe, v_sh, 1e-3, "last converged voltage of the last ring, FE vs shooting");
        return;
      }

    check_rel(fe.last.displacement * 1e3, sh.last.displacement * 1e3, 1e-7,
              "displacement (mm), FE vs shooting");
    for (unsigned int k = 0; k < scene.n_rings(); ++k)
      {
        const double a = fe.last.s2_ring_inner[k] / mu, b = sh.last.s2_ring_inner[k] / mu;
        const std::string what = "s2/mu at the inner edge of ring " + std::to_string(k + 1);
        if (std::abs(b) >= 0.01)
          check_rel(a, b, 1e-5, what);
        else
          check_close(a, b, 1e-7, what);
      }
    std::vector<double> r, z;
    fe_model.profile_at(sh.fields.R, r, z);
    double worst = 0.;
    for (std::size_t i = 0; i < sh.fields.R.size(); ++i)
      worst = std::max({worst, std::abs(r[i] - sh.fields.r[i]), std::abs(z[i] - sh.fields.z[i])});
    check_close(worst / scene.disk_radius, 0., 1e-8, "max |(r, z) FE - shooting| / a");

    check(fe.result.onset.found == sh.result.onset.found,
          std::string("onset found by both or by neither (FE ") +
            (fe.result.onset.found ? "yes" : "no") + ", shooting " +
            (sh.result.onset.found ? "yes" : "no") + ")");
    if (fe.result.onset.found && sh.result.onset.found)
      for (unsigned int k = 0; k < scene.n_rings(); ++k)
        check_close(fe.result.onset.voltages[k], sh.result.onset.voltages[k], 0.01,
                    "onset voltage of ring " + std::to_string(k + 1) + " (V)");
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession           mpi(argc, argv);
  const std::vector<LawCase> laws{
    {"neo-hooke", {}},
    {"mooney-rivlin", {{"Mooney-Rivlin C2 (kPa)", 5.}}},
    {"ogden",
     {{"Ogden alpha 1", 1.5},
      {"Ogden mu 2 (kPa)", -2.},
      {"Ogden alpha 2", -2.},
      {"Ogden mu 3 (kPa)", 0.01},
      {"Ogden alpha 3", 5.}}},
    {"gent-gent", {{"Gent-Gent C2 (kPa)", 5.}}}};
  for (const LawCase &law : laws)
    for (const Case &c : cases())
      {
        std::cout << law.model << ": " << c.name << "\n";
        compare(c, law);
      }
  return finish();
}
