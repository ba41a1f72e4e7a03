#pragma once
// What the time-stepping driver (time_stepper.h) needs from a model beyond an
// equilibrium at a given load: the time step of the material's internal
// variables, the disk's inertia, accepting a step, and an energy budget.
//
// Inertia (Newmark's implicit scheme on the disk coordinate z = z(A)): over a
// step dt the potential gains
//
//   m (z - z_pred)^2 / (2 beta dt^2),   z_pred = z_n + dt v_n + dt^2 (1/2 - beta) a_n,
//
// whose derivative m (z - z_pred) / (beta dt^2) is m a_{n+1}: equilibrium of
// the new state is then m z'' + (internal forces) = F. The pump's water in the
// level tube moves with the enclosed volume V (speed V' / S in a tube of
// cross-section S, column height h): its kinetic energy (rho h / S) V'^2 / 2 is
// the same form in V with mass rho h / S. The membrane's own mass is neglected.

#include <cdea/material/membrane_law.h>
#include <cdea/model/equilibrium_model.h>

#include <vector>

namespace cdea
{
  /// The inertia terms of one time step (dt = 0: none).
  struct InertiaStep
  {
    double dt            = 0.;   ///< s
    double beta          = 0.25; ///< Newmark's beta
    double disk_mass     = 0.;   ///< kg, on z(A)
    double disk_target   = 0.;   ///< m, z_pred of the disk
    double volume_mass   = 0.;   ///< kg/m^4, rho h / S of the water column (0: none)
    double volume_target = 0.;   ///< m^3, V_pred
  };

  /// The energy stored in a state, apart from the kinetic energy (J).
  struct EnergyBudget
  {
    /// Both networks' elastic energy with the internal variables as they are,
    /// minus the weight's work F z(A), plus the water's potential.
    double              mechanical    = 0.;
    double              electrostatic = 0.; ///< (1/2) sum_k Phi_k Q_k
    std::vector<double> charge;             ///< Q_k on the electrode of ring k (C)
  };

  class TransientModel : public EquilibriumModel
  {
  public:
    /// Time step of the internal variables for the next solves: 0 holds them,
    /// +infinity relaxes them completely (as the law defines it).
    virtual void set_time_step(double dt, TimeScheme scheme) = 0;
    /// Inertia terms for the next solves (dt = 0: off).
    virtual void set_inertia(const InertiaStep &inertia) = 0;
    /// Right after a converged solve: the internal variables of that state
    /// become the accepted ones (the start of the next step).
    virtual void accept_time_step() = 0;
    /// Internal variables of a point held at its current stretches for ever.
    virtual void relax_internal_variables() = 0;
    /// Energy the material dissipated over the last solve's step (J).
    virtual double step_dissipation() const = 0;
    /// Whether the material has internal variables at all.
    virtual bool has_internal_variables() const = 0;
    /// z(A), the disk's coordinate (m; z > 0 is the weight's direction).
    virtual double disk_position() const = 0;
    virtual EnergyBudget energy_budget() const = 0;
    /// Static stiffness of the disk coordinate at the current state, loads and
    /// internal variables held: the tangent condensed onto z(A) (N/m).
    virtual double disk_stiffness() const = 0;
  };
} // namespace cdea
