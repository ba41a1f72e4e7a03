#pragma once
// What the load-stepping driver needs from a model of the actuator: reach an
// equilibrium at a given load from the current state, report it, and save or
// restore its state. The FE model and the shooting model both implement it, so
// both follow the same stages and the same onset search.

#include <cdea/output/records.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace cdea
{
  class ContinuationProblem;

  /// The load a state is in equilibrium with.
  struct LoadState
  {
    Stage               stage       = Stage::prestretch;
    double              load_factor = 0.; ///< stage parameter
    double              stretch     = 1.; ///< current equi-biaxial pre-stretch (stage 0 ramps it)
    double              force       = 0.; ///< dead load on the disk (N)
    double              mass        = 0.; ///< kg, F = mass g
    std::vector<double> voltages;         ///< V, one per ring
  };

  struct SolveReport
  {
    bool         converged  = false;
    unsigned int iterations = 0;
    std::string  message; ///< why it failed (empty on success)
  };

  class EquilibriumModel
  {
  public:
    virtual ~EquilibriumModel() = default;

    /// Put the model in the unstretched, unloaded, flat reference state.
    virtual void set_reference_state() = 0;

    /// Try to reach equilibrium at @p load starting from the current state.
    /// On success the equilibrium becomes the current state; on failure the
    /// current state is left as it was before the call.
    virtual SolveReport solve(const LoadState &load) = 0;

    /// Everything of the current state that StepSummary holds, except the
    /// fields the driver owns (stage, load_factor, stroke, wrinkled, newton_iterations).
    virtual StepSummary summary() const = 0;

    /// Fields along the meridian of the current state.
    virtual StepFields fields() const = 0;

    /// Volume (m^3) enclosed between the frame plane and the deformed membrane
    /// with the disk at the current state: pi int r^2 dz along the meridian,
    /// pi int_A^B r^2 (-z') dR (zero for a flat film). NaN if the model cannot tell.
    virtual double enclosed_volume() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// Replace the unknowns of the current state by the linear prediction
    /// x + factor (x - x_older) as the starting guess of the next solve;
    /// @p older_state is an earlier state() of the same stage. A model without
    /// a useful predictor leaves its state alone. The summary is not valid
    /// again until the next successful solve.
    virtual void predict(const std::vector<double> &older_state, double factor)
    {
      (void)older_state;
      (void)factor;
    }

    /// The equilibrium problem along a load path t -> LoadState as a
    /// ContinuationProblem over this model's unknowns, for arc-length
    /// continuation; nullptr if the model does not offer one. The model owns it;
    /// it stays valid until the next call.
    virtual ContinuationProblem *continuation(const std::function<LoadState(double)> &path)
    {
      (void)path;
      return nullptr;
    }

    /// Smallest eigenvalue of the tangent of the current state with dead load
    /// and voltages held fixed (N/m): negative means unstable. NaN if the
    /// model cannot tell.
    virtual double min_tangent_eigenvalue() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// Opaque copy of the current state (with the load it is in equilibrium
    /// with), and its restoration; used to go back to a converged step.
    virtual std::vector<double> state() const                  = 0;
    virtual void                set_state(const std::vector<double> &state) = 0;
  };
} // namespace cdea
