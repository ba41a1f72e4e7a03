#pragma once
// What a solver (FE or shooting) reports for one converged equilibrium, in SI
// units. The HDF5 writer converts to the file's units (mm, kPa, kV, MV/m, g)
// by the table of output fields (output_fields.h).

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  struct Quantity;

  /// The values of the /summary columns the postprocessors add, each by its
  /// row of the table (the handles in namespace summary_column of
  /// output_fields.h), in SI units and in the order they were set.
  class ColumnValues
  {
  public:
    using Entry = std::pair<const Quantity *, double>;

    /// Sets (or overwrites) the value of @p column.
    void set(const Quantity &column, double value)
    {
      for (Entry &e : entries)
        if (e.first == &column)
          {
            e.second = value;
            return;
          }
      entries.emplace_back(&column, value);
    }

    bool has(const Quantity &column) const
    {
      for (const Entry &e : entries)
        if (e.first == &column)
          return true;
      return false;
    }

    /// The SI value of @p column; NaN if it was not set.
    double get(const Quantity &column) const
    {
      for (const Entry &e : entries)
        if (e.first == &column)
          return e.second;
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// The value of @p column in the file's unit (get() times its factor).
    double in_file_units(const Quantity &column) const;

    std::vector<Entry>::const_iterator begin() const { return entries.begin(); }
    std::vector<Entry>::const_iterator end() const { return entries.end(); }
    bool                               empty() const { return entries.empty(); }
    std::size_t                        size() const { return entries.size(); }

  private:
    std::vector<Entry> entries;
  };

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
    /// Further /summary columns of the postprocessors, by their rows of the
    /// table of output fields (SI).
    ColumnValues columns;
  };

  /// An internal variable of the material law along the meridian, as the law
  /// declares it (MembraneLaw::internal_variables()): a /steps dataset of
  /// its own, values in its unit.
  struct InternalField
  {
    std::string         name, unit, description;
    std::vector<double> values;
  };

  /// Fields along the meridian, one entry per sample point (SI; theta in rad).
  struct StepFields
  {
    std::vector<double> R, r, z, theta, lambda1, lambda2, s1, s2, E, Phi;
    std::vector<int>    ring;
    /// The law's internal variables that it writes (empty for an elastic law).
    std::vector<InternalField> internal;

    /// The values of the internal variable @p name; throws
    /// std::out_of_range if the law has none of that name.
    const std::vector<double> &internal_values(const std::string &name) const;
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
