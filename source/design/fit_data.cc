// The CSV files of `cdea fit`: their kind by the header, and the DMA and
// creep readers (the displacement-voltage points are read in fit_model.cc).

#include <cdea/base/file_reading.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/base/units.h>
#include <cdea/design/fit_data.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace cdea
{
  namespace
  {
    constexpr std::size_t max_file_bytes = std::size_t(64) << 20;

    /// "FILE, line N, column NAME".
    std::string place(const std::string &file, const unsigned int line, const std::string &name)
    {
      return file + ", line " + std::to_string(line) + ", column " + name;
    }
  } // namespace

  std::string read_data_file(const std::string &file)
  {
    // Only a CSV: its lines are quoted in messages.
    const FileRead read = has_extension(file, ".csv") ?
                            read_regular_file(file, max_file_bytes) :
                            FileRead{false, "", "the data must be a CSV file whose name ends "
                                                "in .csv"};
    if (!read.ok)
      throw InputError("cannot read data file '" + file + "': " + read.error);
    return read.bytes;
  }

  std::vector<std::string> csv_fields(const std::string &line)
  {
    std::vector<std::string> fields;
    for (const std::string &field : split_list(line, ','))
      {
        std::size_t b = 0, e = field.size();
        while (b < e && std::isspace(static_cast<unsigned char>(field[b])))
          ++b;
        while (e > b && std::isspace(static_cast<unsigned char>(field[e - 1])))
          --e;
        fields.push_back(field.substr(b, e - b));
      }
    if (!line.empty() && line.back() == ',')
      fields.emplace_back();
    return fields;
  }

  std::string csv_content(std::string line, const unsigned int number)
  {
    if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
      line.erase(0, 3);
    if (const auto hash = line.find('#'); hash != std::string::npos)
      line.erase(hash);
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    return line;
  }

  FitDataKind fit_data_kind(const std::string &file)
  {
    std::istringstream in(read_data_file(file));
    return fit_data_kind(in);
  }

  std::vector<std::string> csv_header(std::istream &in)
  {
    std::string line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        line = csv_content(line, number);
        if (line.find_first_not_of(" \t") != std::string::npos)
          return csv_fields(line);
      }
    return {};
  }

  FitDataKind fit_data_kind(std::istream &in)
  {
    const auto fields = csv_header(in);
    const auto has    = [&](const std::string &name) {
      return std::find(fields.begin(), fields.end(), name) != fields.end();
    };
    return has("frequency_Hz") ? FitDataKind::dma :
           has("time_s")       ? FitDataKind::creep :
                                 FitDataKind::displacement_voltage;
  }

  int CsvTable::column(const std::string &name) const
  {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : int(it - names.begin());
  }

  CsvTable read_csv_table(std::istream &in, const std::string &file,
                          const std::function<bool(const std::string &)> &known,
                          const std::string &expected, const std::vector<std::string> &required,
                          const std::size_t max_rows)
  {
    CsvTable    table;
    std::string line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        line = csv_content(line, number);
        if (line.find_first_not_of(" \t") == std::string::npos)
          continue;
        const auto        fields = csv_fields(line);
        const std::string where  = file + ", line " + std::to_string(number);
        if (table.names.empty())
          {
            for (std::size_t k = 0; k < fields.size(); ++k)
              {
                if (!known(fields[k]))
                  throw InputError(where + ": unknown column '" + printable(fields[k]) +
                                   "' (expected " + expected + ")");
                if (const int before = table.column(fields[k]); before >= 0)
                  throw InputError(where + ": column '" + fields[k] + "' appears twice (columns " +
                                   std::to_string(before + 1) + " and " +
                                   std::to_string(k + 1) + ")");
                table.names.push_back(fields[k]);
              }
            table.header_line = number;
            for (const std::string &name : required)
              if (table.column(name) < 0)
                throw InputError(where + ": no column " + name + " (expected " + expected + ")");
            continue;
          }
        if (fields.size() != table.names.size())
          throw InputError(where + ": " + std::to_string(fields.size()) +
                           " fields, but the header has " + std::to_string(table.names.size()));
        if (table.rows.size() == max_rows)
          throw InputError(where + ": more than " + std::to_string(max_rows) + " rows");
        std::vector<double> row;
        for (std::size_t k = 0; k < fields.size(); ++k)
          row.push_back(parse_number(fields[k], where + ", column " + table.names[k], line));
        table.rows.push_back(row);
        table.lines.push_back(number);
      }
    if (table.names.empty())
      throw InputError(file + ": no header line (the column names " + expected + ")");
    if (table.rows.empty())
      throw InputError(file + ": no data rows after the header");
    return table;
  }

  namespace
  {
    /// The value of column @p name in row @p i of @p t (@p fallback if the
    /// column is absent), with the test @p ok that must hold.
    double checked(const CsvTable &t, const std::size_t i, const std::string &file,
                   const std::string &name, const std::function<bool(double)> &ok,
                   const std::string &rule, const double fallback = 1.)
    {
      const int k = t.column(name);
      if (k < 0)
        return fallback;
      const double v = t.rows[i][std::size_t(k)];
      if (!ok(v))
        throw InputError(place(file, t.lines[i], name) + ": " + rule + ", got " +
                         format_number(v));
      return v;
    }

    const auto positive     = [](const double v) { return v > 0.; };
    const auto not_negative = [](const double v) { return v >= 0.; };
  } // namespace

  DmaData read_dma_data(const std::string &file)
  {
    std::istringstream in(read_data_file(file));
    return read_dma_data(in, file);
  }

  DmaData read_dma_data(std::istream &in, const std::string &file)
  {
    const std::vector<std::string> names = {"frequency_Hz", "storage_kPa", "loss_kPa", "weight"};
    const CsvTable                 t     = read_csv_table(
      in, file,
      [&](const std::string &n) { return std::find(names.begin(), names.end(), n) != names.end(); },
      "frequency_Hz, storage_kPa, loss_kPa and optionally weight", {names[0], names[1], names[2]});
    DmaData d;
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      {
        d.frequency.push_back(
          checked(t, i, file, "frequency_Hz", positive, "a frequency must be positive"));
        d.storage.push_back(units::kPa.in_si(
          checked(t, i, file, "storage_kPa", positive, "a storage modulus must be positive")));
        d.loss.push_back(units::kPa.in_si(
          checked(t, i, file, "loss_kPa", not_negative, "a loss modulus must not be negative")));
        d.weight.push_back(checked(t, i, file, "weight", positive, "weights must be positive"));
      }
    return d;
  }

  CreepData read_creep_data(const std::string &file, const unsigned int n_rings,
                            const double voltage_ceiling)
  {
    std::istringstream in(read_data_file(file));
    return read_creep_data(in, file, n_rings, voltage_ceiling);
  }

  CreepData read_creep_data(std::istream &in, const std::string &file, const unsigned int n_rings,
                            const double ceiling)
  {
    std::vector<std::string> names = {"time_s", "displacement_mm", "weight"};
    for (unsigned int r = 1; r <= n_rings; ++r)
      names.push_back("V" + std::to_string(r) + "_kV");
    std::vector<std::string> required = names;
    required.erase(required.begin() + 2);
    const CsvTable t = read_csv_table(
      in, file,
      [&](const std::string &n) { return std::find(names.begin(), names.end(), n) != names.end(); },
      "time_s, V1_kV .. V" + std::to_string(n_rings) +
        "_kV (one per ring of Electrodes/Ring edges (r/a)), displacement_mm and optionally weight",
      required);
    CreepData d;
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      {
        const double last = d.times.empty() ? -1. : d.times.back();
        d.times.push_back(checked(t, i, file, "time_s", [&](double v) { return v >= 0. && v > last; },
                                  "times must be >= 0 and increase strictly"));
        std::vector<double> volts;
        for (unsigned int r = 1; r <= n_rings; ++r)
          volts.push_back(units::kV.in_si(checked(
            t, i, file, "V" + std::to_string(r) + "_kV",
            [&](double v) { return v >= 0. && units::kV.in_si(v) <= ceiling; },
            "a voltage must be from 0 to the film's ceiling of " +
              format_number(units::kV.from_si(ceiling)) + " kV")));
        d.voltages.push_back(volts);
        d.displacement.push_back(units::mm.in_si(
          checked(t, i, file, "displacement_mm", not_negative,
                  "a displacement is the distance |z(A) - z(B)| and must not be negative")));
        d.weight.push_back(checked(t, i, file, "weight", positive, "weights must be positive"));
      }
    return d;
  }
} // namespace cdea
