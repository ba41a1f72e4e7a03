// Parameter derivatives: of the material laws (Gent dielectric, its
// tension-field relaxation) at fixed stretches, and of the FE residual
// assembled by the cell kernel (every ring voltage, shear modulus, Jlim,
// permittivity), all against central differences.

#include <cdea/material/gent_law.h>
#include <cdea/fe/cell_kernel.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/material/tension_field.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <cmath>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// The constants with parameter @p p changed by @p h (voltage: returned apart).
  MaterialConstants shifted(MaterialConstants c, const LawParameter p, const double h)
  {
    if (p == LawParameter::shear_modulus)
      c.shear_modulus += h;
    if (p == LawParameter::jlim)
      c.jlim += h;
    if (p == LawParameter::permittivity)
      c.permittivity += h;
    return c;
  }

  double value_of(const MaterialConstants &c, const double voltage, const LawParameter p)
  {
    switch (p)
      {
        case LawParameter::shear_modulus:
          return c.shear_modulus;
        case LawParameter::jlim:
          return c.jlim;
        case LawParameter::permittivity:
          return c.permittivity;
        case LawParameter::voltage:
          return voltage;
      }
    return 0.;
  }
} // namespace

CDEA_TEST_MAIN()
{
  const MaterialConstants c{25.1e3, 270., 3.98e-11, 1e-3};
  const LawParameter      all[] = {LawParameter::shear_modulus, LawParameter::jlim,
                                   LawParameter::permittivity, LawParameter::voltage};

  std::cout << "Law parameter derivatives vs central differences\n";
  // Taut points, and a wrinkled one of the relaxation (5.5 kV, l = (5, 2.5)).
  for (const bool relaxed : {false, true})
    for (const auto &[l1, l2, V] : {std::tuple{3.0, 2.5, 3e3}, std::tuple{5.0, 2.5, 5.5e3}})
      for (const LawParameter p : all)
        {
          const auto make = [&](const MaterialConstants &k) -> std::shared_ptr<MembraneLaw> {
            auto base = std::make_shared<GentDielectricLaw>(k);
            if (relaxed)
              return std::make_shared<TensionField>(base);
            return base;
          };
          const double h  = 1e-6 * value_of(c, V, p);
          const auto   Vp = p == LawParameter::voltage ? V + h : V;
          const auto   Vm = p == LawParameter::voltage ? V - h : V;
          LawResponse  rp, rm;
          make(shifted(c, p, h))->evaluate({l1, l2, Vp}, {}, law_energy | law_stress, rp);
          make(shifted(c, p, -h))->evaluate({l1, l2, Vm}, {}, law_energy | law_stress, rm);
          double        dW = 0.;
          NominalStress ds{0., 0.};
          const bool    ok = make(c)->parameter_derivative({l1, l2, V}, {}, p, dW, ds);
          const double  scale = c.shear_modulus / value_of(c, V, p);
          const std::string where = std::string(relaxed ? "relaxed" : "plain") + " l1 = " +
                                    std::to_string(l1) + ", p " +
                                    std::to_string(static_cast<int>(p));
          check(ok, where + ": derivative available");
          check_close((dW - (rp.energy - rm.energy) / (2 * h)) / scale, 0., 1e-6,
                      where + ": dW/dp");
          check_close((ds.s1 - (rp.stress.s1 - rm.stress.s1) / (2 * h)) / scale, 0., 1e-6,
                      where + ": ds1/dp");
          check_close((ds.s2 - (rp.stress.s2 - rm.stress.s2) / (2 * h)) / scale, 0., 1e-6,
                      where + ": ds2/dp");
        }

  std::cout << "Kernel: dR/dp of the FE residual vs central differences\n";
  const Scene   scene = paper_scene({1., 1.7, 2.3, 3.}, {{4., 4., 4.}, {4., 5., 6.}});
  MembraneModel model(scene, discretization(3, 3), NewtonSettings());
  run_to_end(model, scene);
  AssembledSystem system;
  model.assemble(assemble_residual | assemble_parameter_derivatives, system);
  const ParameterLayout layout{scene.n_rings()};
  double                R_scale = 0.;
  for (unsigned int i = 0; i < system.residual.size(); ++i)
    R_scale = std::max(R_scale, std::abs(system.parameter_residual[layout.voltage(2)][i]));

  // Whole-model differences: a new model per perturbed material, the same
  // solution and load.
  const auto residual_with = [&](const Scene &s, const LoadState &load) {
    MembraneModel m(s, discretization(3, 3), NewtonSettings());
    ModelState    state = model.state();
    state.load          = load;
    m.set_state(state);
    return m.residual_vector();
  };
  for (unsigned int k = 0; k < scene.n_rings(); ++k)
    {
      const double h     = 1e-3; // V; the residual is quadratic in the voltage
      LoadState    plus  = model.load();
      LoadState    minus = model.load();
      plus.voltages[k] += h;
      minus.voltages[k] -= h;
      const auto   rp = residual_with(scene, plus), rm = residual_with(scene, minus);
      double       worst = 0., size = 0.;
      for (unsigned int i = 0; i < rp.size(); ++i)
        {
          const double d = system.parameter_residual[layout.voltage(k)][i];
          worst          = std::max(worst, std::abs((rp[i] - rm[i]) / (2 * h) - d));
          size           = std::max(size, std::abs(d));
        }
      check(size > 0., "ring " + std::to_string(k + 1) + ": the voltage acts on the residual");
      check_close(worst / size, 0., 1e-6, "dR/dV of ring " + std::to_string(k + 1));
    }
  const std::pair<LawParameter, unsigned int> material[] = {
    {LawParameter::shear_modulus, layout.shear_modulus()},
    {LawParameter::jlim, layout.jlim()},
    {LawParameter::permittivity, layout.permittivity()}};
  for (const auto &[p, column] : material)
    {
      const double h = 1e-6 * value_of(scene.material, 0., p);
      Scene        sp = scene, sm = scene;
      sp.material       = shifted(scene.material, p, h);
      sm.material       = shifted(scene.material, p, -h);
      const auto rp     = residual_with(sp, model.load());
      const auto rm     = residual_with(sm, model.load());
      double     worst = 0., size = 0.;
      for (unsigned int i = 0; i < rp.size(); ++i)
        {
          const double d = system.parameter_residual[column][i];
          worst          = std::max(worst, std::abs((rp[i] - rm[i]) / (2 * h) - d));
          size           = std::max(size, std::abs(d));
        }
      check_close(worst / size, 0., 1e-6,
                  "dR/dp of material parameter " + std::to_string(static_cast<int>(p)));
    }
  return finish();
}
