#pragma once
// The voltage table of Time/Waveform = table (Time/Table file): a CSV file of
// rows 'time_s, one voltage per ring (kV)', read and checked once for the
// validation of the input and once for the waveform of the run.

#include <string>
#include <vector>

namespace cdea
{
  /// The rows of a table file in SI units.
  struct VoltageTable
  {
    std::vector<double>              times; ///< s, from >= 0, strictly increasing
    std::vector<std::vector<double>> volts; ///< V, one per ring in each row
  };

  /// Reads @p file for @p n_rings rings, every voltage at most @p ceiling
  /// (V; the film's, as for the voltage path). '#' lines and a first line
  /// that starts with a name (a header) are skipped. Throws InputError
  /// naming Time/Table file, the file and the line.
  VoltageTable read_voltage_table(const std::string &file, unsigned int n_rings, double ceiling);
} // namespace cdea
