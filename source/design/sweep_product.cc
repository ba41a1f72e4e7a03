// The map file of `cdea sweep`, <Directory>/<Base name>_map.h5, written with
// the plain HDF5 C API by rank 0 after the rows have been gathered. The file
// holds no run-dependent data (no times, no rank count, no object time
// stamps), so a serial and a distributed run of the same map give the same file.

#include <cdea/analysis/run_record.h>
#include <cdea/base/format.h>
#include <cdea/design/sweep.h>
#include <cdea/output/hdf5_support.h>
#include <cdea/output/safe_files.h>

#include <hdf5.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    using hdf5::ErrorPrintingOff;
    using hdf5::Handle;
  } // namespace

  namespace
  {
    using Kind = MapFileContent::Kind;

    /// The root attributes: the parameters, the map's grid and its outcome.
    void add_attributes(MapFileContent &content, const SweepMap &map,
                        const std::string &parameter_text)
    {
      const SweepSettings &s    = map.settings;
      const auto           text = [&](const std::string &name, const std::string &value) {
        content.attributes.push_back({name, Kind::text, 0., value});
      };
      const auto real = [&](const std::string &name, const double value, const Kind kind) {
        content.attributes.push_back({name, kind, value, ""});
      };
      text("parameters", parameter_text);
      text("code_version", CDEA_VERSION);
      text("method", to_string(RunMethod::finite_elements));
      text("run_status", sweep_run_status(map));
      real("inner_voltage_kV", s.inner_voltage / 1e3, Kind::real);
      real("outer_voltage_from_kV", s.outer_from / 1e3, Kind::real);
      real("outer_voltage_to_kV", s.outer_to / 1e3, Kind::real);
      real("outer_voltage_step_kV", s.outer_step / 1e3, Kind::real);
      real("line_tolerance_V", s.line_tolerance, Kind::real);
      real("zero_voltage_displacement_mm", map.zero_voltage_displacement * 1e3, Kind::real);
      real("n_rv", double(map.rows.size()), Kind::integer);
      real("n_outer", double(s.outer_voltages.size()), Kind::integer);
      std::string values;
      for (std::size_t i = 0; i < s.ring_edge_values.size(); ++i)
        values += (i ? ", " : "") + format_number(s.ring_edge_values[i], 12);
      text("ring_edge_values", values);
    }

    /// The datasets of a map, added in the file's order: one value per row,
    /// rows x outer voltages, or rows x the inner edges of both rings.
    class MapDatasets
    {
    public:
      MapDatasets(MapFileContent &content, const SweepMap &map)
        : content(content)
        , map(map)
        , n(map.rows.size())
        , m(map.settings.outer_voltages.size())
      {}

      void add(const std::string &name, const std::vector<std::size_t> &dims,
               std::vector<double> values, const std::string &unit,
               const std::string &description, const Kind kind = Kind::real)
      {
        MapFileContent::Dataset d;
        d.name        = name;
        d.unit        = unit;
        d.description = description;
        d.dims        = dims;
        d.kind        = kind;
        d.values      = std::move(values);
        content.datasets.push_back(std::move(d));
      }

      template <typename Get>
      std::vector<double> per_row(const Get &get) const
      {
        std::vector<double> v(n);
        for (std::size_t i = 0; i < n; ++i)
          v[i] = get(map.rows[i]);
        return v;
      }

      std::vector<double> grid(const std::vector<double> SweepRow::*field,
                               const double                      factor) const
      {
        std::vector<double> v(n * m, nan);
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t k = 0; k < m; ++k)
            v[i * m + k] = (map.rows[i].*field)[k] * factor;
        return v;
      }

      /// rows x 2: @p get(row, j) in kPa for the inner edges of rings 1 and 2.
      template <typename Get>
      std::vector<double> two_edges(const Get &get) const
      {
        std::vector<double> v(n * 2);
        for (std::size_t i = 0; i < n; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            v[i * 2 + j] = get(map.rows[i], j) / 1e3;
        return v;
      }

      MapFileContent    &content;
      const SweepMap    &map;
      const std::size_t  n, m;
    };

    /// The grid: the layouts, the outer voltages and the fields over both.
    void add_grid(MapDatasets &d)
    {
      const SweepMap     &map = d.map;
      const std::size_t   n = d.n, m = d.m;
      std::vector<double> outer(m);
      for (std::size_t k = 0; k < m; ++k)
        outer[k] = map.settings.outer_voltages[k] / 1e3;
      d.add("rv_over_a", {n}, d.per_row([](const SweepRow &r) { return r.rv_over_a; }), "1",
            "inner ring's outer edge r_v over the disk radius a (pre-stretched flat film)");
      d.add("outer_voltage_kV", {m}, outer, "kV",
            "voltage of the outer ring; the inner ring is held at inner_voltage_kV");
      d.add("displacement_mm", {n, m}, d.grid(&SweepRow::displacement, 1e3), "mm",
            "disk deflection |z(disk) - z(frame)|, rv x outer voltage; NaN where the "
            "continuation did not reach the point");
      d.add("stroke_mm", {n, m}, d.grid(&SweepRow::stroke, 1e3), "mm",
            "displacement minus zero_voltage_displacement_mm");
      d.add("stroke_increase_percent", {n, m}, d.grid(&SweepRow::stroke_increase, 1.), "%",
            "100 (stroke / stroke with both rings at the inner voltage - 1)");
      std::vector<double> v(n * m * 2, nan);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < m; ++k)
          {
            v[(i * m + k) * 2 + 0] = map.rows[i].s2_inner_ring1[k] / 1e3;
            v[(i * m + k) * 2 + 1] = map.rows[i].s2_inner_ring2[k] / 1e3;
          }
      d.add("s2_inner_edge_kPa", {n, m, 2}, v, "kPa",
            "nominal hoop stress s2 at the inner edge of ring 1 (disk edge) and ring 2 "
            "(r_v, on the outer ring's side), rv x outer voltage x 2");
    }

    /// The red and the blue line: one point per row each.
    void add_lines(MapDatasets &d)
    {
      const std::pair<const char *, SweepLine SweepRow::*> lines[] = {{"red", &SweepRow::red},
                                                                      {"blue", &SweepRow::blue}};
      for (const auto &[name, line] : lines)
        {
          const std::string prefix = std::string(name) + "_line_";
          const std::string what =
            std::string(name) == "red" ?
              "red line (s2 = 0 at the outer ring's inner edge)" :
              "blue line (equal s2 at the inner edges of both rings)";
          d.add(prefix + "outer_kV", {d.n},
                d.per_row([&](const SweepRow &r) { return (r.*line).outer_voltage / 1e3; }),
                "kV",
                "outer voltage on the " + what +
                  ", by root finding to line_tolerance_V; NaN where absent in the range");
          d.add(prefix + "increase_percent", {d.n},
                d.per_row([&](const SweepRow &r) { return (r.*line).stroke_increase; }), "%",
                "stroke increase on the " + what);
          d.add(prefix + "displacement_mm", {d.n},
                d.per_row([&](const SweepRow &r) { return (r.*line).displacement * 1e3; }),
                "mm", "displacement on the " + what);
          d.add(prefix + "s2_inner_edge_kPa", {d.n, 2},
                d.two_edges(
                  [&](const SweepRow &r, unsigned int j) { return (r.*line).s2_inner[j]; }),
                "kPa", "s2 at the inner edges of rings 1 and 2 on the " + what);
        }
    }

    /// Per row: its base state, how far it got, its cost and why it stopped.
    void add_row_outcomes(MapDatasets &d)
    {
      const std::size_t n = d.n;
      d.add("base_displacement_mm", {n},
            d.per_row([](const SweepRow &r) { return r.base_displacement * 1e3; }), "mm",
            "displacement with both rings at the inner voltage (the reference of the "
            "stroke increase)");
      d.add("base_s2_inner_edge_kPa", {n, 2},
            d.two_edges([](const SweepRow &r, unsigned int j) { return r.base_s2_inner[j]; }),
            "kPa",
            "s2 at the inner edges of rings 1 and 2 with both rings at the inner voltage");
      d.add("lowest_outer_kV", {n},
            d.per_row([](const SweepRow &r) { return r.lowest_voltage / 1e3; }), "kV",
            "lowest outer voltage of the grid reached by the continuation");
      d.add("highest_outer_kV", {n},
            d.per_row([](const SweepRow &r) { return r.highest_voltage / 1e3; }), "kV",
            "highest outer voltage of the grid reached by the continuation");
      d.add("solves", {n}, d.per_row([](const SweepRow &r) { return double(r.solves); }), "1",
            "equilibrium solves of the row (load stages, continuation, root finding)",
            Kind::integer);
      d.add("newton_iterations", {n},
            d.per_row([](const SweepRow &r) { return double(r.newton_iterations); }), "1",
            "Newton iterations of the row", Kind::integer);
      d.add("stop_message", {n}, {}, "",
            "why the continuation of the row stopped before the end of the grid (empty if it "
            "did not)",
            Kind::text);
      for (const SweepRow &r : d.map.rows)
        d.content.datasets.back().texts.push_back(r.message);
    }
  } // namespace

  MapFileContent sweep_map_content(const SweepMap &map, const std::string &parameter_text)
  {
    MapFileContent content;
    add_attributes(content, map, parameter_text);
    MapDatasets datasets(content, map);
    add_grid(datasets);
    add_lines(datasets);
    add_row_outcomes(datasets);
    return content;
  }

  bool some_row_reached(const SweepMap &map)
  {
    return std::any_of(map.rows.begin(), map.rows.end(),
                       [](const SweepRow &r) { return r.base_reached; });
  }

  std::size_t skipped_rows(const SweepMap &map)
  {
    return std::count_if(map.rows.begin(), map.rows.end(),
                         [](const SweepRow &r) { return r.skipped; });
  }

  std::string sweep_run_status(const SweepMap &map)
  {
    const std::string stopped = to_string(RunStatus::stopped) + ": ";
    if (const std::size_t skipped = skipped_rows(map))
      {
        const auto first = std::find_if(map.rows.begin(), map.rows.end(),
                                        [](const SweepRow &r) { return r.skipped; });
        return stopped + first->message + " after " + std::to_string(map.rows.size() - skipped) +
               " of " + std::to_string(map.rows.size()) + " layouts";
      }
    return some_row_reached(map) ? to_string(RunStatus::complete) :
                                   stopped + "no layout reached the inner voltage";
  }

  void write_sweep_file(const std::string &path, const SweepMap &map,
                        const std::string &parameter_text)
  {
    using Kind                   = MapFileContent::Kind;
    const MapFileContent content = sweep_map_content(map, parameter_text);

    ErrorPrintingOff quiet;
    const hdf5::Writer w("cannot write '" + path + "'");
    // In memory, then written whole and renamed onto the path: an older map
    // stays until the new one is complete. No modification times in the
    // object headers: the same map gives the same bytes.
    Handle file = hdf5::create_memory_file(path, false);

    for (const MapFileContent::Attribute &a : content.attributes)
      if (a.kind == Kind::text)
        w.string_attribute(file, a.name, a.text);
      else if (a.kind == Kind::integer)
        w.int_attribute(file, a.name, int(a.real));
      else
        w.double_attribute(file, a.name, a.real);
    for (const MapFileContent::Dataset &d : content.datasets)
      if (d.kind == Kind::text)
        w.string_dataset(file, d.name, d.texts, d.description);
      else if (d.kind == Kind::integer)
        w.int_dataset(file, d.name, std::vector<int>(d.values.begin(), d.values.end()),
                      d.description);
      else
        w.double_dataset(file, d.name, std::vector<hsize_t>(d.dims.begin(), d.dims.end()),
                         d.values, d.unit, d.description);
    const WriteOutcome out = replace_file(path, hdf5::file_image(file, w.name()), true);
    if (!out.ok)
      throw std::runtime_error("cannot write '" + path + "': " + out.message);
  }
} // namespace cdea
