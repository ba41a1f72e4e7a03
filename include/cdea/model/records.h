#pragma once
// What a solver (FE or shooting) reports for one converged equilibrium, in SI
// units. The HDF5 writer converts to the file's units (mm, kPa, kV, MV/m, g).

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  enum class Stage : int
  {
    prestretch = 0,
    dead_load  = 1,
    voltage    = 2
  };

  /// One row of /summary.
  struct StepSummary
  {
    Stage               stage       = Stage::prestretch;
    double              load_factor = 0.; ///< stage parameter (voltage path t in stage 2)
    std::vector<double> voltages;         ///< V, one per ring
    double              mass          = 0.; ///< kg
    double              displacement  = 0.; ///< |z(disk) - z(frame)| (m)
    double              stroke        = 0.; ///< m; NaN before the end of the load stage
    double              s2_min        = 0.; ///< smallest hoop stress anywhere (Pa)
    double              s2_min_radius = 0.; ///< reference radius R where s2_min occurs (m)
    std::vector<double> s2_ring_inner;      ///< hoop stress at each ring's inner edge (Pa)
    bool                wrinkled          = false;
    /// Reference radii R (m) bounding the quadrature points the relaxed law
    /// treats as wrinkled; NaN when there are none (or in check mode).
    double wrinkled_zone_inner = std::numeric_limits<double>::quiet_NaN();
    double wrinkled_zone_outer = std::numeric_limits<double>::quiet_NaN();
    /// Smallest eigenvalue of the tangent with loads held (N/m); NaN if not
    /// computed. Negative: the state is unstable.
    double min_eigenvalue = std::numeric_limits<double>::quiet_NaN();
    /// Largest true electric field (V/m) and its reference radius R (m);
    /// filled by the driver when the breakdown check is on.
    double max_field        = std::numeric_limits<double>::quiet_NaN();
    double max_field_radius = std::numeric_limits<double>::quiet_NaN();
    /// Empty while the state is inside the model's validity; otherwise why
    /// not (e.g. the relaxed law loses ellipticity at some radius).
    std::string validity_limit;
    unsigned int        newton_iterations = 0;
    /// Further /summary columns of the postprocessors: name (with its unit)
    /// and value, in the order they were registered.
    std::vector<std::pair<std::string, double>> columns;
  };

  /// Fields along the meridian, one entry per sample point (SI; theta in rad).
  struct StepFields
  {
    std::vector<double> R, r, z, theta, lambda1, lambda2, s1, s2, E, Phi;
    std::vector<int>    ring;
    /// Viscous stretches of a law with internal variables (empty otherwise).
    std::vector<double> xi1, xi2;
  };

  /// Where the hoop stress first reaches zero (also used for the first
  /// exceedance of the breakdown field).
  struct OnsetRecord
  {
    bool                found = false;
    std::vector<double> voltages; ///< V, one per ring
    double              radius = 0.; ///< pre-stretched flat radius lam_pre R (m)
    double              load_factor = 0.; ///< path parameter t where it happens
  };

  /// A limit point (fold) of the load path: the path parameter is extremal.
  struct LimitPoint
  {
    double              load_factor = 0.; ///< path parameter t
    std::vector<double> voltages;         ///< V
    double              displacement = 0.; ///< m
  };
} // namespace cdea
