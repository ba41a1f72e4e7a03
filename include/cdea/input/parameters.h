#pragma once
// Run-time parameters, one struct per subsection of the .prm file (as in the
// deal.II tutorial step-44). Each struct declares its entries, documented where
// they are declared, and parses them; choices become enums. The subsections of
// the model are here, those of time runs in parameters_time.h, those of the
// design studies in parameters_design.h and the entries of the registered
// plugins (Material/Model and the laws' constants, the load terms' entries)
// in parameters_plugins.h;
// Parameters holds them all.
// Parameters::scene() turns them into a Scene and rejects bad input with an
// InputError that names the parameter. Reading a file (with overrides) is
// parameter_input.h, the range checks validation.h, the solver settings made
// from them solver_settings.h.

#include <cdea/base/text.h>
#include <cdea/input/parameters_design.h>
#include <cdea/input/parameters_plugins.h>
#include <cdea/input/parameters_dynamics.h>
#include <cdea/input/parameters_time.h>
#include <cdea/model/equilibrium_model.h>
#include <cdea/model/scene.h>
#include <cdea/numerics/tangent_solver.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{

  /// How the voltage path is followed (Solver/Continuation).
  enum class Continuation
  {
    load_stepping,
    arc_length
  };

  /// Wrinkling/Model: the plain law with s2 < 0 flagged, or the relaxed law.
  enum class WrinklingModel
  {
    check,
    relaxed
  };

  /// The prm spelling of each choice, for messages.
  std::string to_string(Continuation choice);
  std::string to_string(WrinklingModel choice);

  namespace parameters
  {
    struct Geometry
    {
      double disk_radius_mm;
      double frame_radius_mm;
      double film_thickness_mm;
      double prestretch;
      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    };

    struct Material
    {
      double shear_modulus_kPa;
      double jlim;
      double permittivity;
      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    };

    struct Loading
    {
      double mass_g;
      double gravity;
      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    };

    struct Electrodes
    {
      std::string ring_edges_text;   ///< "1, 1.7, 3"
      std::string voltage_path_text; ///< "5, 5; 5, 6.5"
      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    };

    struct Discretization
    {
      unsigned int polynomial_degree;
      unsigned int elements_per_ring;
      double       grading;
      unsigned int refinements;
      unsigned int samples_per_element;
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);
    };

    struct Solver
    {
      double       residual_tolerance;
      double       update_tolerance;
      unsigned int max_newton_iterations;
      unsigned int prestretch_steps;
      double       load_increment;
      double       voltage_increment_kV;
      double       min_voltage_increment_kV;
      unsigned int max_cutbacks;
      Continuation continuation;
      LinearSolver linear_solver;
      unsigned int max_arc_length_steps;
      double       max_displacement_mm;
      bool         stability_check;
      StabilityEigenvalue stability_eigenvalue;
      double       breakdown_field_MV_per_m;
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);
    };

    struct Wrinkling
    {
      double      onset_tolerance_V;
      WrinklingModel model;
      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    };

    struct Shooting
    {
      double       tolerance;
      unsigned int samples_per_ring;
      static void  declare(dealii::ParameterHandler &prm);
      void         parse(dealii::ParameterHandler &prm);
    };

    /// The pump module's level tube, for the level drop of every run (the
    /// water load's entries are the water term's, fe/water_term.h).
    struct Reservoir
    {
      double      width_mm;
      double      depth_mm;
      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    };

    struct Output
    {
      std::string directory;
      std::string base_name;
      bool         paraview;          ///< also write <Base name>.pvd and its VTU files
      unsigned int paraview_segments; ///< cells around the axis in the revolved surface
      static void declare(dealii::ParameterHandler &prm);
      void        parse(dealii::ParameterHandler &prm);
    };
  } // namespace parameters

  struct Parameters
  {
    parameters::Geometry       geometry;
    parameters::Material       material;
    parameters::Loading        loading;
    parameters::Electrodes     electrodes;
    parameters::Discretization discretization;
    parameters::Solver         solver;
    parameters::Wrinkling      wrinkling;
    parameters::Shooting       shooting;
    parameters::Sweep          sweep;
    parameters::Reservoir      reservoir;
    parameters::Optimization   optimization;
    parameters::Calibration    calibration;
    parameters::Output         output;
    parameters::MaterialLaw    material_law; ///< parameters_plugins.h
    parameters::Time           time;         ///< parameters_time.h
    parameters::LoadTerms      load_terms;   ///< parameters_plugins.h
    parameters::Response        response;         ///< parameters_dynamics.h
    parameters::SteadyState     steady_state;     ///< parameters_dynamics.h
    parameters::FrequencySweep  frequency_sweep;  ///< parameters_dynamics.h

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);

    /// The physical scene in SI units; throws InputError on bad input.
    Scene scene() const;

    /// Path of the results file, "<Directory>/<Base name>.h5".
    std::string results_path(const std::string &suffix = "") const;

    /// Warnings of read_parameters() (entries set twice), for the user.
    std::vector<std::string> input_warnings;
  };

  enum class ParameterFormat
  {
    prm, ///< a .prm file with every entry documented
    json ///< deal.II's JSON form: value, default, pattern and documentation of each entry
  };

  /// A complete, documented parameter file with every default.
  std::string default_parameter_file(ParameterFormat format = ParameterFormat::prm);
} // namespace cdea
