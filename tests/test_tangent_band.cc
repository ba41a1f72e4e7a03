// The band of the tangent on the default mesh (degree 4, 4 cells per ring):
// with Cuthill-McKee the 10 dofs of a cell are numbered consecutively, so the
// band is 9, the least any numbering can give.
// A change of the dof order or of the band storage shows here first.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>

#include "check.h"
#include "scenes.h"

#include <string>

using namespace cdea;
using namespace cdea_test;

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  const Scene      full = paper_scene({1., 3.}, {{5.}});
  const Scene      part = paper_scene({1., 1.7, 3.}, {{5., 6.}});
  for (const Scene *scene : {&full, &part})
    {
      const std::string   name = std::to_string(scene->n_rings()) + " ring(s)";
      const MembraneModel model(*scene, FeDiscretization(), NewtonSettings());
      check(model.discretization().dofs_per_cell() == 10, name + ": 10 dofs per cell");
      check(model.discretization().bandwidth() == 9,
            name + ": mesh band " + std::to_string(model.discretization().bandwidth()) +
              " (expected 9)");
      AssembledSystem system;
      check(model.assemble(assemble_residual | assemble_tangent, system),
            name + ": the reference state assembles");
      check(system.tangent.bandwidth() == 9 && system.tangent.size() == model.n_dofs(),
            name + ": tangent band " + std::to_string(system.tangent.bandwidth()) +
              " (expected 9) over " + std::to_string(model.n_dofs()) + " dofs");
    }
  return finish();
}
