// The disk's inertia and the energy budget of time-dependent runs.
//  - Small oscillations: after a slow ramp to 5 kV the elastic actuator's disk
//    rings about its equilibrium; the period of the ringing against
//    2 pi sqrt(m / k), with k the stiffness of the disk coordinate from the
//    tangent (MembraneModel::disk_stiffness: its Schur complement with the
//    other free unknowns) at the quasi-static equilibrium.
//  - The residual and tangent of a time step (viscous update, disk and water
//    column inertia) against differences of the energy and of the residual.
//  - Energy balance: electrical work = change of stored energy (elastic,
//    weight, electrostatic, kinetic) + dissipated energy, with the dissipation
//    >= 0 in every step; to second order in the time step for the
//    trapezoidal rule (with Newmark's average acceleration), and for the
//    elastic film (no dissipation) also.

#include <cdea/fe/membrane_model.h>
#include <cdea/fe/water_term.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/model/output_fields.h>
#include <cdea/solver/time_stepper.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_close;
using cdea_test::legacy_method;

namespace
{
  const Scene scene = cdea::paper_scene({1., 3.}, {{5.}});

  /// A time column of @p s in the file's unit (NaN if absent).
  double column(const StepSummary &s, const Quantity &c) { return s.columns.in_file_units(c); }

  struct EnergyRun
  {
    double work = 0., stored = 0., dissipated = 0.;
    double peak_work = 0.; ///< largest electrical work during the run (scale)
    bool   dissipation_never_negative = true;
  };

  EnergyRun energy_run(const bool viscous, const TimeScheme scheme, const double dt)
  {
    MembraneModel model(scene, cdea_test::discretization(4, 4), NewtonSettings());
    if (viscous)
      model.set_material_law(
        std::make_shared<TwoNetworkGentLaw>(scene.material, ViscousNetwork{45e3, 270., 0.5}));
    TimeSettings s;
    s.waveform = Waveform::sine(scene.path.voltages(1.), 0.5, 2);
    s.max_step = dt;
    s.method   = legacy_method(scheme);
    TimeStepper stepper(scene, model, SteppingSettings(), s);
    EnergyRun   e;
    double      previous = 0.;
    stepper.on_step      = [&](const StepSummary &summary) {
      const double d = column(summary, summary_column::dissipated_energy);
      if (std::isnan(d))
        return;
      e.dissipation_never_negative = e.dissipation_never_negative && d >= previous;
      previous                     = d;
      e.work                       = column(summary, summary_column::electrical_work);
      e.peak_work                  = std::max(e.peak_work, std::abs(e.work));
      e.stored                     = column(summary, summary_column::stored_energy_change);
      e.dissipated                 = d;
    };
    check(stepper.run().completed, "energy run completes");
    return e;
  }
} // namespace

