// The product of `cdea sweep`, the design map (model/quantities_sweep.h):
// written to <Directory>/<Base name>_map.h5 by rank 0 after the rows have
// been gathered, and returned by the Python module. It holds no
// run-dependent data (no times, no rank count), so a serial and a
// distributed run of the same map give the same file.

#include <cdea/analysis/run_record.h>
#include <cdea/base/format.h>
#include <cdea/design/sweep.h>
#include <cdea/model/quantities_sweep.h>

#include <algorithm>
#include <limits>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The root attributes: the parameters, the map's grid and its outcome.
    void add_attributes(ProductGroup &root, const SweepMap &map, const std::string &parameter_text)
    {
      using namespace sweep_quantity;
      const SweepSettings &s = map.settings;
      std::string          values;
      for (std::size_t i = 0; i < s.ring_edge_values.size(); ++i)
        values += (i ? ", " : "") + format_number(s.ring_edge_values[i], 12);
      root.set(sweep_quantity::parameters, parameter_text)
        .set(code_version, CDEA_VERSION)
        .set(method, to_string(RunMethod::finite_elements))
        .set(sweep_quantity::run_status, sweep_run_status(map))
        .set(inner_voltage, s.inner_voltage)
        .set(outer_from, s.outer_from)
        .set(outer_to, s.outer_to)
        .set(outer_step, s.outer_step)
        .set(line_tolerance, s.line_tolerance)
        .set(sweep_quantity::zero_voltage_displacement, map.zero_voltage_displacement)
        .set(n_rv, map.rows.size())
        .set(n_outer, s.outer_voltages.size())
        .set(ring_edge_values, values);
    }

    /// The values of a map over its rows (SI): one per row, rows x outer
    /// voltages, or rows x the inner edges of both rings.
    class MapValues
    {
    public:
      explicit MapValues(const SweepMap &map)
        : map(map)
        , n(map.rows.size())
        , m(map.settings.outer_voltages.size())
      {}

      template <typename Get>
      std::vector<double> per_row(const Get &get) const
      {
        std::vector<double> v(n);
        for (std::size_t i = 0; i < n; ++i)
          v[i] = get(map.rows[i]);
        return v;
      }

      std::vector<double> grid(const std::vector<double> SweepRow::*field) const
      {
        std::vector<double> v(n * m, nan);
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t k = 0; k < m; ++k)
            v[i * m + k] = (map.rows[i].*field)[k];
        return v;
      }

      /// rows x 2: @p get(row, j) for the inner edges of rings 1 and 2.
      template <typename Get>
      std::vector<double> two_edges(const Get &get) const
      {
        std::vector<double> v(n * 2);
        for (std::size_t i = 0; i < n; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            v[i * 2 + j] = get(map.rows[i], j);
        return v;
      }

      const SweepMap   &map;
      const std::size_t n, m;
    };

    /// The grid: the layouts, the outer voltages and the fields over both.
    void add_grid(ProductGroup &root, const MapValues &d)
    {
      using namespace sweep_quantity;
      const SweepMap     &map = d.map;
      const std::size_t   n = d.n, m = d.m;
      std::vector<double> v(n * m * 2, nan);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < m; ++k)
          {
            v[(i * m + k) * 2 + 0] = map.rows[i].s2_inner_ring1[k];
            v[(i * m + k) * 2 + 1] = map.rows[i].s2_inner_ring2[k];
          }
      root.set(rv_over_a, d.per_row([](const SweepRow &r) { return r.rv_over_a; }))
        .set(outer_voltage, map.settings.outer_voltages)
        .set(displacement, d.grid(&SweepRow::displacement), {n, m})
        .set(stroke, d.grid(&SweepRow::stroke), {n, m})
        .set(stroke_increase, d.grid(&SweepRow::stroke_increase), {n, m})
        .set(s2_inner_edge, v, {n, m, 2});
    }

    /// The red and the blue line: one point per row each.
    void add_lines(ProductGroup &root, const MapValues &d)
    {
      using namespace sweep_quantity;
      struct Line
      {
        SweepLine SweepRow::*line;
        const Quantity      &outer, &increase, &displacement, &s2;
      };
      for (const Line &l : {Line{&SweepRow::red, red_outer, red_increase, red_displacement, red_s2},
                            Line{&SweepRow::blue, blue_outer, blue_increase, blue_displacement,
                                 blue_s2}})
        root.set(l.outer, d.per_row([&](const SweepRow &r) { return (r.*l.line).outer_voltage; }))
          .set(l.increase,
               d.per_row([&](const SweepRow &r) { return (r.*l.line).stroke_increase; }))
          .set(l.displacement,
               d.per_row([&](const SweepRow &r) { return (r.*l.line).displacement; }))
          .set(l.s2,
               d.two_edges([&](const SweepRow &r, unsigned int j) { return (r.*l.line).s2_inner[j]; }),
               {d.n, 2});
    }

    /// Per row: its base state, how far it got, its cost and why it stopped.
    void add_row_outcomes(ProductGroup &root, const MapValues &d)
    {
      using namespace sweep_quantity;
      std::vector<std::string> messages;
      for (const SweepRow &r : d.map.rows)
        messages.push_back(r.message);
      root.set(base_displacement, d.per_row([](const SweepRow &r) { return r.base_displacement; }))
        .set(base_s2, d.two_edges([](const SweepRow &r, unsigned int j) { return r.base_s2_inner[j]; }),
             {d.n, 2})
        .set(lowest_outer, d.per_row([](const SweepRow &r) { return r.lowest_voltage; }))
        .set(highest_outer, d.per_row([](const SweepRow &r) { return r.highest_voltage; }))
        .set(solves, d.per_row([](const SweepRow &r) { return double(r.solves); }))
        .set(newton_iterations,
             d.per_row([](const SweepRow &r) { return double(r.newton_iterations); }))
        .set(stop_message, messages);
    }
  } // namespace

  Product sweep_product(const SweepMap &map, const std::string &parameter_text)
  {
    Product         product;
    const MapValues values(map);
    add_attributes(product.root(), map, parameter_text);
    add_grid(product.root(), values);
    add_lines(product.root(), values);
    add_row_outcomes(product.root(), values);
    return product;
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

} // namespace cdea
