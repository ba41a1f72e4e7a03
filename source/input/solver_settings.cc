#include <cdea/base/units.h>
#include <cdea/fe/load_term.h>
#include <cdea/input/parameters.h>
#include <cdea/input/solver_settings.h>
#include <cdea/input/validation.h>
#include <cdea/input/voltage_table.h>
#include <cdea/material/law_factory.h>

namespace cdea
{
  SteppingSettings stepping_settings(const Parameters &p)
  {
    SteppingSettings s;
    s.prestretch_steps      = p.solver.prestretch_steps;
    s.load_increment        = p.solver.load_increment;
    s.voltage_increment     = units::kV.in_si(p.solver.voltage_increment_kV);
    s.min_voltage_increment = units::kV.in_si(p.solver.min_voltage_increment_kV);
    s.max_cutbacks          = p.solver.max_cutbacks;
    s.onset_tolerance       = p.wrinkling.onset_tolerance_V;
    s.arc_length            = p.solver.continuation == Continuation::arc_length;
    s.max_arc_length_steps  = p.solver.max_arc_length_steps;
    s.max_displacement      = units::mm.in_si(p.solver.max_displacement_mm);
    s.stability_check       = p.solver.stability_check;
    s.stability_eigenvalue  = p.solver.stability_eigenvalue;
    s.breakdown_field       = units::MV_per_m.in_si(p.solver.breakdown_field_MV_per_m);
    s.residual_tolerance    = p.solver.residual_tolerance;
    s.update_tolerance      = p.solver.update_tolerance;
    return s;
  }

  SteppingSettings study_stepping_settings(const Parameters &p)
  {
    SteppingSettings s = stepping_settings(p);
    s.arc_length       = false;
    s.stability_check  = false;
    s.breakdown_field  = 0.;
    return s;
  }

  FeDiscretization fe_discretization(const Parameters &p)
  {
    FeDiscretization d;
    d.degree              = p.discretization.polynomial_degree;
    d.elements_per_ring   = p.discretization.elements_per_ring;
    d.grading             = p.discretization.grading;
    d.refinements         = p.discretization.refinements;
    d.samples_per_element = p.discretization.samples_per_element;
    return d;
  }

  NewtonSettings newton_settings(const Parameters &p)
  {
    NewtonSettings n;
    n.residual_tolerance = p.solver.residual_tolerance;
    n.update_tolerance   = p.solver.update_tolerance;
    n.max_iterations     = p.solver.max_newton_iterations;
    return n;
  }

  shooting::ShootingOptions shooting_options(const Parameters &p)
  {
    shooting::ShootingOptions o;
    o.tolerance        = p.shooting.tolerance;
    o.samples_per_ring = p.shooting.samples_per_ring;
    return o;
  }

  double tube_area(const Parameters &p)
  {
    return units::mm.in_si(p.reservoir.width_mm) * units::mm.in_si(p.reservoir.depth_mm);
  }

  LiquidColumn liquid_column(const Parameters &p)
  {
    // The column of the load term that carries one (the water load's), moved
    // with the disk when its inertia is on (doc/time.md).
    if (p.time.inertia && p.time.water_inertia)
      for (const auto &term : make_load_terms(p.load_terms.values))
        if (const LiquidColumn column = term->liquid_column(); column.present())
          return column;
    return {};
  }

  TimeSettings time_settings(const Parameters &p, const Scene &scene)
  {
    const auto  &t = p.time;
    TimeSettings s;
    s.max_step     = t.time_step_s;
    s.min_step     = t.min_time_step_s;
    s.max_cutbacks = p.solver.max_cutbacks;
    s.method       = t.scheme;
    s.control      = t.step_control;
    s.relative_tolerance     = t.relative_tolerance;
    s.displacement_tolerance = units::mm.in_si(t.absolute_tolerance_mm);
    s.internal_tolerance     = t.internal_tolerance;
    s.inertia      = t.inertia;
    s.rest_time    = t.rest_time();
    s.fields_interval = t.fields_interval_s;
    s.column       = liquid_column(p);
    const std::vector<double> peak = scene.path.voltages(scene.path.n_segments());
    switch (t.waveform)
      {
        case WaveformKind::ramp_hold:
          s.waveform = Waveform::ramp_hold(peak, t.ramp_time_s, t.hold_time_s);
          break;
        case WaveformKind::square:
          s.waveform = Waveform::square(peak, t.frequency_Hz, t.cycles, t.rise_time_s);
          break;
        case WaveformKind::sine:
          s.waveform = Waveform::sine(peak, t.frequency_Hz, t.cycles);
          break;
        case WaveformKind::table:
          {
            const VoltageTable table =
              read_voltage_table(t.table_file, scene.n_rings(), voltage_ceiling(scene));
            s.waveform = Waveform::table(table.times, table.volts);
          }
          break;
      }
    return s;
  }
} // namespace cdea
