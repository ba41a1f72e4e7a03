#pragma once
// The parsed parameters turned into the settings of the solver pieces, in SI
// units: the one place where a prm entry becomes a number a solver takes (kV
// to V, mm to m, ml to m^3). Used by the runs (analysis/), the design studies
// (design/), the Python module, tests and benchmarks alike.

#include <cdea/fe/discretization.h>
#include <cdea/material/membrane_law.h>
#include <cdea/numerics/newton.h>
#include <cdea/shooting/options.h>
#include <cdea/solver/load_stepper.h>
#include <cdea/solver/time_stepper.h>

#include <memory>

namespace cdea
{
  struct Parameters;
  struct Scene;

  /// The load stepper's settings (subsections Solver and Wrinkling).
  SteppingSettings stepping_settings(const Parameters &p);

  /// The load stages of a design study (sweep rows, optimized layouts,
  /// fitted points): stepping_settings() by load stepping, without the
  /// stability check, the breakdown field or arc length, which the studies
  /// report none of.
  SteppingSettings study_stepping_settings(const Parameters &p);

  /// The FE mesh and elements (subsection Discretization).
  FeDiscretization fe_discretization(const Parameters &p);

  /// Newton's tolerances and iterations (subsection Solver).
  NewtonSettings newton_settings(const Parameters &p);

  /// The shooting model's integrator (subsection Shooting).
  shooting::ShootingOptions shooting_options(const Parameters &p);

  /// Cross-section width x depth of the pump's level tube (m^2).
  double tube_area(const Parameters &p);

  /// The liquid column whose inertia a time run carries with the disk's
  /// (Time/Inertia and Time/Water inertia on): that of the load term which
  /// has one (LoadTerm::liquid_column()); none otherwise.
  LiquidColumn liquid_column(const Parameters &p);

  /// The time stepper's settings (waveform from the last waypoint or the table).
  TimeSettings time_settings(const Parameters &p, const Scene &scene);
} // namespace cdea
