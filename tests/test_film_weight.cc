// The film's own weight (source/fe/film_weight_term.cc, the load term "film
// weight"), a load term written as a plugin from scratch (its file and this
// test are all there is):
//  - off by default: Material/Density (kg/m^3) = 0 puts no term into the
//    model, so earlier parameter files and results stay as they were;
//  - its potential: every z moved down by z0 changes it by
//    -rho g H pi (B^2 - A^2) z0 (the film's weight times the drop);
//  - its residual sums over the z unknowns to minus the film's weight;
//  - the residual against differences of the potential and the tangent
//    against differences of the residual, at equilibrium and off it;
//  - at equilibrium the membrane's axial force at every radius carries the
//    dead load and the film inside it,
//    2 pi R H s1 sin(theta) = F + rho g H pi (R^2 - A^2);
//  - its entry checked, time runs and arc length accepted, the shooting model
//    refusing it by its entry.

#include <cdea/analysis/run_input.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/base/text.h>
#include <cdea/fe/load_term.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace cdea;
using namespace cdea_test;

namespace
{
  constexpr double density = 1e5; // kg/m^3: a film of about 80 g beside the 280 g weight

  Parameters with_film(const std::string &more = "")
  {
    return read_parameters(ParameterInput::text(
      "subsection Material\n  set Density (kg/m^3) = 100000\nend\n" + more));
  }

  /// The input error of @p text ("" if none).
  std::string input_error(const std::string &text)
  {
    try
      {
        read_parameters(ParameterInput::text(text));
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  /// The film's weight rho g H pi (B^2 - A^2) (N), on the undeformed film.
  double film_weight(const Scene &scene)
  {
    const double A = scene.inner_reference_radius(), B = scene.outer_reference_radius();
    return density * scene.gravity * scene.material.thickness * M_PI * (B * B - A * A);
  }

  /// The term's share of the potential and of the residual at the state
  /// of @p with (the same model without the term at the same state and load).
  void check_potential_and_residual(MembraneModel &with, MembraneModel &without,
                                    const Scene &scene)
  {
    const auto   x    = with.solution();
    const auto   dofs = with.dof_support();
    const double z0   = 1e-3;
    auto         down = x;
    for (unsigned int i = 0; i < x.size(); ++i)
      if (dofs[i].second == 1)
        down[i] += z0;
    without.set_solution(x);
    const double d0 = with.energy() - without.energy();
    const auto   r  = with.residual_vector(), r0 = without.residual_vector();
    with.set_solution(down);
    without.set_solution(down);
    const double d1 = with.energy() - without.energy();
    with.set_solution(x);
    check_rel(d1 - d0, -film_weight(scene) * z0, 1e-9,
              "moving every z down by 1 mm: the weight's work");
    double sum = 0.;
    for (unsigned int i = 0; i < x.size(); ++i)
      if (dofs[i].second == 1)
        sum += r[i] - r0[i];
    check_rel(sum, -film_weight(scene), 1e-12, "the residual's z entries: minus the weight");
  }

  /// The axial force balance inside every radius of a converged state.
  void check_force_balance(const MembraneModel &model, const Scene &scene, const double tolerance,
                           const std::string &what)
  {
    const StepFields f = model.fields();
    const double     H = scene.material.thickness, A = scene.inner_reference_radius();
    double           worst = 0.;
    for (unsigned int i = 0; i < f.R.size(); ++i)
      {
        const double load  = scene.dead_load() +
                            density * scene.gravity * H * M_PI * (f.R[i] * f.R[i] - A * A);
        const double axial = 2. * M_PI * f.R[i] * H * f.s1[i] * std::sin(f.theta[i]);
        worst              = std::max(worst, std::abs(axial / load - 1.));
      }
    check_close(worst, 0., tolerance, what);
  }
} // namespace

CDEA_TEST_MAIN()
{
  std::cout << "Off by default\n";
  const Parameters defaults = read_parameters(ParameterInput::text(""));
  check(make_load_terms(defaults.load_terms.values).empty(), "no load term from the defaults");

  std::cout << "The film's weight in the model\n";
  const Parameters p     = with_film();
  const Scene      scene = p.scene();
  const auto       terms = make_load_terms(p.load_terms.values);
  check(terms.size() == 1 && terms[0]->describe() == "Film weight: density 100000 kg/m^3",
        "Material/Density (kg/m^3) switches it on");
  for (const unsigned int degree : {1u, 3u})
    {
      MembraneModel with(scene, discretization(degree, 4), NewtonSettings());
      MembraneModel without(scene, discretization(degree, 4), NewtonSettings());
      with.set_load_terms(p.load_terms.values);
      const StepSummary a = run_to_end(with, scene), b = run_to_end(without, scene);
      const std::string label = "p=" + std::to_string(degree);
      check(a.displacement > b.displacement, label + ": the film's weight pulls the disk further");
      check_potential_and_residual(with, without, scene);
      check_derivatives(with, label + " at equilibrium");
      auto x = with.solution();
      for (unsigned int i = 0; i < x.size(); ++i)
        x[i] *= 1. + 0.01 * std::sin(1.3 * i);
      with.set_solution(x);
      check_derivatives(with, label + " off equilibrium");
    }

  std::cout << "Vertical force balance inside every radius\n";
  for (const bool refined : {false, true})
    {
      MembraneModel model(scene, refined ? discretization(4, 16, 1, 8) : discretization(3, 8, 0, 8),
                          NewtonSettings());
      model.set_load_terms(p.load_terms.values);
      run_to_end(model, scene);
      check_force_balance(model, scene, refined ? 1e-6 : 3e-4,
                          refined ? "  refined mesh (p=4, 32 elements per ring)" : "  default mesh");
    }

  std::cout << "Its entry and what it supports\n";
  const std::string negative =
    input_error("subsection Material\n  set Density (kg/m^3) = -1\nend\n");
  check(negative == "Material/Density (kg/m^3) must be zero or positive, got -1",
        "a negative density: " + negative);
  check(input_error("subsection Material\n  set Density (kg/m^3) = 1000\nend\n"
                    "subsection Time\n  set Enabled = true\nend\n")
            .empty(),
        "with a time run");
  check(input_error("subsection Material\n  set Density (kg/m^3) = 1000\nend\n"
                    "subsection Solver\n  set Continuation = arc length\nend\n")
            .empty(),
        "with arc length");
  std::string shoot;
  try
    {
      run_input(p, "", RunMethod::shooting, "shoot");
    }
  catch (const InputError &e)
    {
      shoot = e.what();
    }
  check(shoot == "Material/Density (kg/m^3) = 100000 is implemented in the FE model only: "
                 "use 'cdea run', or set it to 0 for 'cdea shoot'",
        "shoot refuses it: " + shoot);
  check(make_fe_model(p, scene)->load_terms().size() == 1, "a run's FE model holds it");
  return finish();
}
