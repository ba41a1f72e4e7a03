// Agreement of a refined FE run with the independent shooting solver (issue 3,
// item 3; doc/validation.md, "Agreement").
//
// Scenes: the three public cases of model-notes.md and seven of our own
// (other geometry and pre-stretch, other material and thickness, lighter and
// heavier weight, three rings with and without loss of tension, four rings),
// plus the two paper cases continued past their wrinkling onset. Each is run
// through all load stages by the same driver with both models:
//   FE:       p = 4, 16 graded elements per ring, bisected once (32 per ring);
//   shooting: Dormand-Prince tolerance 1e-12.
// At the end of the path they must agree to 1e-7 relative in the disk
// displacement, to 1e-5 in s2/mu at the inner edge of every ring (relative,
// or absolute 1e-7 where |s2/mu| < 0.01), and to 1e-8 a in the whole profile
// (r, z); the wrinkling onset (s2 = 0, located to 1e-4 V by both) must be
// found by both or by neither, at ring voltages within 0.01 V and at the same
// ring edge. The shooting values of the public cases must also reproduce the
// reference values of model-notes.md to their printed digits.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/shooting_model.h>

#include "check.h"
#include "scenes.h"
#include "validation_scenes.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace cdea;
using namespace cdea_test;

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  const auto       start = std::chrono::steady_clock::now();

  FeDiscretization refined;
  refined.degree            = 4;
  refined.elements_per_ring = 16;
  refined.refinements       = 1;
  shooting::ShootingOptions tight;
  tight.tolerance = 1e-12;

  for (const Case &c : cases())
    {
      std::cout << c.name << "\n";
      const Scene  &scene = c.scene;
      const double  mu    = scene.material.shear_modulus;
      MembraneModel fe_model(scene, refined, NewtonSettings());
      shooting::ShootingModel sh_model(scene, tight);
      const Run fe = run(fe_model, scene);
      const Run sh = run(sh_model, scene);
      if (!check(fe.result.completed, "FE run completes " + fe.result.message) ||
          !check(sh.result.completed, "shooting run completes " + sh.result.message))
        continue;

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

      // The whole profile: the FE solution at the shooting samples.
      std::vector<double> r, z;
      fe_model.profile_at(sh.fields.R, r, z);
      double worst = 0.;
      for (std::size_t i = 0; i < sh.fields.R.size(); ++i)
        worst = std::max(
          {worst, std::abs(r[i] - sh.fields.r[i]), std::abs(z[i] - sh.fields.z[i])});
      check_close(worst / scene.disk_radius, 0., 1e-8, "max |(r, z) FE - shooting| / a");

      // Loss of tension.
      check(fe.result.onset.found == sh.result.onset.found,
            std::string("onset found by both or by neither (FE ") +
              (fe.result.onset.found ? "yes" : "no") + ", shooting " +
              (sh.result.onset.found ? "yes" : "no") + ")");
      check(sh.result.onset.found == c.onset_expected,
            std::string("onset ") + (c.onset_expected ? "" : "not ") + "expected on this path");
      if (fe.result.onset.found && sh.result.onset.found)
        {
          for (unsigned int k = 0; k < scene.n_rings(); ++k)
            check_close(fe.result.onset.voltages[k], sh.result.onset.voltages[k], 0.01,
                        "onset voltage of ring " + std::to_string(k + 1) + " (V)");
          std::ostringstream where;
          where << "onset at the same place (r/a = "
                << sh.result.onset.radius / scene.disk_radius << ")";
          check_close(fe.result.onset.radius / scene.disk_radius,
                      sh.result.onset.radius / scene.disk_radius, 1e-9, where.str());
        }

      // Public reference values, printed to 5 decimals.
      if (c.public_displacement_mm > 0.)
        {
          check_close(sh.last.displacement * 1e3, c.public_displacement_mm, 0.5e-5 + 1e-12,
                      "shooting vs model-notes displacement (mm, 5 decimals)");
          for (unsigned int k = 0; k < c.public_s2_over_mu.size(); ++k)
            check_close(sh.last.s2_ring_inner[k] / mu, c.public_s2_over_mu[k], 0.5e-5 + 1e-12,
                        "shooting vs model-notes s2/mu, ring " + std::to_string(k + 1));
        }
    }
  std::cout << "time "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";
  return finish();
}
