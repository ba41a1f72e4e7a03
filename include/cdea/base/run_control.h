#pragma once
// How a run reacts to signals, how a command ends (its exit code), and errors
// turned into one line for the user.

#include <exception>
#include <stdexcept>
#include <string>

namespace cdea
{
  /// Exit codes of every command: 0 success, 1 bad input or unwritable output
  /// (nothing is written), 2 the work stopped before its end or could not
  /// write all of its results (signal, full disk, vanished directory; the
  /// messages say where the results so far are).
  enum ExitCode : int
  {
    exit_success      = 0,
    exit_input_error  = 1,
    exit_not_complete = 2
  };

  /// For the lifetime of the object SIGINT, SIGTERM and SIGHUP only ask the
  /// run to stop: it stops after its current step and finishes its results
  /// file. A second such signal ends the process at once, as without the
  /// object (the journal keeps the steps; doc/usage.md). A signal that was
  /// ignored when the object was made (nohup) stays ignored.
  class StopOnSignals
  {
  public:
    StopOnSignals();
    ~StopOnSignals();
    StopOnSignals(const StopOnSignals &)            = delete;
    StopOnSignals &operator=(const StopOnSignals &) = delete;

    /// The signal that asked to stop, or 0.
    static int requested();
  };

  /// Thrown at a step boundary after a stop was requested.
  class RunInterrupted : public std::runtime_error
  {
  public:
    explicit RunInterrupted(int signal);
    int signal;
  };

  /// "SIGINT", "SIGTERM", ...
  std::string signal_name(int signal);

  /// SIGPIPE and SIGXFSZ ignored for the whole process: output to a closed
  /// pipe (`cdea run ... | head`) fails quietly and the run goes on writing
  /// its file; a write past the file size limit fails with EFBIG, which the
  /// results file handles, instead of killing the process.
  void ignore_output_signals();

  /// A standard stream closed when the process started (`cdea run x >&-`)
  /// is opened onto /dev/full (stdin onto /dev/null), so that no file the
  /// command opens takes its number and receives its text, and a write to it
  /// fails as to a full disk. Call before anything is opened.
  void reopen_closed_standard_streams();

  /// The exit code after a command returned @p code: standard output and
  /// error flushed, and if a write to either failed (a full disk, a closed
  /// pipe, a closed stream) a message (on stderr if it works) and
  /// exit_not_complete instead of exit_success.
  int exit_code_after_output(int code);

  /// @p text on one line: every run of blanks, tabs and newlines becomes
  /// one blank (deal.II's messages span several indented lines).
  std::string fold_whitespace(const std::string &text);

  /// The message of @p e on one line, without deal.II's stack trace and
  /// source location.
  std::string one_line_message(const std::exception &e);
} // namespace cdea
