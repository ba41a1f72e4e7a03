// The command front: every command runs through run_command(), which does by
// the flags of the command's row what every command needs (command.h).

#include <cdea/analysis/uncertainty.h>
#include <cdea/base/mpi_session.h>
#include <cdea/base/run_control.h>
#include <cdea/base/text.h>
#include <cdea/commands/command.h>

#include <iostream>
#include <optional>
#include <sstream>

namespace cdea
{
  void ClaimedOutput::give_up()
  {
    lock.release();
    remove_created_directories(created);
    created.clear();
  }

  namespace
  {
    /// A --set value "Subsection/Entry=value" as an override; throws
    /// InputError if it has no '='.
    std::pair<std::string, std::string> override_of(const std::string &setting)
    {
      const auto equal = setting.find('=');
      if (equal == std::string::npos)
        throw InputError("--set '" + setting +
                         "': expected 'Subsection/Entry=value', e.g. --set 'Loading/Mass (g)=300'");
      return {trim_blanks(setting.substr(0, equal)), trim_blanks(setting.substr(equal + 1))};
    }

    /// The words after the command's name: the arguments, and the --set
    /// overrides taken out of them (in their order).
    void split_words(const std::vector<std::string> &words, Invocation &invocation)
    {
      for (std::size_t i = 1; i < words.size(); ++i)
        if (words[i] == "--set" && invocation.command.has(reads_parameters))
          {
            if (i + 1 == words.size())
              throw InputError("--set needs a value: --set 'Subsection/Entry=value'");
            invocation.input.overrides.push_back(override_of(words[++i]));
          }
        else if (words[i].rfind("--set=", 0) == 0 && invocation.command.has(reads_parameters))
          invocation.input.overrides.push_back(override_of(words[i].substr(6)));
        else
          invocation.arguments.push_back(words[i]);
    }

    /// Whether @p arguments fit one of the row's forms.
    bool fits_a_form(const Command &command, const std::vector<std::string> &arguments)
    {
      for (const std::string &form : command.forms)
        {
          if (form == "...")
            return true;
          std::istringstream       in(form);
          std::vector<std::string> tokens;
          for (std::string t; in >> t;)
            tokens.push_back(t);
          // A last token "...": any further arguments.
          const bool more = !tokens.empty() && tokens.back() == "...";
          if (more)
            tokens.pop_back();
          bool fits = more ? arguments.size() >= tokens.size() : tokens.size() == arguments.size();
          for (std::size_t i = 0; fits && i < tokens.size(); ++i)
            fits = tokens[i][0] != '-' || tokens[i] == arguments[i];
          if (fits)
            return true;
        }
      return false;
    }

    int unknown_command(const std::string &word)
    {
      if (mpi::rank() == 0)
        std::cerr << "cdea: unknown command '" << word << "'\n\n" << usage_text();
      return exit_input_error;
    }

    /// `cdea CMD --help` or `cdea CMD -h`: the command's lines of the usage.
    bool asks_for_help(const std::vector<std::string> &arguments)
    {
      return arguments.size() == 1 && (arguments[0] == "--help" || arguments[0] == "-h");
    }

    /// A known command with arguments that fit none of its forms: what it
    /// takes and what it got.
    int wrong_arguments(const Command &command, const std::vector<std::string> &arguments)
    {
      if (mpi::rank() != 0)
        return exit_input_error;
      std::string got = arguments.empty() ? "no arguments" : "";
      for (const std::string &a : arguments)
        got += (got.empty() ? "'" : " '") + a + "'";
      std::cerr << "cdea " << command.name << ": wrong arguments (got " << got << "); usage:\n"
                << command_usage(command) << "('cdea --help' lists every command)\n";
      return exit_input_error;
    }

    /// A serial job started by an MPI launcher on several ranks: each would
    /// write the same results.
    bool refused_on_several_ranks(const Command &command)
    {
      if (command.ranks != Ranks::one || mpi::size() == 1)
        return false;
      if (mpi::rank() == 0)
        std::cerr << "cdea: '" << command.name << "' is a serial job, but an MPI launcher "
                  << "started " << mpi::size() << " processes of it (each would "
                  << "write the same results): run it without mpirun or with -np 1; "
                  << "'cdea sweep', 'cdea frequency-sweep' and 'cdea optimize' use several "
                  << "processes\n";
      return true;
    }

