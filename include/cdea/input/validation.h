#pragma once
// Checks of the input beyond what deal.II's patterns check: the range of every
// numeric input at parse time (validate_ranges(), the allowed ranges of
// doc/usage.md), the entries of time runs (validate_time()), the Reservoir,
// the load terms' options (validate_load_terms()), and what a command or study
// cannot do (the FE-only options for the shooting model, time runs, load terms
// and laws other than the film's for the design studies). Every
// message names the parameter and is one short line.

#include <string>

namespace cdea
{
  struct Parameters;
  struct Scene;

  /// The voltage ceiling: no ring voltage may make the field in the flat
  /// pre-stretched film, V lam_pre^2 / H, exceed this (V/m).
  constexpr double max_flat_field = 1e10;

  /// The largest voltage (V) of @p scene's film: max_flat_field H / lam_pre^2.
  double voltage_ceiling(const Scene &scene);

  /// Throws InputError naming the first parameter outside its allowed range
  /// (finite, physically sensible, and a run of bounded size: steps, mesh,
  /// results held in memory), or an output name the file system cannot take.
  /// @p scene is p.scene().
  void validate_ranges(const Parameters &p, const Scene &scene);

  /// Checks the Material/Model and Time entries (reads the table file): the
  /// law of Material/Model is built from its entries, which the law checks;
  /// throws InputError naming the parameter.
  void validate_time(const Parameters &p);

  /// Subsection Response (the frequency range, the membrane's density).
  void validate_dynamics(const Parameters &p);

  /// Rejects bad Reservoir entries with an InputError that names the
  /// parameter, e.g. "Reservoir/Width (mm) must be positive, got -3" (the
  /// water's are the water term's, checked with the others' by validate_ranges()).
  void validate_reservoir(const Parameters &p);

  /// Refuses a load term switched on (fe/load_term.h) with an option it does
  /// not support (LoadTermSupport): Time/Enabled = true, Solver/Continuation =
  /// arc length, Solver/Stability check = true. InputError "ENTRY = VALUE is
  /// not supported with OPTION (use OFF)".
  void validate_load_terms(const Parameters &p);

  /// Refuses a load term switched on that lacks @p support (LoadTermSupport)
  /// for the command @p command ("sweep"): InputError "ENTRY = VALUE is not
  /// supported by cdea COMMAND: WHY (use OFF)".
  void require_load_term_support(const Parameters &p, unsigned int support,
                                 const std::string &command, const std::string &why);

  /// Whether the law of Material/Model serves the shooting model and the
  /// design studies (MembraneLaw::serves_every_model(): the elastic laws of
  /// the library, not the viscoelastic one).
  bool serves_every_model(const Parameters &p);

  /// Refuses the options only the FE model has (load terms without
  /// supports_shooting, such as the water load; the relaxed law; a
  /// Material/Model that does not serve every model) and time runs for the
  /// command @p command ("shoot", "compare"): throws InputError.
  void require_shooting_options(const Parameters &p, const std::string &command);

  /// The design studies build their models with an elastic law that serves
  /// every model: throws InputError "Material/Model = NAME is not supported
  /// by cdea COMMAND: WHY (use elastic)" for any other law.
  void require_film_law(const Parameters &p, const std::string &command, const std::string &why);

  /// The design commands (@p command: "optimize", "fit") work on the
  /// quasi-static elastic model, whose sensitivities they use: throws
  /// InputError naming Time/Enabled or Material/Model if the file asks for
  /// a time run or the viscoelastic law.
  void require_quasi_static_elastic(const Parameters &p, const std::string &command);
} // namespace cdea
