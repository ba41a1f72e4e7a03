#pragma once
// `cdea sweep FILE.prm`: design maps over two-ring layouts (see doc/design-maps.md).

#include <string>

namespace cdea
{
  /// Returns the process exit code (see ExitCode in commands.h).
  int run_sweep(const std::string &prm_file);
} // namespace cdea
