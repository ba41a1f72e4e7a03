// The material laws by name (material/law_factory.h) and their declared
// internal variables (MembraneLaw::internal_variables()):
//  - both laws are registered (the linker keeps them) under the names of
//    Material/Model; make_membrane_law() builds each from plain settings,
//    network B's constants converted from the prm units;
//  - an unknown name and a missing constant are refused with messages that
//    name them;
//  - the two-network law declares xi1, xi2 (written, relaxed to l1, l2) and
//    their rates q1, q2 (not written, relaxed to 0): relaxed_internal_variables
//    follows the declaration; the Gent law declares none;
//  - the FE model's fields carry the written ones, by name, with their unit.

#include <cdea/fe/membrane_model.h>
#include <cdea/material/gent_law.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/two_network_gent.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <stdexcept>
#include <string>
#include <vector>

using namespace cdea;
using namespace cdea_test;

namespace
{
  const MaterialConstants film{25.1e3, 270., 3.98e-11, 1e-3};

  LawSettings settings(const std::string &model)
  {
    LawSettings s;
    s.model     = model;
    s.material  = film;
    s.constants = {{"Network B shear modulus (kPa)", 45.},
                   {"Network B Jlim", 60.},
                   {"Relaxation time (s)", 2.}};
    return s;
  }

  /// The message of what @p f throws as std::invalid_argument ("" if nothing).
  template <typename F>
  std::string refusal(F &&f)
  {
    try
      {
        f();
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

CDEA_TEST_MAIN()
{
  check(MembraneLaws::names() == std::vector<std::string>{"elastic", "gent-gent", "mooney-rivlin",
                                                         "neo-hooke", "ogden", "viscoelastic"},
        "the laws registered under the names of Material/Model");

  const auto elastic = make_membrane_law(settings("elastic"));
  const auto *gent   = dynamic_cast<const GentDielectricLaw *>(elastic.get());
  check(gent && gent->constants().shear_modulus == film.shear_modulus &&
          gent->constants().jlim == film.jlim && elastic->n_internal_variables() == 0,
        "elastic: the Gent law of the film, no internal variables");

  const auto  viscous = make_membrane_law(settings("viscoelastic"));
  const auto *two     = dynamic_cast<const TwoNetworkGentLaw *>(viscous.get());
  check(two && two->network_b().shear_modulus == 45e3 && two->network_b().jlim == 60. &&
          two->network_b().relaxation_time == 2. && two->network_a().jlim == film.jlim,
        "viscoelastic: network B's constants from kPa, network A the film");

  const std::string unknown = refusal([] { make_membrane_law(settings("hyperelastic")); });
  check(unknown.find("'hyperelastic'") != std::string::npos, "unknown law refused: " + unknown);
  LawSettings incomplete = settings("viscoelastic");
  incomplete.constants.erase("Network B Jlim");
  const std::string missing = refusal([&] { make_membrane_law(incomplete); });
  check(missing.find("Material/Network B Jlim") != std::string::npos,
        "missing constant refused: " + missing);

  // The declaration of the two-network law.
  const std::vector<InternalVariable> &declared = viscous->internal_variables();
  std::vector<std::string>             names, written;
  for (const InternalVariable &v : declared)
    {
      names.push_back(v.name);
      if (v.written)
        written.push_back(v.name);
    }
  check(names == std::vector<std::string>{"xi1", "xi2", "q1", "q2"} &&
          written == std::vector<std::string>{"xi1", "xi2"},
        "xi1, xi2, q1, q2 declared; xi1 and xi2 written");
  check(declared[0].relaxed == RelaxedValue::meridian_stretch &&
          declared[1].relaxed == RelaxedValue::hoop_stretch &&
          declared[2].relaxed == RelaxedValue::zero && declared[3].relaxed == RelaxedValue::zero,
        "xi relaxes to the stretches, q to zero");
  double relaxed[4] = {-1., -1., -1., -1.};
  viscous->relaxed_internal_variables({2.5, 1.75, 3e3}, relaxed);
  check(relaxed[0] == 2.5 && relaxed[1] == 1.75 && relaxed[2] == 0. && relaxed[3] == 0.,
        "relaxed_internal_variables follows the declaration");

  // The FE model's fields: the written variables by name.
  const Scene   scene = paper_scene({1., 3.}, {{0.}});
  MembraneModel model(scene, cdea_test::discretization(2, 4), NewtonSettings());
  model.set_material_law(viscous);
  const StepFields f = model.fields();
  check(f.internal.size() == 2 && f.internal[0].name == "xi1" && f.internal[1].name == "xi2" &&
          f.internal[0].unit == "1" && f.internal_values("xi1").size() == f.R.size(),
        "the FE fields hold xi1 and xi2 at every sample");
  return failures() ? 1 : 0;
}
