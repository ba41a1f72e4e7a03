#pragma once
// Periodic steady states of a periodic drive (Time/Waveform = sine or square,
// doc/dynamics.md, "Periodic steady states and the frequency sweep"): the
// state x that the time integration maps onto itself over one period T,
// P(x) = x, found on one period rather than by running many cycles.
//
// x holds the differential state: the disk's z(A) and v (with inertia), the
// water column's V and V' (with water inertia) and the law's evolving
// internal variables y at every quadrature point (MembraneLaw::n_evolving(),
// any law). The membrane's nodal unknowns are algebraic and follow: a state
// x is lifted to a consistent start by one solve with y held and z (and V)
// pinned by a stiff inertia term m (z - z_x)^2 / (2 delta^2), whose gradient
// is the disk's acceleration m a.
//
// P is the ESDIRK integration (solver/esdirk_step.h) over [0, T], landing on
// the waveform's breakpoints, steps at most T/32 (with fixed steps: Time/Time step (s)).
// Newton on P(x) - x = 0 with Jacobian-free GMRES on (I - dP/dx), the
// directional derivatives as differences of period maps on a frozen step
// sequence (the one the error control chose for the current iterate), so
// that P is smooth in x. Start: the relaxed equilibrium (network B carries
// nothing) at the waveform's voltages at t = 0, then Steady state/Start
// periods of plain integration. Converged when the weighted defect max_i |P(x)_i - x_i| /
// s_i is below Steady state/Tolerance, and one more period integrated with
// error control from the found state (its own step sequence) moves it by
// less than the tolerance too. Weights s_i: the half swing over the period of
// z (the stroke amplitude), of V, and the largest of the internal variables
// (at least Time/Internal variable tolerance); velocities: the swing times
// 2 pi f.

#include <cdea/input/parameters.h>
#include <cdea/model/scene.h>
#include <cdea/model/waveform.h>

#include <complex>
#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  struct SteadyStateSettings
  {
    double       tolerance     = 1e-6; ///< the weighted periodicity defect
    unsigned int max_newton    = 12;   ///< Newton iterations
    unsigned int max_krylov    = 40;   ///< GMRES iterations per Newton iteration
    unsigned int start_periods = 2;    ///< plain integration before Newton
    double       low_fraction  = 0.;   ///< the drive's low voltage over its peak
  };

  /// The steady period at one frequency.
  struct SteadyPeriod
  {
    double       frequency  = 0.; ///< Hz
    bool         converged  = false;
    double       defect     = 0.; ///< weighted periodicity defect at the end
    double       check_move = 0.; ///< weighted move of the check period
    unsigned int newton_iterations = 0, krylov_iterations = 0, period_maps = 0;
    unsigned int steps_per_period  = 0;
    double       stroke_amplitude  = 0.; ///< m, half the peak-to-peak of z(A)
    double       mean_displacement = 0.; ///< m, z(A) averaged over the period
    /// z(A)'s first harmonic: z = mean + Re(c exp(i 2 pi f t)) + ... (m).
    std::complex<double> first_harmonic;
    double               volume_swing = 0.; ///< m^3, peak-to-peak of the enclosed volume
    double electrical_work   = 0.; ///< J over the period
    double weight_work       = 0.; ///< J, m g (z(T) - z(0))
    double dissipated        = 0.; ///< J, the branches' dissipation over the period
    double stored_change     = 0.; ///< J, stored and kinetic energy at T minus at 0
    double s2_min            = 0.; ///< Pa, smallest hoop stress over the period
    bool   loss_of_tension   = false;
    std::string message;           ///< why it failed (empty if converged)
    double      seconds = 0.;

    /// |electrical - dissipated - stored change| / dissipated (not finite
    /// without dissipation: an elastic film).
    double energy_defect() const;
  };

  /// The drive's waveform for a steady state at @p frequency: Time/Waveform
  /// (sine or square with its rise time), one period, swinging between
  /// @p low_fraction of the voltage path's last waypoint and that waypoint.
  /// Throws InputError for a waveform that is not periodic.
  Waveform periodic_waveform(const Parameters &p, const Scene &scene, double frequency,
                             double low_fraction);

  class PeriodicSteadyState
  {
  public:
    PeriodicSteadyState(const Parameters &p, const Scene &scene,
                        const SteadyStateSettings &settings);
    ~PeriodicSteadyState();

    /// The steady period at @p frequency (Hz).
    SteadyPeriod solve(double frequency);

    /// The quasi-static stroke amplitude of the drive: half the difference
    /// of z(A) at the peak and at the low voltage, film relaxed (m).
    double quasi_static_amplitude();

  private:
    class Impl;
    std::unique_ptr<Impl> impl;
  };
} // namespace cdea
