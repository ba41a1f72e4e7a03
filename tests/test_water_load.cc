// Hydrostatic water load of the pump (issue 6, FE model): the residual against
// central differences of the potential (which includes the water's E_w), the
// tangent (local follower-load terms plus the rank-one free-surface term)
// against central differences of the residual, the vertical force balance of
// the disk and the membrane inside every radius under the water's pressure,
// quadratic Newton convergence through the Sherman-Morrison solve, and the
// refusal of a state in which the water no longer fills the cone.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/water_term.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

using namespace cdea;
using namespace cdea_test;

namespace
{
  WaterLoad paper_water()
  {
    WaterLoad w;
    w.enabled = true; // 150 ml, 1000 kg/m^3, 9.81 m/s^2, 20 mm x 20 mm tube
    return w;
  }

  /// The water term with @p w, as the model's load terms.
  std::vector<std::unique_ptr<LoadTerm>> water_terms(const WaterLoad &w)
  {
    auto term = std::make_unique<WaterTerm>();
    term->set_water(w);
    std::vector<std::unique_ptr<LoadTerm>> terms;
    terms.push_back(std::move(term));
    return terms;
  }

  /// The model's water term.
  const WaterTerm &water_of(const MembraneModel &model)
  {
    return dynamic_cast<const WaterTerm &>(*model.load_terms().at(0));
  }

  /// Largest entry of the water's share of the tangent at the current state
  /// (the model with the water on minus the same model with it off).
  double water_tangent_scale(MembraneModel &model)
  {
    const WaterLoad w = water_of(model).water();
    const auto      K = model.tangent_matrix();
    model.set_load_terms(std::vector<std::unique_ptr<LoadTerm>>());
    const auto K0 = model.tangent_matrix();
    model.set_load_terms(water_terms(w));
    double d = 0.;
    for (unsigned int i = 0; i < K.size(); ++i)
      for (unsigned int j = 0; j < K.size(); ++j)
        d = std::max(d, std::abs(K[i][j] - K0[i][j]));
    return d;
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  const Scene      pump = paper_scene({1., 1.7, 3.}, {{4., 4.}, {4., 5.}});

  std::cout << "Derivatives with the water load\n";
  {
    MembraneModel model(pump, discretization(3, 4), NewtonSettings());
    model.set_load_terms(water_terms(paper_water()));
    run_to_end(model, pump);
    double K_scale = 0.;
    for (const auto &row : model.tangent_matrix())
      for (const double k : row)
        K_scale = std::max(K_scale, std::abs(k));
    check(water_tangent_scale(model) > 1e-3 * K_scale, "the water changes the tangent noticeably");
    check_derivatives(model, "pump 4 / 5 kV with water, p=3");
    auto x = model.solution();
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] *= 1. + 0.01 * std::sin(1.7 * i); // off equilibrium, z(B) != 0 too
    model.set_solution(x);
    check_derivatives(model, "perturbed state");
  }
  {
    // Halfway through the load stage: the water's gravity is ramped with it.
    MembraneModel model(pump, discretization(1, 6), NewtonSettings());
    model.set_load_terms(water_terms(paper_water()));
    LoadState load;
    load.stage    = Stage::prestretch;
    load.stretch  = pump.prestretch;
    load.voltages = {0., 0.};
    check(model.solve(load).converged, "pre-stretch");
    for (const double t : {0.25, 0.5})
      {
        load.stage       = Stage::dead_load;
        load.load_factor = t;
        load.mass        = pump.mass * t;
        load.force       = pump.dead_load() * t;
        check(model.solve(load).converged, "dead load stage at t = " + std::to_string(t));
      }
    check_derivatives(model, "load stage t = 0.5 with water, p=1");
  }

  std::cout << "Vertical force balance inside every radius, with the water\n";
  // 2 pi R H s1 sin(theta) = F + rho g (h + z_A) pi a^2 + 2 pi rho g int_A^R (h + z) r r' dR:
  // the membrane's axial force carries the weight, the water on the disk and
  // the water on the membrane inside R (pressure normal to the membrane).
  for (const bool refined : {false, true})
    {
      MembraneModel model(pump, refined ? discretization(4, 16, 1, 8) : discretization(3, 8, 0, 8),
                          NewtonSettings());
      const WaterLoad w = paper_water();
      model.set_load_terms(water_terms(w));
      run_to_end(model, pump);
      const StepFields f    = model.fields();
      const double     head = water_of(model).free_surface_height(model.enclosed_volume());
      const double     rg   = w.density * w.gravity, H = pump.material.thickness;
      const double     a    = f.r.front();
      double           load = pump.dead_load() + rg * (head + f.z.front()) * M_PI * a * a;
      double           worst = 0.;
      for (unsigned int i = 0; i < f.R.size(); ++i)
        {
          if (i > 0) // trapezoid of (h + z) d(r^2 / 2)
            load += 2. * M_PI * rg * (head + 0.5 * (f.z[i] + f.z[i - 1])) * 0.5 *
                    (f.r[i] * f.r[i] - f.r[i - 1] * f.r[i - 1]);
          const double axial = 2. * M_PI * f.R[i] * H * f.s1[i] * std::sin(f.theta[i]);
          worst              = std::max(worst, std::abs(axial / load - 1.));
        }
      check(head > 0., "the free surface lies above the frame plane");
      check(load > 2. * pump.dead_load(), "the water carries more than the weight");
      check_close(worst, 0., refined ? 1e-6 : 3e-4,
                  refined ? "  refined mesh (p=4, 32 elements per ring)" : "  default mesh");
    }

  std::cout << "Newton through the Sherman-Morrison solve\n";
  {
    MembraneModel model(pump, FeDiscretization(), NewtonSettings());
    model.set_load_terms(water_terms(paper_water()));
    run_to_end(model, pump);
    const double v0   = model.enclosed_volume();
    LoadState    load;
    load.stage        = Stage::voltage;
    load.load_factor  = 2.;
    load.stretch      = pump.prestretch;
    load.mass         = pump.mass;
    load.force        = pump.dead_load();
    load.voltages     = {4.0e3, 4.9e3};
    const SolveReport r = model.solve(load);
    check(r.converged && r.iterations <= 4,
          "from 4 / 5 kV to 4 / 4.9 kV in " + std::to_string(r.iterations) +
            " iterations (<= 4: quadratic)");
    check(model.enclosed_volume() < v0, "lower outer voltage, smaller volume");
  }

  std::cout << "Water that cannot fill the cone is refused\n";
  {
    MembraneModel model(pump, FeDiscretization(), NewtonSettings());
    WaterLoad     w = paper_water();
    w.water_volume  = 20e-6; // 20 ml: less than the cone holds under the weight alone
    model.set_load_terms(water_terms(w));
    RunResult result;
    run_to_end(model, pump, &result);
    check(!result.completed, "the run stops");
    check(result.message.find("no longer fills the cone") != std::string::npos,
          "with a message that says why: " + result.message.substr(0, 160));
  }

  std::cout << "Water load off: the model is unchanged\n";
  {
    MembraneModel dry(pump, FeDiscretization(), NewtonSettings());
    MembraneModel off(pump, FeDiscretization(), NewtonSettings());
    WaterLoad     w = paper_water();
    w.enabled       = false;
    off.set_load_terms(water_terms(w));
    const StepSummary a = run_to_end(dry, pump), b = run_to_end(off, pump);
    check_close(a.displacement, b.displacement, 0., "same displacement");
  }
  return finish();
}
