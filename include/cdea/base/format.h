#pragma once
// The project's one formatting of voltages and numbers for messages and tables.

#include <string>
#include <vector>

namespace cdea
{
  /// "5, 6.5 kV" from volts, @p digits significant digits.
  std::string format_kV(const std::vector<double> &volts, int digits = 6);
  /// "6.5 kV" from volts.
  std::string format_kV(double volts, int digits = 6);
  /// A number with @p digits significant digits ("%g" style).
  std::string format_number(double value, int digits = 6);
  /// A number with @p decimals digits after the point, right-aligned in @p width.
  std::string format_fixed(double value, int decimals, int width = 0);
  /// A size in bytes as "25 kB", "11.7 MB", "1.2 GB" (3 significant digits).
  std::string format_bytes(double bytes);
  /// A number with 17 significant digits, read back as the same double (for
  /// parameter files written by cdea).
  std::string exact_number(double value);

  // Tables of the design commands and the sweep.
  /// format_fixed, but "-" for NaN (a value that could not be computed).
  std::string format_fixed_or_dash(double value, int decimals);
  /// @p values times @p factor, each with @p decimals digits after the point,
  /// separated by spaces ("5.0000 6.3824").
  std::string format_fixed_list(const std::vector<double> &values, int decimals,
                                double factor = 1.);
  /// @p text if it has at most @p width characters, else its words that fit
  /// in @p width followed by " ..." (never cut inside a word).
  std::string shorten_at_word(const std::string &text, std::size_t width);
} // namespace cdea
