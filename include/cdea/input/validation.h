#pragma once
// Range checks of every numeric input at parse time, checks of the output
// names, duplicate entries, and messages kept short. The allowed ranges are
// listed in doc/usage.md ("Allowed ranges").

#include <string>
#include <vector>

namespace cdea
{
  struct Parameters;
  struct Scene;

  /// The voltage ceiling: no ring voltage may make the field in the flat
  /// pre-stretched film, V lam_pre^2 / H, exceed this (V/m).
  constexpr double max_flat_field = 1e10;

  /// The largest voltage (V) of @p scene's film: max_flat_field H / lam_pre^2.
  double voltage_ceiling(const Scene &scene);

  /// Throws InputError naming the first parameter outside its allowed range
  /// (finite, physically sensible, and a run of bounded size: steps, mesh,
  /// results held in memory), or an output name the file system cannot take.
  /// @p scene is p.scene().
  void validate_ranges(const Parameters &p, const Scene &scene);

  /// Warnings about entries set more than once in the parameter file text
  /// @p prm_text (the last value is used), one per repetition.
  std::vector<std::string> duplicate_entry_warnings(const std::string &prm_text,
                                                    const std::string &filename);

} // namespace cdea
