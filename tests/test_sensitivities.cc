// Exact sensitivities (fe/sensitivities.h) against central finite differences.
//
// 1. The kernel's dR/dp at fixed nodal values against differences of the
//    residual of models rebuilt with the parameter changed (every parameter
//    kind; the ring edges and the pre-stretch move the mesh).
// 2. The outputs of whole solves (the load stages from the unstretched film
//    to the end of the voltage path, on a new model for every solve):
//    displacement, stroke, enclosed volume change, s2 and E at every
//    quadrature point and ring inner edge, on 1, 2 and 3 rings, for every
//    parameter, against the direct method; the adjoint against the direct.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/sensitivities.h>
#include <cdea/solver/load_stepper.h>

#include "check.h"
#include "fe_checks.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

using namespace cdea;
using namespace cdea_test;

namespace
{
  NewtonSettings tight_newton()
  {
    NewtonSettings n;
    n.residual_tolerance = 1e-12;
    n.update_tolerance   = 1e-12;
    return n;
  }

  /// The outputs of one whole solve, and (optionally) their exact gradients.
  struct Solved
  {
    double          displacement = 0., stroke = 0., volume_change = 0.;
    Eigen::VectorXd s2, field;  ///< quadrature points, then the ring inner edges
    unsigned int    n_quadrature_points = 0;
    Eigen::VectorXd d_displacement, d_stroke, d_volume_change;
    Eigen::MatrixXd d_s2, d_field;
    std::unique_ptr<MembraneModel> model;
  };

  Solved solve(const Scene &scene, const std::vector<SceneParameter> *parameters)
  {
    Solved out;
    out.model = std::make_unique<MembraneModel>(scene, discretization(4, 3), tight_newton());
    SteppingSettings settings;
    LoadStepper      stepper(scene, *out.model, settings);
    double           reference_displacement = 0., reference_volume = 0.;
    Eigen::VectorXd  d_reference_displacement, d_reference_volume;
    stepper.on_step = [&](const StepSummary &s) {
      if (s.stage == Stage::dead_load && s.load_factor == 1.)
        {
          reference_displacement = s.displacement;
          reference_volume       = out.model->enclosed_volume();
          if (parameters)
            {
              const StateSensitivity at_reference(*out.model, *parameters);
              d_reference_displacement = at_reference.d_displacement();
              d_reference_volume       = at_reference.d_volume();
            }
        }
    };
    const RunResult run = stepper.run();
    if (!run.completed)
      throw std::runtime_error("solve did not complete: " + run.message);
    out.displacement  = out.model->displacement();
    out.stroke        = out.displacement - reference_displacement;
    out.volume_change = out.model->enclosed_volume() - reference_volume;
    const StateSensitivity at_end(*out.model, parameters ? *parameters :
                                                           std::vector<SceneParameter>{});
    const PointValues points = at_end.points();
    out.s2                  = points.s2;
    out.field               = points.field;
    out.n_quadrature_points = points.n_quadrature_points;
    if (parameters)
      {
        out.d_displacement  = at_end.d_displacement();
        out.d_stroke        = at_end.d_displacement() - d_reference_displacement;
        out.d_volume_change = at_end.d_volume() - d_reference_volume;
        out.d_s2            = points.d_s2;
        out.d_field         = points.d_field;
      }
    return out;
  }

  /// max |a - b| / max |b|.
  double relative_difference(const Eigen::VectorXd &a, const Eigen::VectorXd &b)
  {
    return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
  }

  /// The step of the central difference of parameter @p p.
  double step_of(const SceneParameter &p, const double value)
  {
    return p.kind == ParameterKind::ring_edge ? 1e-5 : 1e-5 * std::abs(value);
  }

  void check_kernel(const Scene &scene, const std::string &what)
  {
    std::cout << "dR/dp of the kernel at fixed nodal values, " << what << "\n";
    const auto    parameters = all_parameters(scene.n_rings());
    MembraneModel model(scene, discretization(3, 2), tight_newton());
    SteppingSettings settings;
    LoadStepper      stepper(scene, model, settings);
    stepper.run();
    const ModelState       state = model.state();
    const StateSensitivity exact(model, parameters);
    double                 worst = 0.;
    for (unsigned int j = 0; j < parameters.size(); ++j)
      {
        const SceneParameter &p = parameters[j];
        const double          v = parameter_value(scene, p), h = step_of(p, v);
        std::vector<double>   r[2];
        for (int side = 0; side < 2; ++side)
          {
            const double value   = v + (side == 0 ? h : -h);
            const Scene  changed = with_parameter(scene, p, value);
            MembraneModel other(changed, discretization(3, 2), tight_newton());
            ModelState    s = state;
            if (p.kind == ParameterKind::voltage)
              s.load.voltages[p.index] = value;
            if (p.kind == ParameterKind::mass)
              {
                s.load.mass  = value;
                s.load.force = value * scene.gravity;
              }
            other.set_state(s);
            r[side] = other.residual_vector();
          }
        Eigen::VectorXd fd(r[0].size());
        for (unsigned int i = 0; i < fd.size(); ++i)
          fd[i] = (r[0][i] - r[1][i]) / (2. * h);
        for (const unsigned int i : model.discretization().constrained)
          fd[i] = 0.;
        const double e = relative_difference(exact.residual_derivative().col(j), fd);
        worst          = std::max(worst, e);
        check_close(e, 0., 1e-7, "  " + p.name());
      }
    std::cout << "  worst " << worst << "\n";
  }

