#include <deal.II/base/parameter_handler.h>

#include <cdea/base/run_control.h>
#include <cdea/input/duplicate_entries.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/input/prm_text.h>
#include <cdea/input/validation.h>
#include <cdea/output/safe_files.h>

#include <filesystem>
#include <cctype>
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

    /// "in parameter file 'x.prm': " or "in parameter text: ".
    std::string where(const ParameterInput &input)
    {
      return input.is_text ? std::string("in parameter text: ") :
                             "in parameter file '" + input.source + "': ";
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
          const std::string ours = explain_override_error(key, value, message_of(e));
          throw InputError(name + " = '" + value + "': " + (ours.empty() ? message_of(e) : ours));
        }
      prm.leave_subsection();
      check_override_value(key, value);
    }

    /// A .json or .xml parameter file: the bytes read (bounded, a regular
    /// file) go to deal.II's reader of that format, which opens nothing.
    void parse_other_format(const ParameterInput &input, const std::string &extension,
                            const std::string &bytes, ParameterHandler &prm)
    {
      if (extension != ".json" && extension != ".xml")
        throw InputError(where(input) + "the name of a parameter file must end in .prm, .json "
                         "or .xml");
      std::istringstream in(bytes);
      try
        {
          if (extension == ".json")
            prm.parse_input_from_json(in, false);
          else
            prm.parse_input_from_xml(in, false);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(where(input) + message_of(e));
        }
    }

    /// @p prm with every entry declared, the file or text parsed and the
    /// overrides set; returns the main text (a file read bounded, its
    /// includes expanded and its structure checked first: prm_text.h).
    std::string parse_input(const ParameterInput &input, ParameterHandler &prm)
    {
      const std::string raw  = input.is_text ? input.source : read_parameter_file(input.source);
      const std::string name = input.is_text ? "parameter text" : input.source;
      std::string extension = std::filesystem::path(name).extension();
      for (char &c : extension)
        c = char(std::tolower(static_cast<unsigned char>(c)));
      Parameters::declare(prm);
      std::string main = raw;
      if (input.is_text || extension == ".prm")
        {
          const PrmText text = prepare_parameter_text(raw, name, !input.is_text, prm);
          main               = text.main;
          try
            {
              std::istringstream in(text.text);
              prm.parse_input(in, name, "", false);
            }
          catch (const dealii::ExceptionBase &e)
            {
              throw InputError(explain_parse_error(text, message_of(e)));
            }
        }
      else
        parse_other_format(input, extension, raw, prm);
      for (const auto &[key, value] : input.overrides)
        apply_override(prm, key, value);
      return main;
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
    ParameterHandler  prm;
    const std::string content = parse_input(input, prm);
    Parameters        parameters;
    try
      {
        parameters.parse(prm);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError(where(input) + message_of(e));
      }
    validate_ranges(parameters, parameters.scene()); // now, before anything is written
    validate_time(parameters);
    validate_load_terms(parameters);
    validate_dynamics(parameters);
    parameters.input_warnings =
      duplicate_entry_warnings(content, input.is_text ? "parameter text" : input.source);
    if (text)
      {
        std::ostringstream out;
        prm.print_parameters(out, ParameterHandler::ShortText);
        *text = out.str();
      }
    return parameters;
  }

  Parameters read_parameters(const std::string &filename, std::string *text)
  {
    return read_parameters(ParameterInput::file(filename), text);
  }

  void write_changed_parameters(const ParameterInput &input, const std::string &path,
                                const std::vector<ParameterChange> &changes,
                                const std::string                  &comment)
  {
    ParameterHandler prm;
    parse_input(input, prm);
    for (const ParameterChange &c : changes)
      {
        prm.enter_subsection(c.subsection);
        prm.set(c.entry, c.value);
        prm.leave_subsection();
      }
    std::ostringstream text;
    text << comment;
    prm.print_parameters(text, ParameterHandler::ShortText);
    const std::string  bytes = text.str();
    const WriteOutcome out   = replace_file(path, {bytes.begin(), bytes.end()}, true);
    if (!out.ok)
      throw std::runtime_error("cannot write '" + path + "': " + out.message);
  }
} // namespace cdea
