#pragma once
// Entries set more than once in a parameter file: deal.II takes the last
// value silently, so the reader warns about every repetition.

#include <string>
#include <vector>

namespace cdea
{
  /// Warnings about entries set more than once in the parameter file text
  /// @p prm_text named @p filename (the last value is used), one per
  /// repetition: "<file> line 24: Loading/Mass (g) is set again (first on
  /// line 23); the last value is used".
  std::vector<std::string> duplicate_entry_warnings(const std::string &prm_text,
                                                    const std::string &filename);
} // namespace cdea
