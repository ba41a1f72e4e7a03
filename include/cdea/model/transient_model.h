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

#include <algorithm>
#include <vector>

namespace cdea
{
  /// A liquid column that moves with the enclosed volume V: the pump's water
  /// (the water load term gives it, LoadTerm::liquid_column()), of density
  /// rho, W in the cone and a level tube of cross-section S together, its
  /// free surface at the height h = (W - V) / S. Its mass on V is
  /// m_V = rho h / S (kg/m^4), zero once the tube is empty, and linear in V
  /// with the slope -rho / S^2.
  struct LiquidColumn
  {
    double density = 0.; ///< kg/m^3; 0: no column
    double volume  = 0.; ///< m^3, W
    double area    = 1.; ///< m^2, S

    bool present() const { return density > 0.; }
    /// m_V = rho max(h, 0) / S at @p V (the fixed-step schemes, the
    /// frequency response).
    double mass(const double V) const { return density * std::max((volume - V) / area, 0.) / area; }
    /// rho / S^2 (kg/m^7), -dm_V/dV.
    double mass_per_volume() const { return density / (area * area); }
    /// The same m_V as mass_per_volume() max(W - V, 0): the ESDIRK stages'
    /// form, whose slope their inertia term takes (rounded apart from mass();
    /// each path keeps its own).
    double mass_by_slope(const double V) const
    {
      return mass_per_volume() * std::max(volume - V, 0.);
    }
  };

  /// The inertia terms of one time step (dt = 0: none).
  ///
  /// The water column's mass m_V (LiquidColumn) depends on V through the
  /// column height h = (W - V) / S. Newmark's steps freeze it over a step
  /// (volume_mass_slope = 0). A Runge-Kutta stage (dt = gamma h, beta = 1)
  /// keeps it exact: the equation of motion of the kinetic energy
  /// m_V(V) V'^2 / 2 is m_V(V) V'' + m_V'(V) V'^2 / 2 = force, with
  /// m_V(V) = volume_mass + volume_mass_slope (V - volume_reference),
  /// V'' = (V - volume_target) / (beta dt^2), V' = (V - volume_start) / dt.
  struct InertiaStep
  {
    double dt            = 0.;   ///< s
    double beta          = 0.25; ///< Newmark's beta
    double disk_mass     = 0.;   ///< kg, on z(A)
    double disk_target   = 0.;   ///< m, z_pred of the disk
    double volume_mass   = 0.;   ///< kg/m^4, rho h / S of the water column (0: none)
    double volume_target = 0.;   ///< m^3, V_pred
    double volume_mass_slope = 0.; ///< kg/m^7, dm_V/dV (0: the mass frozen)
    double volume_reference  = 0.; ///< m^3, where m_V = volume_mass
    double volume_start      = 0.; ///< m^3, the stage's Vhat
    /// A force (N) the solve's residual tolerance is relative to at least
    /// (0: the model's own scale). A short stage's inertia stiffness k makes
    /// k z carry a round-off of k |z| eps that Newton's residual cannot get
    /// below; the stages set this so that the tolerance allows it.
    double residual_scale = 0.;
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
    /// The index of z(A) among the unknowns.
    virtual unsigned int disk_z_dof() const = 0;
    virtual EnergyBudget energy_budget() const = 0;
    /// Static stiffness of the disk coordinate at the current state, loads and
    /// internal variables held: the tangent condensed onto z(A) (N/m).
    virtual double disk_stiffness() const = 0;

    // Runge-Kutta stages (time_stepper.h, doc/time.md "Error control"). The
    // internal variables are vectors in the layout of ModelState::internal;
    // the law says which of their numbers evolve (MembraneLaw::n_evolving()).

    /// The internal variables of the last solve: after a converged stage its
    /// values, with the rates there.
    virtual std::vector<double> internal_now() const = 0;
    /// The start of a stage: the accepted (and current) internal variables
    /// become @p start with the evolving ones advanced by h sum_j w_j rate_j,
    /// rate_j those stored in @p stages[j].
    virtual void set_internal_start(const std::vector<double>                  &start,
                                    const std::vector<const std::vector<double> *> &stages,
                                    const std::vector<double> &weights, double h) = 0;
    /// The largest |h sum_j d_j rate_j| / (absolute + relative |y|) over the
    /// evolving variables y of @p end (0 if none); @p shifted, if given, gets
    /// @p end with y moved by that estimate.
    virtual double internal_error(const std::vector<const std::vector<double> *> &stages,
                                  const std::vector<double> &d, double h,
                                  const std::vector<double> &end, double absolute,
                                  double relative, std::vector<double> *shifted) const = 0;
    /// To first order, the change of z(A) if the current state's internal
    /// variables were @p internal (held), with the tangent of the last solve.
    virtual double disk_position_change(const std::vector<double> &internal) = 0;
    /// The charge Q_k on each ring's electrode at the current state (C).
    virtual std::vector<double> charges() const = 0;
    /// The material's dissipation rate at the current internal variables (W).
    virtual double dissipation_rate() const = 0;
  };
} // namespace cdea
