#include <cdea/base/mpi_session.h>
#include <cdea/base/progress.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace cdea
{
  std::string format_duration(const double seconds)
  {
    std::ostringstream o;
    if (!std::isfinite(seconds))
      o << "?";
    else if (seconds < 60.)
      o << std::fixed << std::setprecision(seconds < 10. ? 1 : 0) << seconds << " s";
    else if (seconds < 3600.)
      o << int(seconds / 60.) << " min " << std::setw(2) << std::setfill('0')
        << int(std::fmod(seconds, 60.)) << " s";
    else
      o << int(seconds / 3600.) << " h " << std::setw(2) << std::setfill('0')
        << int(std::fmod(seconds, 3600.) / 60.) << " min";
    return o.str();
  }

  Progress::Progress(const std::size_t total, const bool enabled, std::string unit)
    : total(total)
    , enabled(enabled)
    , terminal(isatty(fileno(stdout)) != 0 && !mpi::launched_by_mpirun())
    , unit(std::move(unit))
    , start(std::chrono::steady_clock::now())
    , last(start)
  {
    if (const char *env = std::getenv("CDEA_PROGRESS_SECONDS"))
      {
        char        *end = nullptr;
        const double v   = std::strtod(env, &end);
        if (end != env && v >= 0.)
          interval = v;
      }
    if (const char *env = std::getenv("CDEA_PROGRESS"))
      {
        const std::string mode = env;
        if (mode == "lines")
          terminal = false;
        else if (mode == "bar")
          terminal = true;
        else if (mode == "off")
          this->enabled = false;
      }
  }

  void Progress::add(const std::size_t count)
  {
    done += count;
    if (!enabled)
      return;
    const auto   now   = std::chrono::steady_clock::now();
    const double since = std::chrono::duration<double>(now - last).count();
    if (terminal ? since >= 0.1 : since >= interval)
      {
        show(now);
        last = now;
      }
  }

  void Progress::finish()
  {
    if (!enabled)
      return;
    show(std::chrono::steady_clock::now());
    if (terminal)
      std::cout << std::endl;
  }

  void Progress::show(const std::chrono::steady_clock::time_point now)
  {
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const double left    = done == 0 ? std::numeric_limits<double>::quiet_NaN() :
                                       elapsed * double(total - std::min(done, total)) /
                                         double(done);
    const double       fraction = total ? double(done) / double(total) : 1.;
    std::ostringstream line;
    line << done << '/' << total << ' ' << unit << " (" << int(100. * fraction) << " %), "
         << format_duration(elapsed) << " elapsed, " << format_duration(left) << " left";
    if (terminal)
      {
        const int   width = 30, filled = int(width * fraction);
        std::string bar   = "  [" + std::string(filled, '#') + std::string(width - filled, '.') +
                          "] " + line.str();
        // Blank what a longer previous bar left behind.
        const std::size_t length = bar.size();
        if (bar.size() < shown)
          bar += std::string(shown - bar.size(), ' ');
        shown = length;
        std::cout << '\r' << bar << std::flush;
      }
    else
      std::cout << "  progress: " << line.str() << std::endl;
  }
} // namespace cdea
