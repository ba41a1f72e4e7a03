#include <deal.II/base/exceptions.h>

#include <cdea/base/run_control.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

namespace cdea
{
  namespace
  {
    volatile std::sig_atomic_t stop_signal = 0;

    const int stop_signals[] = {SIGINT, SIGTERM, SIGHUP};

    extern "C" void ask_to_stop(const int signal)
    {
      if (stop_signal != 0)
        {
          // The second request: no more waiting for the step to end.
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      stop_signal = signal;
    }

    struct sigaction previous[3];
  } // namespace

  StopOnSignals::StopOnSignals()
  {
    stop_signal = 0;
    for (int i = 0; i < 3; ++i)
      {
        // A signal ignored from the start stays ignored (nohup, background
        // jobs of a shell).
        sigaction(stop_signals[i], nullptr, &previous[i]);
        if (previous[i].sa_handler == SIG_IGN)
          continue;
        struct sigaction action = {};
        action.sa_handler       = ask_to_stop;
        action.sa_flags         = SA_RESTART;
        sigemptyset(&action.sa_mask);
        sigaction(stop_signals[i], &action, nullptr);
      }
  }

  StopOnSignals::~StopOnSignals()
  {
    for (int i = 0; i < 3; ++i)
      sigaction(stop_signals[i], &previous[i], nullptr);
  }

  int StopOnSignals::requested() { return stop_signal; }

  RunInterrupted::RunInterrupted(const int signal)
    : std::runtime_error("interrupted by " + signal_name(signal))
    , signal(signal)
  {}

  std::string signal_name(const int signal)
  {
    switch (signal)
      {
        case SIGINT:
          return "SIGINT";
        case SIGTERM:
          return "SIGTERM";
        case SIGHUP:
          return "SIGHUP";
        default:
          return "signal " + std::to_string(signal);
      }
  }

  void ignore_output_signals()
  {
    std::signal(SIGPIPE, SIG_IGN);
    std::signal(SIGXFSZ, SIG_IGN);
  }

  namespace
  {
    bool stdout_was_closed = false;

    /// Opens @p device onto the closed descriptor @p fd.
    void fill(const int fd, const char *device, const int flags)
    {
      if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF)
        return;
      int opened = ::open(device, flags);
      if (opened < 0)
        opened = ::open("/dev/null", flags);
      if (opened >= 0 && opened != fd)
        {
          ::dup2(opened, fd);
          ::close(opened);
        }
      if (fd == STDOUT_FILENO)
        stdout_was_closed = true;
    }
  } // namespace

  void reopen_closed_standard_streams()
  {
    fill(STDIN_FILENO, "/dev/null", O_RDONLY);
    fill(STDOUT_FILENO, "/dev/full", O_WRONLY);
    fill(STDERR_FILENO, "/dev/full", O_WRONLY);
  }

  int exit_code_after_output(const int code)
  {
    std::cout.flush();
    errno                 = 0;
    const bool out_failed = std::fflush(stdout) != 0 || std::ferror(stdout) || std::cout.fail();
    const int  out_error  = errno;
    std::cerr.flush();
    const bool err_failed = std::fflush(stderr) != 0 || std::ferror(stderr) || std::cerr.fail();
    if (!out_failed && !err_failed)
      return code;
    if (out_failed && !err_failed)
      {
        // The error of the failed write itself is gone: say what it must
        // have been from what stdout is.
        struct stat st = {};
        const bool  pipe = ::fstat(STDOUT_FILENO, &st) == 0 && S_ISFIFO(st.st_mode);
        std::cerr << "cdea: cannot write to standard output: "
                  << (stdout_was_closed ? std::string("it was closed") :
                      out_error != 0    ? std::string(std::strerror(out_error)) :
                      pipe              ? std::string("the pipe was closed by its reader") :
                                          std::string("the disk or device is full"))
                  << " (what the command printed is incomplete)" << std::endl;
      }
    return code == exit_success ? exit_not_complete : code;
  }

  std::string fold_whitespace(const std::string &text)
  {
    std::string out;
    for (const char c : text)
      if (c == '\n' || c == '\t' || c == ' ')
        {
          if (!out.empty() && out.back() != ' ')
            out += ' ';
        }
      else
        out += c;
    while (!out.empty() && out.back() == ' ')
      out.pop_back();
    return out;
  }

  std::string one_line_message(const std::exception &e)
  {
    std::string text;
    if (const auto *deal = dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        // The exception's own information, without the banner, location
        // and stack trace of what().
        std::ostringstream info;
        deal->print_info(info);
        text = info.str();
        if (text.find_first_not_of(" \t\n") == std::string::npos)
          text = deal->get_exc_name();
      }
    else
      text = e.what();
    std::string out = fold_whitespace(text);
    constexpr std::size_t longest = 500;
    if (out.size() > longest)
      out = out.substr(0, longest) + "... (" + std::to_string(out.size()) + " characters)";
    return out;
  }
} // namespace cdea
