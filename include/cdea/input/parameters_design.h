#pragma once
// The subsections of the design studies: Sweep (`cdea sweep`,
// doc/design-maps.md), Optimization (`cdea optimize`, doc/optimization.md) and
// Calibration (`cdea fit`). Entries are read as text here; sweep_settings(),
// optimization_settings() and fit_settings() check them and name the
// parameter in every message.

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{
  /// Optimization/Objective.
  enum class DesignObjective
  {
    stroke,
    volume_change
  };

  /// Optimization/Algorithm: NLopt's gradient-based methods.
  enum class DesignAlgorithm
  {
    slsqp,
    mma
  };

  std::string to_string(DesignObjective choice);
  std::string to_string(DesignAlgorithm choice);

  namespace parameters
  {
    /// `cdea sweep`: two-ring layouts 1, r_v/a, b/a; validated by the sweep.
    struct Sweep
    {
      std::string ring_edge_values_text;    ///< "1.2, 1.25, 1.3, ..., 2.6"
      double      inner_voltage_kV;
      std::string outer_voltage_range_text; ///< "from, to, step"
      bool        confirm_long;             ///< more than 1e6 map points allowed
      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    };

    struct Optimization
    {
      unsigned int    rings;
      std::string     fixed_voltages_text; ///< "5, free"
      std::string     fixed_edges_text;    ///< "free" or "1.7, free"
      std::string     edge_bounds_text;    ///< "1.2, 2.6"
      std::string     voltage_bounds_text; ///< "0, 8"
      std::string     min_hoop_stress_text;
      std::string     max_field_text; ///< a number or "inf"
      std::string     min_ring_width_text;
      DesignObjective objective;
      unsigned int    starts;
      DesignAlgorithm algorithm;
      unsigned int    max_evaluations;
      double          tolerance;
      static void     declare(dealii::ParameterHandler &prm);
      void            parse(dealii::ParameterHandler &prm);
    };

    struct Calibration
    {
      std::string  free_parameters_text; ///< "shear modulus, Jlim"
      unsigned int max_iterations;
      double       tolerance;
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace cdea
