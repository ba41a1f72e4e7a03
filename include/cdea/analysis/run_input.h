#pragma once
// The input of a run (`cdea run`, `cdea shoot`, `cdea compare`, and the same
// runs in-process): the validated parameters, their scene and every parameter
// as text, with the checks that depend on the model that runs them.

#include <cdea/analysis/uncertainty.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/model/scene.h>

#include <string>

namespace cdea
{
  /// The model of a run, and the root attribute `method` of its results
  /// file. A run of finite_elements with Time/Enabled is a run in time.
  enum class RunMethod
  {
    finite_elements,
    shooting,
    finite_elements_in_time
  };

  /// "finite elements", "shooting", "finite elements in time".
  std::string to_string(RunMethod method);

  /// The input of a run: validated parameters, their scene, and every
  /// parameter as text (for the results file).
  struct RunInput
  {
    Parameters  parameters;
    Scene       scene;
    std::string text;
    /// Subsection Uncertainty checked against the scene (a quasi-static FE run only).
    UncertainConstants uncertainty;
  };

  /// The checks of a run beyond the parameters' own: the scene and the
  /// Reservoir; for the shooting model also the FE-only options refused for
  /// the command @p command ("shoot", "compare") and the voltage path followed
  /// by load stepping (@p note, if given, receives the line the command
  /// prints when that changes the Continuation). Throws InputError with the
  /// message the command prints.
  RunInput run_input(const Parameters &parameters, const std::string &text, RunMethod method,
                     const std::string &command, std::string *note = nullptr);

  /// The parameters of @p input read (read_parameters()) and checked as
  /// run_input() does for `cdea run` (finite elements) or `cdea shoot`.
  RunInput read_run_input(const ParameterInput &input, RunMethod method,
                          std::string *note = nullptr);

  /// @p p with the voltage path followed by load stepping, as the shooting
  /// model does; @p note receives a line for the user if that changed the
  /// Continuation (else it is left empty).
  Parameters load_stepping_parameters(const Parameters &p, const std::string &command,
                                      std::string &note);

  /// Where the command writes the results of a run of @p method:
  /// <Directory>/<Base name>.h5, or <Base name>_shooting.h5.
  std::string results_path(const Parameters &p, RunMethod method);
} // namespace cdea
