#include <cdea/base/file_reading.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/input/voltage_table.h>
#include <cdea/base/units.h>

#include <filesystem>
#include <sstream>

namespace cdea
{
  namespace
  {
    const std::string entry = "Time/Table file";

    /// The table file as messages name it: a relative path with the path it
    /// resolves to from the working directory.
    std::string describe_file(const std::string &file)
    {
      const std::filesystem::path path(file);
      std::error_code             error;
      const auto                  resolved = std::filesystem::absolute(path, error);
      if (path.is_absolute() || error)
        return "'" + file + "'";
      return "'" + file + "' (relative to the working directory: " + resolved.string() + ")";
    }

    /// As the fit's CSV files: a table is no larger than this.
    constexpr std::size_t max_table_bytes = std::size_t(64) << 20;

    /// The bytes of the table @p file: a regular file named *.csv (so that
    /// a message quoting a line quotes a CSV, never another file), read
    /// bounded.
    std::string read_table(const std::string &file)
    {
      if (file.empty())
        throw InputError(entry + " must be given for Time/Waveform = table");
      if (!has_extension(file, ".csv"))
        throw InputError(entry + " " + describe_file(file) +
                         ": the table must be a CSV file whose name ends in .csv");
      const FileRead read = read_regular_file(file, max_table_bytes);
      if (!read.ok)
        throw InputError(entry + ": cannot read " + describe_file(file) +
                         (read.error == "it does not exist" ? std::string() : ": " + read.error));
      return read.bytes;
    }

    /// One row of numbers (@p line, trailing blanks removed) appended to
    /// @p table; @p where names the file and line in messages.
    void add_row(const std::string &line, const std::string &where, const unsigned int n_rings,
                 const double ceiling, VoltageTable &table)
    {
      const std::vector<double> row = parse_number_list(line, where);
      if (row.size() != n_rings + 1)
        throw InputError(where + ": expected time and " + std::to_string(n_rings) +
                         " voltage(s), got " + std::to_string(row.size()) + " value(s)");
      if (row[0] < 0. || (!table.times.empty() && !(row[0] > table.times.back())))
        throw InputError(where + ": times must be >= 0 and increase strictly, got " +
                         format_number(row[0]));
      std::vector<double> v(row.begin() + 1, row.end());
      for (double &x : v)
        {
          if (x < 0.)
            throw InputError(where + ": voltages must not be negative, got " + format_number(x));
          if (!(x <= units::kV.from_si(ceiling)))
            throw InputError(where + ": " + format_number(x) + " kV is above the voltage "
                             "ceiling of " + format_number(units::kV.from_si(ceiling)) + " kV for this "
                             "film (as for Electrodes/Voltage path (kV))");
          x *= 1e3;
        }
      table.times.push_back(row[0]);
      table.volts.push_back(v);
    }
  } // namespace

  VoltageTable read_voltage_table(const std::string &file, const unsigned int n_rings,
                                  const double ceiling)
  {
    std::istringstream in(read_table(file));
    VoltageTable       table;
    std::string   line;
    unsigned int  number         = 0;
    bool          header_allowed = true; // the first non-comment line may be a header
    while (std::getline(in, line))
      {
        ++number;
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#')
          continue;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
          line.pop_back();
        // A header starts with a name; a row that starts like a number and
        // does not parse is a mistake in the data, not a header.
        const bool header = std::string("0123456789+-.").find(line[first]) == std::string::npos;
        if (header && header_allowed)
          {
            header_allowed = false;
            continue;
          }
        header_allowed = false;
        add_row(line, entry + " '" + file + "', line " + std::to_string(number), n_rings,
                ceiling, table);
      }
    if (table.times.empty())
      throw InputError(entry + " " + describe_file(file) + " has no rows of numbers");
    return table;
  }
} // namespace cdea
