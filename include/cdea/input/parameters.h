#pragma once
// Run-time parameters, one struct per subsection of the .prm file (as in the
// deal.II tutorial step-44). Each struct declares its entries and binds them
// to its members in one place (declare(), on the one table of
// base/parameter_declarations.h: deal.II's add_parameter); choices become
// enums. Each subsection registers itself (CDEA_REGISTER_PARAMETER_SUBSECTION,
// in the source file that declares it) with its position among the others:
// no list of subsections is kept anywhere else. The structs are here, their
// entries in the sources input/parameters_model.cc (the model),
// parameters_time.cc (time runs), parameters_design.cc (the design studies),
// parameters_dynamics.cc (the small-signal response, the periodic steady
// states) and parameters_plugins.cc (Material/Model and the laws' constants,
// the load terms' entries). Parameters holds them all; a subsection that
// keeps its struct to itself is held by type (Parameters::subsection<S>()).
// Parameters::scene() turns them into a Scene and rejects bad input with an
// InputError that names the parameter. Reading a file (with overrides) is
// parameter_input.h, the range checks validation.h, the solver settings made
// from them solver_settings.h.

#include <cdea/base/parameter_declarations.h>
#include <cdea/base/text.h>
#include <cdea/material/law_factory.h>
#include <cdea/model/equilibrium_model.h>
#include <cdea/model/scene.h>
#include <cdea/model/waveform.h>   // WaveformKind
#include <cdea/numerics/esdirk.h>  // TimeMethod, TimeStepControl
#include <cdea/numerics/tangent_solver.h>

