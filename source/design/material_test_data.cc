// Material-test data files (material_test_data.h): the kind from the
// header, the raw machine columns through the specimen, the checks of every
// value; the CSV reading is design/fit_data's.

#include <cdea/base/format.h>
#include <cdea/base/parameter_declarations.h>
#include <cdea/base/text.h>
#include <cdea/base/units.h>
#include <cdea/design/fit_data.h>
#include <cdea/design/material_test_data.h>
#include <cdea/input/parameters.h>
#include <cdea/input/specimen_entries.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// Machine histories are long (a 30 min hold at 50 Hz is 9e4 rows).
    constexpr std::size_t max_test_rows = 100000;

    /// The columns of each kind, and the columns every kind may have.
    const std::vector<std::string> stretch_columns{"uniaxial_stretch", "equibiaxial_stretch",
                                                   "pure_shear_stretch"};
    const std::vector<std::string> raw_columns{"displacement_mm", "force_N"};
    const std::string              stress_column = "nominal_stress_kPa";

    bool listed(const std::vector<std::string> &list, const std::string &name)
    {
      return std::find(list.begin(), list.end(), name) != list.end();
    }

    bool known_column(const std::string &name)
    {
      return name == "time_s" || name == "weight" || name == stress_column ||
             listed(stretch_columns, name) || listed(raw_columns, name);
    }

    const std::string expected =
      "time_s and one of uniaxial_stretch, equibiaxial_stretch, pure_shear_stretch with "
      "nominal_stress_kPa, or displacement_mm with force_N; optionally weight";

    /// "time_s, uniaxial_stretch, nominal_stress_kPa (a uniaxial test)".
    std::string kind_columns(const std::string &stretch)
    {
      if (stretch.empty())
        return "time_s, displacement_mm, force_N (a machine's raw columns)";
      const std::size_t k = std::size_t(
        std::find(stretch_columns.begin(), stretch_columns.end(), stretch) - stretch_columns.begin());
      return "time_s, " + stretch + ", " + stress_column + " (a " + test_kind_name(TestKind(k)) +
             " test)";
    }

    /// The kind's stretch column (empty: raw columns) from the header; an
    /// InputError naming the column that mixes kinds or is missing.
    std::string header_kind(const CsvTable &t, const std::string &file)
    {
      const auto at = [&](const std::string &column) {
        return file + ", line " + std::to_string(t.header_line) + ", column " + column;
      };
      std::string stretch;
      for (const std::string &name : t.names)
        if (listed(stretch_columns, name))
          {
            if (!stretch.empty())
              throw InputError(at(name) + ": a second test's stretch column beside " + stretch +
                               ": one file holds one test (" + kind_columns(stretch) + ")");
            stretch = name;
          }
      for (const std::string &name : t.names)
        {
          if (!stretch.empty() && listed(raw_columns, name))
            throw InputError(at(name) + ": a column of " + kind_columns("") +
                             " mixed with the columns of " + kind_columns(stretch));
          if (stretch.empty() && name == stress_column && t.column("force_N") >= 0)
            throw InputError(at(name) + ": a column of the stretch tests (time_s, "
                             "uniaxial_stretch, equibiaxial_stretch or pure_shear_stretch, "
                             "nominal_stress_kPa) mixed with the columns of " + kind_columns(""));
        }
      const std::vector<std::string> needed =
        stretch.empty() ? std::vector<std::string>{"displacement_mm", "force_N"} :
                          std::vector<std::string>{stress_column};
      if (stretch.empty() && t.column("displacement_mm") < 0 && t.column("force_N") < 0)
        throw InputError(file + ", line " + std::to_string(t.header_line) +
                         ": no stretch column (expected " + expected + ")");
      for (const std::string &name : needed)
        if (t.column(name) < 0)
          throw InputError(file + ", line " + std::to_string(t.header_line) + ": no column " +
                           name + " (expected " + kind_columns(stretch) + ")");
      return stretch;
    }

    /// Column @p name of row @p i, with the test @p ok that must hold.
    double value(const CsvTable &t, const std::size_t i, const std::string &file,
                 const std::string &name, const std::function<bool(double)> &ok,
                 const std::string &rule)
    {
      const double v = t.rows[i][std::size_t(t.column(name))];
      if (!ok(v))
        throw InputError(file + ", line " + std::to_string(t.lines[i]) + ", column " + name +
                         ": " + rule + ", got " + format_number(v));
      return v;
    }

    /// The specimen checked for raw columns of file @p file.
    void require_specimen(const TestSpecimen &s, const std::string &file)
    {
      if (!(s.gauge_length > 0.) || !(s.width > 0.) || !(s.thickness > 0.))
        throw InputError(file + ": raw machine columns (time_s, displacement_mm, force_N) need "
                         "the specimen: its test, gauge length, width and thickness (all "
                         "above 0; Calibration/Specimen entries)");
    }
  } // namespace

  bool is_material_test(std::istream &in)
  {
    const auto fields = csv_header(in);
    return std::any_of(fields.begin(), fields.end(), [](const std::string &name) {
      return listed(stretch_columns, name) || name == "force_N";
    });
  }

  bool is_material_test(const std::string &file)
  {
    std::istringstream in(read_data_file(file));
    return is_material_test(in);
  }

  double material_test_weight(std::istream &in, const std::string &file)
  {
    double       weight = 1.;
    unsigned int given  = 0; // the line of the weight
    std::string  line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        if (csv_content(line, number).find_first_not_of(" \t") != std::string::npos)
          break; // the header line: the top of the file ends
        const std::size_t hash = line.find('#');
        if (hash == std::string::npos)
          continue;
        std::istringstream words(line.substr(hash + 1));
        std::string        key, rest;
        if (!(words >> key) || key != "weight")
          continue;
        const std::string where = file + ", line " + std::to_string(number) + ": '# weight'";
        if (given != 0)
          throw InputError(where + " given twice (also on line " + std::to_string(given) + ")");
        given = number;
        std::getline(words, rest);
        rest = trim_blanks(rest);
        if (!rest.empty() && rest.back() == '\r')
          rest = trim_blanks(rest.substr(0, rest.size() - 1));
        std::size_t used = 0;
        try
          {
            weight = std::stod(rest, &used);
          }
        catch (const std::exception &)
          {
            used = 0;
          }
        if (rest.empty() || used != rest.size() || !(weight > 0.) || !std::isfinite(weight))
          throw InputError(where + " must be followed by one number above 0 (the file's weight "
                                   "in a joint fit), got '" + rest + "'");
      }
    return weight;
  }

  double material_test_weight(const std::string &file)
  {
    std::istringstream in(read_data_file(file));
    return material_test_weight(in, file);
  }

  MaterialTestData read_material_test(const std::string &file, const TestSpecimen &specimen)
  {
    std::istringstream in(read_data_file(file));
    return read_material_test(in, file, specimen);
  }

  MaterialTestData read_material_test(std::istream &in, const std::string &file,
                                      const TestSpecimen &specimen)
  {
    const CsvTable    t       = read_csv_table(in, file, known_column, expected, {"time_s"},
                                               max_test_rows);
    const std::string stretch = header_kind(t, file);
    MaterialTestData  d;
    d.name = file;
    d.raw  = stretch.empty();
    if (d.raw)
      require_specimen(specimen, file);
    d.history.kind = d.raw ? specimen.kind :
                             TestKind(std::find(stretch_columns.begin(), stretch_columns.end(),
                                                stretch) - stretch_columns.begin());
    const bool has_weight = t.column("weight") >= 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      {
        const double last = d.history.time.empty() ? -1. : d.history.time.back();
        d.history.time.push_back(value(t, i, file, "time_s",
                                       [&](double v) { return v >= 0. && v > last; },
                                       "times must be >= 0 and increase strictly"));
        if (d.raw)
          {
            const double u = value(t, i, file, "displacement_mm", [](double v) { return v >= 0.; },
                                   "a tension test's displacement must be at least 0 (stretch "
                                   "at least 1)");
            d.history.stretch.push_back(1. + units::mm.in_si(u) / specimen.gauge_length);
            d.stress.push_back(value(t, i, file, "force_N", [](double) { return true; }, "") /
                               (specimen.width * specimen.thickness));
          }
        else
          {
            d.history.stretch.push_back(
              value(t, i, file, stretch, [](double v) { return v >= 1.; },
                    "a tension test's stretch must be at least 1 (the unstressed state)"));
            d.stress.push_back(units::kPa.in_si(
              value(t, i, file, stress_column, [](double) { return true; }, "")));
          }
        d.weight.push_back(has_weight ? value(t, i, file, "weight",
                                              [](double v) { return v > 0.; },
                                              "weights must be positive") :
                                        1.);
        d.lines.push_back(t.lines[i]);
      }
    return d;
  }

  void declare_specimen_parameters(ParameterDeclarations &prm)
  {
    SpecimenEntries::declare_entries(prm);
  }

  TestSpecimen test_specimen(const Parameters &p)
  {
    return parse_specimen(p.subsection<SpecimenEntries>().values);
  }

  TestSpecimen parse_specimen(const ParameterValues &values)
  {
    TestSpecimen      s;
    const std::string test = trim_blanks(values.text("Calibration/Specimen test"));
    if (test == "equibiaxial")
      s.kind = TestKind::equibiaxial;
    else if (test == "pure shear")
      s.kind = TestKind::pure_shear;
    else if (test != "uniaxial")
      throw InputError("Calibration/Specimen test must be uniaxial, equibiaxial or pure shear, "
                       "got '" + test + "'");
    const auto size = [&](const std::string &entry) {
      const double v = values.number("Calibration/" + entry);
      if (!(v >= 0. && v <= 1e4))
        throw InputError("Calibration/" + entry +
                         " must be from 0 (not given) to 1e4 mm, got " + format_number(v));
      return units::mm.in_si(v);
    };
    s.gauge_length = size("Specimen gauge length (mm)");
    s.width        = size("Specimen width (mm)");
    s.thickness    = size("Specimen thickness (mm)");
    return s;
  }
} // namespace cdea
