#include <deal.II/base/exceptions.h>

#include <cdea/base/run_control.h>

#include <csignal>
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
