#pragma once
// Progress of a long computation (a design map, an optimization, a time run):
// items done, total and time left, as a live bar on a terminal, as plain lines
// every CDEA_PROGRESS_SECONDS (default 5) otherwise and under an MPI launcher
// (OpenMPI gives each rank a pseudo-terminal of its own, which the launcher
// copies into one stream, often a file). CDEA_PROGRESS = lines | bar | off
// forces a mode.

#include <chrono>
#include <cstddef>
#include <string>

namespace cdea
{
  /// "8.2 s", "3 min 05 s", "2 h 10 min" ("?" if not finite).
  std::string format_duration(double seconds);

  class Progress
  {
  public:
    /// @p unit names the items ("points").
    Progress(std::size_t total, bool enabled, std::string unit = "points");
    /// @p count more items are done.
    void add(std::size_t count);
    /// Show the final state (and end the bar's line).
    void finish();

  private:
    std::size_t total, done = 0, shown = 0;
    bool        enabled, terminal;
    std::string unit;
    double      interval = 5.;
    std::chrono::steady_clock::time_point start, last;

    void show(std::chrono::steady_clock::time_point now);
  };
} // namespace cdea
