#pragma once
// The command front of the cdea program, as git.c has it: one table of
// commands (command_table.cc), one sequence that runs every command by the
// flags of its row (run_command(), front.cc), and one file per command
// (commands/<name>.cc) that holds only what is its own: its input checks, the
// path it writes, and its work with its report. The sequence: arguments
// matched against the row's forms (--set overrides taken out), the MPI ranks
// the command may run on, the parameter file read with its overrides and
// validated, the command's own checks, the warnings printed, the output
// claimed, SIGINT/SIGTERM/SIGHUP turned into a stop request, the work, and
// its exit code (ExitCode, base/run_control.h). doc/architecture.md, "How to
// add a command".

#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/output/safe_files.h>

#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  struct Command;

  /// The output a command claims before its work (Output::claimed_first):
  /// the path, its lock and the directories the claim created.
  struct ClaimedOutput
  {
    std::string              path;
    OutputLock               lock;
    std::vector<std::string> created;

    /// Nothing is written after all: the lock goes, and with it the
    /// directories the claim made (if they are still empty).
    void give_up();
  };

  /// One command line on its way through the front.
  struct Invocation
  {
    const Command           &command;
    std::vector<std::string> arguments; ///< after the command's name, without --set
    bool                     root = true; ///< MPI rank 0: the rank that prints and writes
    /// Command::reads_parameters: arguments[0] with the --set overrides,
    /// read and validated by the front, and every parameter as text.
    ParameterInput input;
    Parameters     parameters;
    std::string    parameter_text;
    ClaimedOutput  output; ///< Output::claimed_first, on rank 0
  };

  /// What a command does once the front has read its input: one class per
  /// command file, made by the factory of its row.
  class CommandJob
  {
  public:
    virtual ~CommandJob() = default;
    /// The command's checks beyond those of the parameters (its study's
    /// settings, its data file): throws InputError with the line to print.
    /// Runs on every rank; nothing is written yet.
    virtual void check(Invocation &) {}
    /// Output::claimed_first: the file the front claims before the work.
    virtual std::string output_path(const Invocation &) const { return {}; }
    /// The work and its report; returns the exit code (ExitCode).
    virtual int run(Invocation &invocation) = 0;
  };

  /// Where a command runs under an MPI launcher.
  enum class Ranks
  {
    one,       ///< a serial job: refused when the launcher started several ranks
    all,       ///< collective: every rank works, rank 0 prints and writes
    first_only ///< rank 0 alone acts, the others end at once (help, version)
  };

  /// What a command writes, and who claims it (doc/usage.md, "What survives what").
  enum class Output
  {
    none,          ///< prints only
    claimed_first, ///< files claimed by the front before the work (CommandJob::output_path())
    claimed_by_run ///< a results file claimed when the run starts (RunOutput), or
                   ///< a recovered file beside a journal (recover holds its lock)
  };

  /// The flags of a row.
  enum CommandFlag : unsigned int
  {
    reads_parameters = 1u << 0, ///< first argument FILE.prm; takes --set overrides
    stops_on_signals = 1u << 1, ///< SIGINT, SIGTERM, SIGHUP end it cleanly with exit 2
    time_runs        = 1u << 2, ///< supports Time/Enabled = true
    in_python        = 1u << 3  ///< also cdea.<name>() in the Python module (doc/python.md)
  };

  /// A row of the command table.
  struct Command
  {
    std::string name; ///< as typed: "run", "--version"
    /// Each accepted argument list, as --help shows it: placeholders in
    /// capitals (any value), options (from '-') as typed, "..." anything.
    std::vector<std::string> forms;
    /// What --help says, one entry per form.
    std::vector<std::string> help;
    unsigned int             flags;
    Ranks                    ranks;
    Output                   output;
    std::unique_ptr<CommandJob> (*make_job)();
    std::vector<std::string> aliases = {}; ///< other names ("-h", "help")

    bool has(const CommandFlag flag) const { return (flags & flag) != 0; }
  };

  /// Every command, in the order of --help.
  const std::vector<Command> &command_table();

  /// The row named @p name (or by an alias), or nullptr.
  const Command *find_command(const std::string &name);

  /// The text of `cdea --help`, made from the table.
  std::string usage_text();

  /// The lines of `cdea --help` about @p command (`cdea run --help`).
  std::string command_usage(const Command &command);

  /// The whole command line after the program's name: the command, its
  /// arguments and --set overrides. Returns the exit code.
  int run_command_line(const std::vector<std::string> &words);
} // namespace cdea
