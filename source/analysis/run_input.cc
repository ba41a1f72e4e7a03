#include <cdea/analysis/run_input.h>
#include <cdea/input/validation.h>

namespace cdea
{
  std::string to_string(const RunMethod method)
  {
    switch (method)
      {
        case RunMethod::shooting:
          return "shooting";
        case RunMethod::finite_elements_in_time:
          return "finite elements in time";
        case RunMethod::finite_elements:
          break;
      }
    return "finite elements";
  }

  Parameters load_stepping_parameters(const Parameters &p, const std::string &command,
                                      std::string &note)
  {
    Parameters q = p;
    note.clear();
    if (q.solver.continuation != Continuation::load_stepping)
      {
        note = "cdea " + command + ": Solver/Continuation = " +
               to_string(q.solver.continuation) +
               " applies to the FE model of 'cdea run'; both solvers follow the path by load "
               "stepping here";
        q.solver.continuation = Continuation::load_stepping;
      }
    return q;
  }

  RunInput run_input(const Parameters &parameters, const std::string &text,
                     const RunMethod method, const std::string &command, std::string *note)
  {
    RunInput in;
    in.parameters = parameters;
    in.text       = text;
    in.scene      = in.parameters.scene();
    validate_reservoir(in.parameters);
    if (method == RunMethod::shooting || in.parameters.time.enabled)
      require_uncertainty_support(in.parameters,
                                 method == RunMethod::shooting ? command : "run in time");
    else
      in.uncertainty = uncertain_constants(in.parameters, in.scene);
    if (method == RunMethod::shooting)
      {
        require_shooting_options(in.parameters, command);
        std::string line;
        in.parameters = load_stepping_parameters(in.parameters, command, line);
        if (note)
          *note = line;
      }
    return in;
  }

  RunInput read_run_input(const ParameterInput &input, const RunMethod method, std::string *note)
  {
    std::string      text;
    const Parameters p = read_parameters(input, &text);
    return run_input(p, text, method, "shoot", note);
  }

  std::string results_path(const Parameters &p, const RunMethod method)
  {
    return p.results_path(method == RunMethod::shooting ? "_shooting" : "");
  }
} // namespace cdea