    /// The parameter file read with its overrides and validated, then the
    /// command's own checks; false (the message printed) on bad input.
    bool read_input(CommandJob &job, Invocation &invocation)
    {
      try
        {
          if (invocation.command.has(reads_parameters))
            {
              invocation.input.is_text = false;
              invocation.input.source  = invocation.arguments.at(0);
              invocation.parameters =
                read_parameters(invocation.input, &invocation.parameter_text);
              require_uncertainty_support(invocation.parameters, invocation.command.name);
            }
          job.check(invocation);
          return true;
        }
      catch (const InputError &e)
        {
          if (invocation.root)
            std::cerr << "cdea: " << e.what() << '\n';
          return false;
        }
    }

    void print_warnings(const Invocation &invocation)
    {
      if (invocation.root)
        for (const std::string &warning : invocation.parameters.input_warnings)
          std::cerr << "cdea: warning: " << warning << '\n';
    }

    /// The output folder must be writable and the file ours alone before the
    /// work starts; rank 0 claims it, the others follow its verdict.
    bool claim(const CommandJob &job, Invocation &invocation)
    {
      int writable = 1;
      if (invocation.root)
        {
          ClaimedOutput &out = invocation.output;
          out.path           = job.output_path(invocation);
          std::string why;
          if (!claim_output(out.path, out.lock, why, &out.created))
            {
              std::cerr << "cdea: cannot write '" << out.path << "': " << why << '\n';
              writable = 0;
            }
        }
      if (invocation.command.ranks == Ranks::all)
        mpi::broadcast(writable);
      return writable != 0;
    }

    /// The common sequence of every command (command.h).
    int run_command(Invocation &invocation)
    {
      const Command &command = invocation.command;
      if (refused_on_several_ranks(command))
        return exit_input_error;
      if (command.ranks == Ranks::first_only && !invocation.root)
        return exit_success;
      const std::unique_ptr<CommandJob> job = command.make_job();
      if (!read_input(*job, invocation))
        return exit_input_error;
      print_warnings(invocation);
      // A stop request ends the work at its next step, row, evaluation or
      // iteration, with the results so far written (exit code 2). The
      // handlers come before the claim, so that no signal finds a lock
      // without its owner ready to remove it, and stay until the process
      // ends: a signal after the work (MPI's and deal.II's clean-up) is moot.
      static std::optional<StopOnSignals> stop_on_signals;
      if (command.has(stops_on_signals))
        stop_on_signals.emplace();
      if (command.output == Output::claimed_first && !claim(*job, invocation))
        return exit_input_error;
      if (const int signal = StopOnSignals::requested();
          signal != 0 && stop_on_signals && command.ranks != Ranks::all)
        {
          invocation.output.give_up();
          if (invocation.root)
            std::cerr << "cdea: interrupted by " << signal_name(signal)
                      << " before the work began; nothing was written\n";
          return exit_not_complete;
        }
      return job->run(invocation);
    }
  } // namespace

  int run_command_line(const std::vector<std::string> &words)
  {
    ignore_output_signals();
    try
      {
        if (words.empty())
          {
            if (mpi::rank() == 0)
              std::cerr << usage_text();
            return exit_input_error;
          }
        const Command *command = find_command(words[0]);
        if (!command)
          return unknown_command(words[0]);
        Invocation invocation{*command, {}, mpi::rank() == 0, {}, {}, {}, {}};
        try
          {
            split_words(words, invocation);
          }
        catch (const InputError &e)
          {
            if (invocation.root)
              std::cerr << "cdea: " << e.what() << '\n';
            return exit_input_error;
          }
        if (asks_for_help(invocation.arguments) && command->name != "--help")
          {
            if (invocation.root)
              std::cout << command_usage(*command);
            return exit_success;
          }
        if (!fits_a_form(*command, invocation.arguments))
          return wrong_arguments(*command, invocation.arguments);
        return run_command(invocation);
      }
    catch (const std::exception &e)
      {
        std::cerr << "cdea: error: " << one_line_message(e) << '\n';
        return exit_input_error;
      }
  }
} // namespace cdea