#include <any>
#include <map>
#include <stdexcept>
#include <string>
#include <typeindex>
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

  /// Output/Step rows: which steps of a time run the terminal's table shows.
  enum class StepRows
  {
    every,    ///< a row per step
    progress, ///< a row per twentieth of the waveform's time, and every row before it
    none      ///< no rows: the banner, events and the final state only
  };

  /// The prm spelling of each choice, for messages.
  std::string to_string(Continuation choice);
  std::string to_string(WrinklingModel choice);
  std::string to_string(WaveformKind choice);
  std::string to_string(TimeMethod choice);
  std::string to_string(TimeStepControl choice);
  std::string to_string(DesignObjective choice);
  std::string to_string(DesignAlgorithm choice);

  namespace parameters
  {
    // The model (input/parameters_model.cc).

    struct Geometry
    {
      double disk_radius_mm;
      double frame_radius_mm;
      double film_thickness_mm;
      double prestretch;
      void   declare(ParameterDeclarations &prm);
    };

    struct Material
    {
      double shear_modulus_kPa;
      double jlim;
      double permittivity;
      void   declare(ParameterDeclarations &prm);
    };

    struct Loading
    {
      double mass_g;
      double gravity;
      void   declare(ParameterDeclarations &prm);
    };

    struct Electrodes
    {
      std::string ring_edges_text;   ///< "1, 1.7, 3"
      std::string voltage_path_text; ///< "5, 5; 5, 6.5"
      void        declare(ParameterDeclarations &prm);
    };

    struct Discretization
    {
      unsigned int polynomial_degree;
      unsigned int elements_per_ring;
      double       grading;
      unsigned int refinements;
      unsigned int samples_per_element;
      bool         error_estimate; ///< of a quasi-static run (analysis/run_error_estimate.h)
      void         declare(ParameterDeclarations &prm);
    };

    struct Solver
    {
      double              residual_tolerance;
      double              update_tolerance;
      unsigned int        max_newton_iterations;
      unsigned int        prestretch_steps;
      double              load_increment;
      double              voltage_increment_kV;
      double              min_voltage_increment_kV;
      unsigned int        max_cutbacks;
      Continuation        continuation;
      LinearSolver        linear_solver;
      unsigned int        max_arc_length_steps;
      double              max_displacement_mm;
      bool                stability_check;
      StabilityEigenvalue stability_eigenvalue;
      double              breakdown_field_MV_per_m;
      void                declare(ParameterDeclarations &prm);
    };

    struct Wrinkling
    {
      double         onset_tolerance_V;
      WrinklingModel model;
      void           declare(ParameterDeclarations &prm);
    };

    struct Shooting
    {
      double       tolerance;
      unsigned int samples_per_ring;
      void         declare(ParameterDeclarations &prm);
    };

    /// The pump module's level tube, for the level drop of every run (the
    /// water load's entries are the water term's, fe/water_term.h).
    struct Reservoir
    {
      double width_mm;
      double depth_mm;
      void   declare(ParameterDeclarations &prm);
    };

    struct Output
    {
      std::string  directory;
      std::string  base_name;
      bool         paraview;          ///< also write <Base name>.pvd and its VTU files
      unsigned int paraview_segments; ///< cells around the axis in the revolved surface
      StepRows     step_rows;         ///< a time run's rows in the terminal
      void         declare(ParameterDeclarations &prm);
    };

    // Time runs (doc/time.md, input/parameters_time.cc): checked by
    // validate_time() (validation.h), made the stepper's settings by
    // time_settings() (solver_settings.h).

    struct Time
    {
      bool            enabled;
      WaveformKind    waveform;
      double          ramp_time_s;
      double          hold_time_s;
      double          frequency_Hz;
      unsigned int    cycles;
      double          rise_time_s;
      std::string     table_file;
      double          time_step_s;
      double          min_time_step_s;
      TimeMethod      scheme;
      TimeStepControl step_control;
      double          relative_tolerance;
      double          absolute_tolerance_mm;
      double          internal_tolerance;
      bool            inertia;
      bool            water_inertia;
      std::string     rest_time_text; ///< "relaxed" or seconds
      double          fields_interval_s;
      void            declare(ParameterDeclarations &prm);

      /// Rest time before voltage (s): infinity for 'relaxed'; throws
      /// InputError naming the entry unless it is 'relaxed' or a time >= 0.
      double rest_time() const;
    };

    // The design studies (input/parameters_design.cc): their entries are text
    // here, checked by sweep_settings(), optimization_settings() and
    // fit_settings(), which name the parameter in every message.

    /// `cdea sweep` (doc/design-maps.md): two-ring layouts 1, r_v/a, b/a.
    struct Sweep
    {
      std::string ring_edge_values_text;    ///< "1.2, 1.25, 1.3, ..., 2.6"
      double      inner_voltage_kV;
      std::string outer_voltage_range_text; ///< "from, to, step"
      bool        confirm_long;             ///< more than 1e6 map points allowed
      void        declare(ParameterDeclarations &prm);
    };

    /// `cdea optimize` (doc/optimization.md).
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
      void            declare(ParameterDeclarations &prm);
    };

    /// `cdea fit`.
    struct Calibration
    {
      std::string  free_parameters_text; ///< "shear modulus, Jlim"
      std::string  candidate_models_text; ///< "elastic 0, elastic 1" (model selection)
      unsigned int max_iterations;
      double       tolerance;
      void         declare(ParameterDeclarations &prm);
    };

    // The dynamics (doc/dynamics.md, input/parameters_dynamics.cc): the
    // small-signal response of `cdea response` (checked by
    // validate_dynamics()), the periodic steady states and the frequency
    // sweep of `cdea frequency-sweep` (checked by frequency_sweep_settings()).

    struct Response
    {
      double       lowest_frequency_Hz;
      double       highest_frequency_Hz;
      unsigned int frequencies;
      unsigned int modes;
      double       membrane_density;
      void         declare(ParameterDeclarations &prm);
    };

    struct SteadyState
    {
      double       tolerance;
      unsigned int max_newton_iterations;
      unsigned int krylov_dimension;
      unsigned int start_periods;
      double       low_fraction;
      void         declare(ParameterDeclarations &prm);
    };

    struct FrequencySweep
    {
      double      lowest_frequency_Hz;
      double      highest_frequency_Hz;
      int         frequencies; ///< as given (checked by the command)
      bool        log_spacing;
      std::string frequency_list; ///< "Frequencies (Hz)" as given; empty: the range
      double      usable_factor;
      bool        confirm_long; ///< more than 1000 frequencies allowed
      void        declare(ParameterDeclarations &prm);
    };

    // The plugins' entries (input/parameters_plugins.cc): their selection,
    // documentation and entries come from the registries of the material
    // laws (material/law_factory.h) and the load terms (fe/load_term.h).

    /// Material/Model and the entries the registered laws declare in
    /// subsection Material.
    struct MaterialLaw
    {
      std::string                        model;     ///< a registered law's name
      std::map<std::string, double>      constants; ///< every law's number entries, by name
      std::map<std::string, std::string> texts;     ///< every law's text entries, by name
      void                               declare(ParameterDeclarations &prm);

      /// The settings of the law, with @p network_a (the film's constants, SI).
      LawSettings settings(const MaterialConstants &network_a) const;
    };

    /// The entries the registered load terms declare, and those of the core
    /// they read, by path: what MembraneModel::set_load_terms() and the
    /// checks of validation.h build the terms from.
    struct LoadTermValues
    {
      ParameterValues values;
      /// Declares the terms' entries of subsection Reservoir (@p reservoir
      /// true: they stand with the Reservoir's own) or the others.
      void declare(ParameterDeclarations &prm, bool reservoir);
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
    parameters::MaterialLaw    material_law;
    parameters::Time           time;
    parameters::LoadTermValues load_terms;
    parameters::Response       response;
    parameters::SteadyState    steady_state;
    parameters::FrequencySweep frequency_sweep;

    /// Every registered subsection's entries, bound to this object, in the
    /// order of their positions (the order deal.II declares them in).
    ParameterDeclarations declarations();

    /// Declares every entry in @p prm.
    static void declare(dealii::ParameterHandler &prm);
    /// Every entry's value from @p prm (declared by declare()) into this object.
    void parse(dealii::ParameterHandler &prm);
    /// The checks the subsections register, in the order of their positions.
    void check_subsections() const;

    /// The physical scene in SI units; throws InputError on bad input.
    Scene scene() const;

    /// Path of the results file, "<Directory>/<Base name>.h5".
    std::string results_path(const std::string &suffix = "") const;

    /// Warnings of read_parameters() (entries set twice), for the user.
    std::vector<std::string> input_warnings;

    /// The subsection whose struct is @p S, held by type (one registered
    /// with CDEA_REGISTER_OWN_SUBSECTION); throws std::logic_error if it was
    /// never declared on this object.
    template <typename S>
    const S &subsection() const
    {
      const auto it = own.find(std::type_index(typeid(S)));
      if (it == own.end())
        throw std::logic_error(std::string("no parameter subsection ") + S::name +
                               " was read into these parameters");
      return std::any_cast<const S &>(it->second);
    }
    /// The same, made (default-constructed) if it is not there yet.
    template <typename S>
    S &subsection()
    {
      std::any &held = own[std::type_index(typeid(S))];
      if (!held.has_value())
        held = S{};
      return std::any_cast<S &>(held);
    }

  private:
    std::map<std::type_index, std::any> own;
  };

  /// A subsection of the parameter file as it registers itself.
  struct ParameterSubsection
  {
    /// Where its entries stand among the others' (the subsections are
    /// declared by increasing position; deal.II numbers the patterns in that
    /// order, and print-parameters --json shows the numbers). A new
    /// subsection takes a position after the last (the Frequency sweep's 190).
    int position;
    /// Declares its entries on @p prm, bound to its part of @p p.
    void (*declare)(ParameterDeclarations &prm, Parameters &p);
    /// Its checks of a file read (InputError naming the entry), run after
    /// the checks of validation.h; nullptr: none.
    void (*check)(const Parameters &p);
  };

  /// Registers @p subsection; true. Throws std::logic_error if its position is taken.
  bool register_parameter_subsection(const ParameterSubsection &subsection);

  enum class ParameterFormat
  {
    prm, ///< a .prm file with every entry documented
    json ///< deal.II's JSON form: value, default, pattern and documentation of each entry
  };

  /// A complete, documented parameter file with every default.
  std::string default_parameter_file(ParameterFormat format = ParameterFormat::prm);

  /// Declares @p declarations' entries that are declared here
  /// (EntryDeclaration::declared_here) in @p prm, in their order.
  void declare_entries(dealii::ParameterHandler &prm, const ParameterDeclarations &declarations);

  /// Hands every entry of @p declarations its value from @p prm, in their order.
  void read_entries(dealii::ParameterHandler &prm, const ParameterDeclarations &declarations);
} // namespace cdea

