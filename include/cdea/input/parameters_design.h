#pragma once
// The subsections of the design commands: Optimization (`cdea optimize`,
// doc/optimization.md) and Calibration (`cdea fit`). Entries are read as
// text here; optimize_settings() and fit_settings() check them and name the
// parameter in every message.

#include <cdea/base/format.h> // exact_number() for the parameter files the commands write

#include <string>
#include <vector>

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

  /// One entry of a parameter file to set: subsection, entry, value.
  struct ParameterChange
  {
    std::string subsection, entry, value;
  };

  /// Write @p prm_file with @p changes applied to @p path (all entries, as
  /// deal.II prints them; replaced only once complete), after the comment
  /// lines @p comment. Throws std::runtime_error naming @p path.
  void write_changed_parameters(const std::string &prm_file, const std::string &path,
                                const std::vector<ParameterChange> &changes,
                                const std::string                  &comment);

  struct Parameters;

  /// The design commands (@p command: "optimize", "fit") work on the
  /// quasi-static elastic model, whose sensitivities they use: throws
  /// InputError naming Time/Enabled or Material/Model if the file asks for
  /// a time run or the viscoelastic law.
  void require_quasi_static_elastic(const Parameters &p, const std::string &command);

  namespace parameters
  {
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
