// Exact sensitivities to the laws' own constants (fe/sensitivities.h,
// ParameterKind::law_constant) against central differences of whole FE
// solves: the disk displacement and s2 at each ring's inner edge of the
// paper's two-ring scene (r_v/a = 1.7, 5/5 then 5/6 kV) under
// Mooney-Rivlin (d/dC2), Ogden (d/dalpha_1, d/dmu_2) and Gent-Gent (d/dC2),
// with the shear modulus beside them; and a constant the scene's law does
// not have refused by name.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/sensitivities.h>
#include <cdea/solver/load_stepper.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <cmath>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cdea;
using namespace cdea_test;

namespace
{
  struct Outputs
  {
    double              displacement = 0.;
    std::vector<double> s2_inner;
    Eigen::VectorXd     d_displacement;
    Eigen::MatrixXd     d_s2; ///< points x parameters
    unsigned int        first_edge = 0;
  };

  Outputs solve(const Scene &scene, const std::vector<SceneParameter> &parameters)
  {
    NewtonSettings newton;
    newton.residual_tolerance = 1e-12;
    newton.update_tolerance   = 1e-12;
    MembraneModel    model(scene, discretization(4, 3), newton);
    SteppingSettings settings;
    LoadStepper      stepper(scene, model, settings);
    StepSummary      last;
    stepper.on_step = [&](const StepSummary &s) { last = s; };
    if (!stepper.run().completed)
      throw std::runtime_error("solve did not complete");
    const StateSensitivity at(model, parameters);
    const PointValues      points = at.points();
    return {model.displacement(), last.s2_ring_inner, at.d_displacement(), points.d_s2,
            points.n_quadrature_points};
  }

  void check_law(const std::string &model, const std::map<std::string, double> &constants,
                 const std::vector<std::string> &entries)
  {
    std::cout << model << "\n";
    Scene scene          = paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 6.}});
    scene.material_model = model;
    scene.law_constants  = constants;
    std::vector<SceneParameter> parameters{{ParameterKind::shear_modulus, 0, ""}};
    for (const std::string &e : entries)
      parameters.push_back({ParameterKind::law_constant, 0, e});
    const Outputs base = solve(scene, parameters);
    for (unsigned int j = 0; j < parameters.size(); ++j)
      {
        const SceneParameter &p = parameters[j];
        const double          v = parameter_value(scene, p), h = 1e-5 * std::abs(v);
        const Outputs plus  = solve(with_parameter(scene, p, v + h), {});
        const Outputs minus = solve(with_parameter(scene, p, v - h), {});
        const double  fd    = (plus.displacement - minus.displacement) / (2 * h);
        check_rel(base.d_displacement[j], fd, 1e-6, "d displacement / d " + p.name());
        for (unsigned int k = 0; k < scene.n_rings(); ++k)
          check_rel(base.d_s2(base.first_edge + k, j),
                    (plus.s2_inner[k] - minus.s2_inner[k]) / (2 * h), 1e-6,
                    "d s2(inner edge of ring " + std::to_string(k + 1) + ") / d " + p.name());
      }
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  check_law("mooney-rivlin", {{"Mooney-Rivlin C2 (kPa)", 2.}}, {"Mooney-Rivlin C2 (kPa)"});
  check_law("ogden",
            {{"Ogden alpha 1", 1.5},
             {"Ogden mu 2 (kPa)", -2.},
             {"Ogden alpha 2", -2.},
             {"Ogden mu 3 (kPa)", 0.01},
             {"Ogden alpha 3", 5.}},
            {"Ogden alpha 1", "Ogden mu 2 (kPa)"});
  check_law("gent-gent", {{"Gent-Gent C2 (kPa)", 2.}}, {"Gent-Gent C2 (kPa)"});

  // A constant the law does not have.
  Scene scene          = paper_scene({1., 3.}, {{5.}});
  scene.material_model = "neo-hooke";
  std::string message;
  try
    {
      solve(scene, {{ParameterKind::law_constant, 0, "Mooney-Rivlin C2 (kPa)"}});
    }
  catch (const std::exception &e)
    {
      message = e.what();
    }
  check(message.find("'Mooney-Rivlin C2 (kPa)' is not a constant of the scene's law") !=
          std::string::npos,
        "a constant of another law refused: " + message);
  return finish();
}