  void check_outputs(const Scene &scene, const std::string &what)
  {
    std::cout << "Whole solves, " << what << "\n";
    const auto   parameters = all_parameters(scene.n_rings());
    const Solved base       = solve(scene, &parameters);
    double       worst[7]   = {0., 0., 0., 0., 0., 0., 0.};
    for (unsigned int j = 0; j < parameters.size(); ++j)
      {
        const SceneParameter &p = parameters[j];
        const double          v = parameter_value(scene, p), h = step_of(p, v);
        const Solved          plus  = solve(with_parameter(scene, p, v + h), nullptr);
        const Solved          minus = solve(with_parameter(scene, p, v - h), nullptr);
        const auto            fd    = [&](const double a, const double b) { return (a - b) / (2. * h); };
        // The quadrature points and the ring inner edges (which carry the
        // jump of the voltage) each with their own max-norm.
        const unsigned int Q = base.n_quadrature_points, P = unsigned(base.s2.size());
        const auto         compare = [&](const Eigen::VectorXd &exact, const Eigen::VectorXd &a,
                                 const Eigen::VectorXd &b, const bool edges) {
          const unsigned int first = edges ? Q : 0, count = edges ? P - Q : Q;
          return relative_difference(exact.segment(first, count),
                                     (a - b).segment(first, count) / (2. * h));
        };
        const double e[7] = {
          std::abs(fd(plus.displacement, minus.displacement) / base.d_displacement[j] - 1.),
          std::abs(fd(plus.stroke, minus.stroke) / base.d_stroke[j] - 1.),
          std::abs(fd(plus.volume_change, minus.volume_change) / base.d_volume_change[j] - 1.),
          compare(base.d_s2.col(j), plus.s2, minus.s2, false),
          compare(base.d_s2.col(j), plus.s2, minus.s2, true),
          compare(base.d_field.col(j), plus.field, minus.field, false),
          compare(base.d_field.col(j), plus.field, minus.field, true)};
        const std::string names[7] = {"displacement",        "stroke",
                                      "volume change",       "s2 at the quadrature points",
                                      "s2 at the ring inner edges", "E at the quadrature points",
                                      "E at the ring inner edges"};
        for (int k = 0; k < 7; ++k)
          {
            worst[k] = std::max(worst[k], e[k]);
            check_close(e[k], 0., 1e-6, "  d(" + names[k] + ")/d(" + p.name() + ")");
          }
      }
    check(base.n_quadrature_points > 0 &&
            base.s2.size() == Eigen::Index(base.n_quadrature_points + scene.n_rings()),
          "  one value at the inner edge of each ring after the quadrature points");
    std::cout << "  worst relative differences: displacement " << worst[0] << ", stroke "
              << worst[1] << ", volume change " << worst[2] << ", s2 " << worst[3]
              << " (ring edges " << worst[4] << "), E " << worst[5] << " (ring edges " << worst[6]
              << ")\n";
  }

  void check_adjoint(const Scene &scene)
  {
    std::cout << "Adjoint against direct\n";
    const auto       parameters = all_parameters(scene.n_rings());
    const Solved     base       = solve(scene, &parameters);
    StateSensitivity s(*base.model, parameters);
    const unsigned int N = base.model->n_dofs();
    // The displacement: dJ/dx = e_zA - e_zB, no explicit part.
    Eigen::VectorXd g = Eigen::VectorXd::Zero(N);
    g[base.model->disk_z_dof()] = 1.;
    const Eigen::VectorXd direct  = s.d_displacement();
    const Eigen::VectorXd adjoint = s.adjoint(g, Eigen::VectorXd::Zero(parameters.size()));
    check_close(relative_difference(adjoint, direct), 0., 1e-12,
                "displacement gradient, adjoint vs direct");
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  const Scene one   = paper_scene({1., 3.}, {{5.}});
  const Scene two   = paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 6.}});
  const Scene three = paper_scene({1., 1.5, 2.2, 3.}, {{4., 5., 6.}});

  check_kernel(three, "3 rings");
  check_outputs(one, "1 ring, 5 kV");
  check_outputs(two, "2 rings, r_v/a = 1.7, 5/6 kV");
  check_outputs(three, "3 rings, edges 1.5, 2.2, 4/5/6 kV");
  check_adjoint(two);
  return finish();
}
