#pragma once
// What the load-stepping driver needs from a model of the actuator: reach an
// equilibrium at a given load from the current state, report its quantities,
// and save or restore its state. The FE model and the shooting model both
// implement it, so both follow the same stages and the same onset search.

#include <cdea/model/records.h>
#include <cdea/numerics/solve_report.h>

#include <cmath>
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
    double              time        = 0.; ///< s (time-dependent runs)

    bool operator==(const LoadState &o) const
    {
      return stage == o.stage && load_factor == o.load_factor && stretch == o.stretch &&
             force == o.force && mass == o.mass && voltages == o.voltages && time == o.time;
    }
  };

  /// A model's state: the load, the model's unknowns (FE: the dof values;
  /// shooting: the start values of the integration) and the internal
  /// variables of the material (empty for an elastic law). Copying it and
  /// handing it back to set_state() restores the state exactly.
  struct ModelState
  {
    LoadState           load;
    std::vector<double> unknowns;
    std::vector<double> internal;

    bool operator==(const ModelState &o) const
    {
      return load == o.load && unknowns == o.unknowns && internal == o.internal;
    }
  };

  /// Stability of a state with dead load and voltages held.
  struct StateStability
  {
    double min_eigenvalue = std::numeric_limits<double>::quiet_NaN(); ///< of the tangent (N/m)
    double stable = std::numeric_limits<double>::quiet_NaN(); ///< 1 or 0; NaN: no answer
  };

  /// When the stability check computes the smallest eigenvalue
  /// (Solver/Stability eigenvalue): at every state, or only where the state
  /// is not positive definite or is near a fold (elsewhere the inertia of
  /// one factorization decides, and the eigenvalue is NaN).
  enum class StabilityEigenvalue
  {
    every_step,
    near_folds,
    /// near_folds at the first state of a run: no reference eigenvalue from
    /// earlier states (a run's output does not depend on the model's history).
    near_folds_first
  };

  /// Hoop stresses of a state, as the wrinkling check reads them.
  struct HoopStresses
  {
    double              s2_min        = 0.; ///< smallest anywhere (Pa)
    double              s2_min_radius = 0.; ///< reference radius R of s2_min (m)
    std::vector<double> s2_ring_inner;      ///< at each ring's inner edge, that ring's side (Pa)
    /// Reference radii bounding the points the relaxed law treats as
    /// wrinkled; NaN when there are none.
    double wrinkled_zone_inner = std::numeric_limits<double>::quiet_NaN();
    double wrinkled_zone_outer = std::numeric_limits<double>::quiet_NaN();
    /// Empty while the state is inside the model's validity; otherwise why not.
    std::string validity_limit;
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

    /// The load of the current state.
    virtual const LoadState &load() const = 0;

    /// |z(disk) - z(frame)| of the current state (m).
    virtual double displacement() const = 0;

    /// Hoop stresses of the current state.
    virtual HoopStresses hoop_stresses() const = 0;

    /// Fields along the meridian of the current state.
    virtual StepFields fields() const = 0;

    /// The model's own quantities of the current state (load, displacement,
    /// hoop stresses; the driver's and the other postprocessors' fields are
    /// left at their defaults).
    StepSummary summary() const;

    /// Volume (m^3) enclosed between the frame plane and the deformed membrane
    /// with the disk at the current state: pi int r^2 dz along the meridian,
    /// pi int_A^B r^2 (-z') dR (zero for a flat film). NaN if the model cannot tell.
    virtual double enclosed_volume() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// Replace the unknowns of the current state by the linear prediction
    /// x + factor (x - x_older) as the starting guess of the next solve;
    /// @p older is an earlier state() of the same stage. A model without a
    /// useful predictor leaves its state alone.
    virtual void predict(const ModelState &older, double factor)
    {
      (void)older;
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
    virtual double min_tangent_eigenvalue()
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// The stability check of the current state: min_tangent_eigenvalue()
    /// (@p eigenvalue says where; by default everywhere) and whether the
    /// tangent is positive definite (FE: from the inertia of its
    /// factorization, Sylvester's law; by default the eigenvalue's sign).
    virtual StateStability stability(StabilityEigenvalue eigenvalue)
    {
      (void)eigenvalue;
      const double lambda = min_tangent_eigenvalue();
      return {lambda, std::isnan(lambda) ? lambda : double(lambda > 0.)};
    }

    /// Copy of the current state, and its restoration.
    virtual ModelState state() const                  = 0;
    virtual void       set_state(const ModelState &state) = 0;
  };
} // namespace cdea