/// Registers a subsection: @p declare (void(ParameterDeclarations &,
/// Parameters &)) at @p position, with @p check (void(const Parameters &) or
/// nullptr); one line in the source file that declares it, inside namespace
/// cdea. @p tag names the registration (unique in its file).
#define CDEA_REGISTER_PARAMETER_SUBSECTION(tag, position, declare, check)                     \
  namespace                                                                                  \
  {                                                                                          \
    [[maybe_unused]] const bool tag##_registered =                                          \
      ::cdea::register_parameter_subsection({position, declare, check});                     \
  }

/// Registers the subsection Parameters::@p member (its declare(
/// ParameterDeclarations &) binds its entries) at @p position.
#define CDEA_REGISTER_MEMBER_SUBSECTION(member, position)                                     \
  CDEA_REGISTER_PARAMETER_SUBSECTION(                                                        \
    member, position,                                                                        \
    [](::cdea::ParameterDeclarations &prm, ::cdea::Parameters &p) { p.member.declare(prm); }, \
    nullptr)

/// Registers the subsection whose struct is @p S, held by type in Parameters
/// (Parameters::subsection<S>()): S::name is its name, S::declare(
/// ParameterDeclarations &) binds its entries, S::check() checks them; at
/// @p position, under the registration's name @p tag.
#define CDEA_REGISTER_OWN_SUBSECTION(tag, S, position)                                        \
  CDEA_REGISTER_PARAMETER_SUBSECTION(                                                        \
    tag, position,                                                                             \
    [](::cdea::ParameterDeclarations &prm, ::cdea::Parameters &p) {                         \
      p.subsection<S>().declare(prm);                                                        \
    },                                                                                       \
    [](const ::cdea::Parameters &p) { p.subsection<S>().check(); })
