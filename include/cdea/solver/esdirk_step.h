#pragma once
// One step of an ESDIRK method (numerics/esdirk.h) on a TransientModel: the
// membrane's unknowns (algebraic where they carry no mass), the disk's z and
// v (with inertia), the pump's water volume V and V' (with the water
// column's inertia) and the material's evolving internal variables y.
//
// Stage i (i >= 2) at t_i = t_n + c_i h starts from
//   yhat = y_n + h sum_{j<i} a_ij rate_j,  zhat = z_n + h sum a_ij v_j,
//   vhat = v_n + h sum a_ij a_j  (and V, V' alike)
// and solves equilibrium with the internal variables' backward Euler step of
// gamma h from yhat (MembraneLaw, "evolving internal variables") and the
// inertia term m (z - zhat - gamma h vhat)^2 / (2 (gamma h)^2), whose
// gradient is m a_i with v_i = (z_i - zhat) / (gamma h), a_i = (v_i - vhat) /
// (gamma h). Stage 1 is the end of the last step. The last stage is the new
// state; the error estimate h sum (b_j - bhat_j) K_j of every differential
// component is weighed against the tolerances (TimeSettings). With no inertia
// the disk is algebraic: its estimate is the linear response of z(A) to the
// internal variables' estimate.
//
// Energy over the step, to the method's order (quadratures of an added
// differential variable): dissipation h sum b_j D_j; electrical work
// [Phi . Q] - h sum b_j Q_j . Phi'(t_j) (integration by parts of Phi dQ).

#include <cdea/model/transient_model.h>
#include <cdea/numerics/esdirk.h>
#include <cdea/numerics/solve_report.h>


#include <functional>
#include <vector>

namespace cdea
{
  /// The mechanical state of the disk (and the water column) between steps.
  struct InertiaState
  {
    double z = 0., v = 0., a = 0.;          ///< disk: m, m/s, m/s^2
    double V = 0., V_dot = 0., V_ddot = 0.; ///< enclosed volume and its rates
  };

  /// A time run's state at one time: what the next step starts from and the
  /// energy budget needs (the model's state with the internal variables'
  /// rates, the motion, the dissipation rate and the charges).
  struct TimePoint
  {
    double              t = 0.;
    ModelState          state;
    InertiaState        motion;
    double              dissipation_rate = 0.; ///< W
    std::vector<double> charges;               ///< C, one per ring
  };

  /// What an ESDIRK step needs besides the model.
  struct EsdirkStepSettings
  {
    const EsdirkTableau *tableau   = nullptr;
    double               disk_mass = 0.; ///< kg; 0: the disk has no inertia
    /// The liquid column on the enclosed volume (the pump's water; none:
    /// no such inertia).
    LiquidColumn column;
    double relative_tolerance     = 1e-6;
    double displacement_tolerance = 1e-9; ///< m
    double internal_tolerance     = 1e-9;
    /// Velocities are weighed as displacements times this (rad/s).
    double angular_frequency = 1.;
  };

  class EsdirkStep
  {
  public:
    /// @p load_at(t, inside): the load at t on the waveform's piece holding
    /// inside; @p voltage_rates(t, inside) its voltages' rates (V/s).
    EsdirkStep(TransientModel &model, const EsdirkStepSettings &settings,
               std::function<LoadState(double, double)>           load_at,
               std::function<std::vector<double>(double, double)> voltage_rates);

    /// The step of length @p h from @p start. On success the model holds the
    /// last stage (not yet accepted) and the estimates are set; on failure the
    /// model's state is unspecified (the caller restores @p start).
    SolveReport take(const TimePoint &start, double h);
    /// The stages of the last take() (the first is its start).
    const std::vector<TimePoint> &stage_points() const { return stages; }

    /// The new state: the last stage (after a successful take()).
    const TimePoint &end() const { return stages.back(); }
    /// The weighted error norm (accepted if <= 1).
    double error_ratio() const { return ratio; }
    /// The estimate of the local error of z(A) (m).
    double displacement_error() const { return z_error; }
    double work() const { return step_work; }             ///< J, electrical
    double dissipated() const { return step_dissipated; } ///< J
    unsigned int iterations() const { return newton_iterations; }
    unsigned int solves() const { return stage_solves; }

    /// The liquid column's mass rho h / S at volume @p V as the stages take
    /// it (LiquidColumn::mass_by_slope(), kg/m^4).
    double column_mass(double V) const { return settings.column.mass_by_slope(V); }
    /// Forget the last steps' stages as predictors (after a jump in the state).
    void clear_history() { previous.clear(); }

    /// Called after every converged implicit stage with its index i (>= 1)
    /// and h, while the model still holds the stage (its solution, tangent,
    /// time step gamma h and internal variables from the stage's start): for
    /// sensitivities through the stages (fe/time_sensitivity.h). None: not called.
    std::function<void(unsigned int, double)> on_stage;

  private:
    TransientModel                                     &model;
    EsdirkStepSettings                                  settings;
    std::function<LoadState(double, double)>           load_at;
    std::function<std::vector<double>(double, double)> voltage_rates;
    std::vector<TimePoint>                             stages, previous;
    double       ratio = 0., z_error = 0., step_work = 0., step_dissipated = 0.;
    unsigned int newton_iterations = 0, stage_solves = 0;

    SolveReport solve_stage(unsigned int i, double h);
    SolveReport take_stages(const TimePoint &start, double h);
    void        predict(double t) const;
    InertiaStep stage_inertia(unsigned int i, double h, InertiaState &hat) const;
    void        estimate_error(double h);
    void        energy(double h);
  };
} // namespace cdea
