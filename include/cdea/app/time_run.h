#pragma once
// `cdea run FILE.prm` with Time/Enabled = true: the FE model through the
// quasi-static pre-stretch and weight, then in time through the voltage
// waveform (doc/time.md). Returns the process exit code (commands.h).

#include <string>

namespace cdea
{
  struct Parameters;
  struct Scene;

  int run_time(const Parameters &p, const Scene &scene, const std::string &prm_text);
} // namespace cdea