CDEA_TEST_MAIN()
{
  // The FE residual and tangent of a time step (viscous update and both
  // inertia terms, pump scene with its water load) against differences.
  {
    Scene pump = cdea::paper_scene({1., 1.7, 3.}, {{4., 5.}});
    MembraneModel model(pump, cdea_test::discretization(3, 2), NewtonSettings());
    WaterLoad     water;
    water.enabled = true;
    auto water_term = std::make_unique<WaterTerm>();
    water_term->set_water(water);
    std::vector<std::unique_ptr<LoadTerm>> terms;
    terms.push_back(std::move(water_term));
    model.set_load_terms(std::move(terms));
    model.set_material_law(
      std::make_shared<TwoNetworkGentLaw>(pump.material, ViscousNetwork{45e3, 270., 2.}));
    model.set_time_step(std::numeric_limits<double>::infinity(), TimeScheme::backward_euler);
    cdea_test::run_to_end(model, pump);
    model.relax_internal_variables();
    for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::trapezoidal})
      {
        model.set_time_step(0.01, scheme);
        InertiaStep inertia;
        inertia.dt            = 0.01;
        inertia.disk_mass     = pump.mass;
        inertia.disk_target   = model.disk_position() - 1e-4;
        inertia.volume_mass   = 2e5;
        inertia.volume_target = model.enclosed_volume() + 1e-7;
        model.set_inertia(inertia);
        cdea_test::check_derivatives(model, scheme == TimeScheme::backward_euler ?
                                              "time step, backward Euler, inertia" :
                                              "time step, trapezoidal, inertia");
      }
  }

  // Small oscillations about the 5 kV equilibrium of the elastic actuator.
  {
    MembraneModel static_model(scene, cdea_test::discretization(4, 4), NewtonSettings());
    const double  z_eq = cdea_test::run_to_end(static_model, scene).displacement;
    const double  k    = static_model.disk_stiffness();
    const double  omega = std::sqrt(k / scene.mass);

    MembraneModel model(scene, cdea_test::discretization(4, 4), NewtonSettings());
    TimeSettings  s;
    s.waveform = Waveform::ramp_hold(scene.path.voltages(1.), 2., 3.);
    s.max_step = 1e-3;
    s.method   = TimeMethod::backward_euler; // the fixed steps of earlier versions
    TimeStepper         stepper(scene, model, SteppingSettings(), s);
    std::vector<double> crossings;
    double              t0 = 0., u0 = 0., amplitude = 0.;
    stepper.on_step = [&](const StepSummary &summary) {
      const double t = column(summary, summary_column::waveform_time);
      if (!(t > 2.))
        return;
      const double u = summary.displacement - z_eq;
      amplitude      = std::max(amplitude, std::abs(u));
      if (t0 > 2. && (u0 < 0.) != (u < 0.))
        crossings.push_back(t0 + (t - t0) * u0 / (u0 - u));
      t0 = t;
      u0 = u;
    };
    check(stepper.run().completed, "ringing run completes");
    const double period = 2. * (crossings.back() - crossings.front()) / (crossings.size() - 1);
    std::cout << "disk stiffness k = " << k << " N/m, m = " << scene.mass << " kg: period "
              << 2. * M_PI / omega << " s; ringing: " << crossings.size()
              << " zero crossings, period " << period << " s, amplitude " << amplitude * 1e3
              << " mm\n";
    check(crossings.size() > 10, "the disk rings");
    check_close(period * omega / (2. * M_PI), 1., 2e-3, "ringing period = 2 pi sqrt(m / k)");
  }

  // Energy balance over two cycles of a 0.5 Hz sine to 5 kV.
  for (const bool viscous : {true, false})
    for (const TimeScheme scheme : {TimeScheme::trapezoidal, TimeScheme::backward_euler})
      {
        if (!viscous && scheme == TimeScheme::backward_euler)
          continue; // the same run: the scheme is the dashpots'
        double previous = 0.;
        for (const double dt : {0.02, 0.01, 0.005})
          {
            const EnergyRun e      = energy_run(viscous, scheme, dt);
            const double    defect = e.work - e.stored - e.dissipated;
            std::cout << (viscous ? "viscoelastic, " : "elastic, ")
                      << (scheme == TimeScheme::trapezoidal ? "trapezoidal" : "backward Euler")
                      << ", dt " << dt << ": work " << e.work << " mJ, stored change "
                      << e.stored << " mJ, dissipated " << e.dissipated
                      << " mJ, defect " << defect << " mJ (peak work " << e.peak_work << " mJ)";
            if (previous != 0.)
              std::cout << ", order " << std::log2(std::abs(previous / defect));
            std::cout << '\n';
            check(e.dissipation_never_negative, "dissipation >= 0 in every step");
            check(!viscous || e.dissipated > 1e-2 * e.work, "the dashpots dissipate");
            if (scheme == TimeScheme::trapezoidal && dt == 0.005)
              {
                check_close(defect / e.peak_work, 0., 1e-5,
                            "energy balance at dt = 5 ms (relative to the peak work)");
                check(std::log2(std::abs(previous / defect)) > 1.7, "defect of second order");
              }
            if (scheme == TimeScheme::backward_euler && dt == 0.005)
              check_close(defect / e.peak_work, 0., 1e-3, "energy balance, backward Euler");
            previous = defect;
          }
      }
  return cdea_test::finish();
}
