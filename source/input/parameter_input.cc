#include <deal.II/base/parameter_handler.h>

#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/base/run_control.h>
#include <cdea/input/validation.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace cdea
{
  using dealii::ParameterHandler;

  namespace
  {
    std::string message_of(const dealii::ExceptionBase &e)
    {
      std::ostringstream message;
      e.print_info(message);
      return fold_whitespace(message.str());
    }

    /// Sets "Subsection/Entry" = value in @p prm, or throws an InputError
    /// naming the key.
    void apply_override(ParameterHandler &prm, const std::string &key, const std::string &value)
    {
      const std::string name  = "override '" + key + "'";
      const auto        slash = key.find('/');
      if (slash == std::string::npos || slash == 0 || slash + 1 == key.size())
        throw InputError(name + ": expected 'Subsection/Entry', e.g. 'Loading/Mass (g)'");
      const std::string section = key.substr(0, slash), entry = key.substr(slash + 1);
      if (!prm.subsection_path_exists({section}))
        throw InputError(name + ": there is no subsection '" + section +
                         "' (cdea print-parameters lists every parameter)");
      prm.enter_subsection(section);
      try
        {
          prm.set(entry, value);
        }
      catch (const ParameterHandler::ExcEntryUndeclared &)
        {
          prm.leave_subsection();
          throw InputError(name + ": subsection " + section + " has no entry '" + entry +
                           "' (cdea print-parameters lists every parameter)");
        }
      catch (const dealii::ExceptionBase &e)
        {
          prm.leave_subsection();
          throw InputError(name + " = '" + value + "': " + message_of(e));
        }
      prm.leave_subsection();
    }
  } // namespace

  ParameterInput ParameterInput::file(const std::string &path)
  {
    ParameterInput input;
    input.source = path;
    return input;
  }

  ParameterInput ParameterInput::text(const std::string &prm_text)
  {
    ParameterInput input;
    input.is_text = true;
    input.source  = prm_text;
    return input;
  }

  Parameters read_parameters(const ParameterInput &input, std::string *text)
  {
    const std::string &filename = input.source;
    if (!input.is_text)
      {
        std::ifstream probe(filename);
        if (!probe || !std::filesystem::is_regular_file(filename))
          throw InputError("cannot read parameter file '" + filename +
                           "': it does not exist, is not a regular file or is not readable");
      }
    ParameterHandler prm;
    Parameters::declare(prm);
    try
      {
        if (input.is_text)
          {
            std::istringstream in(input.source);
            prm.parse_input(in, "parameter text", "", false);
          }
        else
          prm.parse_input(filename, "", false, false);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError((input.is_text ? std::string("in parameter text: ") :
                                          "in parameter file '" + filename + "': ") +
                         message_of(e));
      }
    for (const auto &[key, value] : input.overrides)
      apply_override(prm, key, value);
    Parameters parameters;
    try
      {
        parameters.parse(prm);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError((input.is_text ? std::string("in parameter text: ") :
                                          "in parameter file '" + filename + "': ") +
                         message_of(e));
      }
    validate_ranges(parameters, parameters.scene()); // now, before anything is written
    validate_time(parameters);
    if (input.is_text)
      parameters.input_warnings = duplicate_entry_warnings(input.source, "parameter text");
    else
      {
        std::ifstream      in(filename);
        std::ostringstream content;
        content << in.rdbuf();
        parameters.input_warnings = duplicate_entry_warnings(content.str(), filename);
      }
    if (text)
      {
        std::ostringstream out;
        prm.print_parameters(out, ParameterHandler::ShortText);
        *text = out.str();
      }
    return parameters;
  }
} // namespace cdea
