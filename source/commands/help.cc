// `cdea --help` (also -h, help): the usage text, made from the command table.

#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// Where the descriptions start.
    constexpr std::size_t description_column = 29;

    /// "  cdea run FILE.prm          solve the scene ...", one line per line
    /// of the description.
    void add_form(std::ostringstream &out, const std::string &name, const std::string &form,
                  const std::string &help)
    {
      std::string usage = "  cdea " + name;
      if (!form.empty() && form != "...")
        usage += " " + form;
      if (usage.size() < description_column)
        out << usage << std::string(description_column - usage.size(), ' ');
      else
        out << usage << '\n' << std::string(description_column, ' ');
      std::istringstream lines(help);
      std::string        line;
      for (bool first = true; std::getline(lines, line); first = false)
        out << (first ? "" : std::string(description_column, ' ')) << line << '\n';
    }

    /// The names of the commands @p which says yes to, joined by ", ".
    std::string names(const std::function<bool(const Command &)> &which)
    {
      std::string list;
      for (const Command &command : command_table())
        if (which(command))
          list += (list.empty() ? "" : ", ") + command.name;
      return list;
    }

    /// The functions of the Python module are the commands' names with '_'
    /// for '-' (frequency-sweep: cdea.frequency_sweep()).
    std::string python_names(std::string list)
    {
      std::replace(list.begin(), list.end(), '-', '_');
      return list;
    }

    /// What the rows' flags say, for the commands that read a parameter file.
    std::string flag_notes()
    {
      std::ostringstream out;
      out << "--set 'Subsection/Entry=value' after FILE.prm sets that entry after the file\n"
          << "is read (repeatable), e.g. cdea run FILE.prm --set 'Loading/Mass (g)=300'.\n"
          << "Commands that read FILE.prm: "
          << names([](const Command &c) { return c.has(reads_parameters); }) << ".\n"
          << "Under mpirun -np N: "
          << names([](const Command &c) { return c.ranks == Ranks::all; })
          << " (the ranks share the work);\nserial jobs, refused on more than one rank: "
          << names([](const Command &c) { return c.ranks == Ranks::one; }) << ".\n"
          << "Stopped cleanly by SIGINT, SIGTERM, SIGHUP (exit 2; the steps, map rows or\n"
          << "frequencies done are written, beside an older result as <stem>.partial.h5):\n  "
          << names([](const Command &c) { return c.has(stops_on_signals); }) << ".\n"
          << "Time runs (Time/Enabled = true): "
          << names([](const Command &c) { return c.has(time_runs); }) << ".\n"
          << "In Python (import cdea, doc/python.md): "
          << python_names(names([](const Command &c) { return c.has(in_python); })) << ".\n";
      return out.str();
    }

    class Help final : public CommandJob
    {
    public:
      int run(Invocation &) override
      {
        std::cout << usage_text();
        return exit_success;
      }
    };
  } // namespace

  std::string usage_text()
  {
    std::ostringstream out;
    out << "cdea: finite-element model of a cone dielectric elastomer actuator with a\n"
           "partitioned ring electrode (axisymmetric Gent membrane, ideal dielectric).\n"
           "\n"
           "Usage:\n";
    for (const Command &command : command_table())
      for (std::size_t i = 0; i < command.forms.size(); ++i)
        add_form(out, command.name, command.forms[i], command.help.at(i));
    out << '\n'
        << flag_notes() << '\n'
        << "Exit codes: 0 success; 1 bad input or output not writable (nothing written);\n"
           "2 the run stopped before the end of its voltage path, was interrupted\n"
           "(SIGINT, SIGTERM, SIGHUP) or could not write all its steps (the messages\n"
           "say where the converged steps are).\n"
           "See doc/usage.md for every parameter and the output layout.\n";
    return out.str();
  }

  std::string command_usage(const Command &command)
  {
    std::ostringstream out;
    for (std::size_t i = 0; i < command.forms.size(); ++i)
      add_form(out, command.name, command.forms[i], command.help.at(i));
    if (command.has(reads_parameters))
      out << "--set 'Subsection/Entry=value' after FILE.prm sets that entry (repeatable).\n";
    return out.str();
  }

  std::unique_ptr<CommandJob> help_job()
  {
    return std::make_unique<Help>();
  }
} // namespace cdea
