// `cdea sweep FILE.prm`: the design map of subsection Sweep over the MPI
// ranks (design/sweep.h), a progress display, the map file, and a table of
// the layouts with the largest stroke increase of each line.

#include <cdea/base/format.h>
#include <cdea/base/mpi_session.h>
#include <cdea/base/progress.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/design/sweep.h>
#include <cdea/model/quantities_sweep.h>
#include <cdea/output/product_file.h>
#include <cdea/output/product_table.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <tuple>

namespace cdea
{
  namespace
  {
    /// The row with the largest value of @p increase (size if none is a number).
    std::size_t line_maximum(const ProductGroup &map, const Quantity &increase)
    {
      const std::vector<double> &x    = map.at(increase).values;
      std::size_t                best = x.size();
      for (std::size_t i = 0; i < x.size(); ++i)
        if (!std::isnan(x[i]) && (best == x.size() || x[i] > x[best]))
          best = i;
      return best;
    }

    std::string ranks_text()
    {
      return std::to_string(mpi::size()) + (mpi::size() == 1 ? " rank" : " ranks");
    }

    class Sweep final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        base     = invocation.parameters.scene();
        settings = sweep_settings(invocation.parameters, base);
      }

      std::string output_path(const Invocation &invocation) const override
      {
        return invocation.parameters.results_path("_map");
      }

      int run(Invocation &invocation) override
      {
        const Parameters &p    = invocation.parameters;
        const bool        root = invocation.root;
        const std::size_t n = settings.ring_edge_values.size(), m = settings.outer_voltages.size();
        if (root)
          print_banner(p, invocation.output.path);
        const auto start = std::chrono::steady_clock::now();
        Progress   progress(n * m, root);
        try
          {
            map = compute_sweep_map(p, base, settings,
                                    [&](const std::size_t c) { progress.add(c); });
          }
        catch (const std::exception &e)
          {
            std::cerr << "cdea: sweep failed: " << one_line_message(e) << '\n';
            invocation.output.give_up();
            return exit_input_error;
          }
        progress.finish();
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!root)
          return exit_success;
        return write_and_report(invocation);
      }

    private:
      Scene         base;
      SweepSettings settings;
      SweepMap      map;
      double        seconds = 0.;

      /// A voltage of the map in kV, as the map file holds it.
      static double kV(const double volts) { return units::kV_divided.from_si(volts); }

      void print_banner(const Parameters &p, const std::string &path) const
      {
        const auto &s = settings;
        std::cout << "cdea " << CDEA_VERSION << " sweep: " << s.ring_edge_values.size()
                  << " layouts r_v/a = " << s.ring_edge_values.front() << " .. "
                  << s.ring_edge_values.back() << " x " << s.outer_voltages.size()
                  << " outer voltages " << kV(s.outer_from) << " .. "
                  << kV(s.outer_voltages.back()) << " kV (step " << kV(s.outer_step)
                  << " kV), inner ring at " << kV(s.inner_voltage) << " kV\n"
                  << "FE model: degree " << p.discretization.polynomial_degree << ", "
                  << p.discretization.elements_per_ring << " elements per ring; "
                  << ranks_text() << " (rows round-robin); writing " << path << '\n';
        // The work before it starts: the file holds about 40 bytes a point,
        // 340 a layout and 20 kB of names and descriptions (measured: 101 kB
        // for prm/sweep-inner5.prm's 29 x 61, 11.7 MB for 29 x 10001).
        const double rows = double(s.ring_edge_values.size()),
                     points = rows * double(s.outer_voltages.size());
        std::cout << "work: " << static_cast<unsigned long long>(points)
                  << " map points (the progress shows the time left), results about "
                  << format_bytes(20e3 + 40. * points + 340. * rows) << std::endl;
      }

      /// Rank 0: the map file (unless no row was computed before a stop),
      /// the table and how the map ended.
      int write_and_report(Invocation &invocation)
      {
        const std::string &path    = invocation.output.path;
        const std::size_t  skipped = skipped_rows(map);
        if (skipped > 0 && skipped == map.rows.size())
          {
            std::cerr << "cdea: " << map.rows.front().message
                      << " before any layout was computed; nothing written\n";
            invocation.output.give_up();
            return exit_not_complete;
          }
        // A map cut short goes beside an older one (<stem>.partial.h5).
        std::string wrote;
        const Product product = sweep_product(map, invocation.parameter_text);
        try
          {
            ReplaceTogether file({path});
            write_product_file(product, path);
            wrote = file.commit(skipped > 0).front();
          }
        catch (const std::exception &e)
          {
            std::cerr << "cdea: " << e.what() << " (the map is lost; an older map stays)\n";
            return exit_not_complete;
          }
        print_layouts(product.root());
        std::cout << "wrote " << wrote << '\n';
        if (skipped > 0)
          {
            std::cerr << "cdea: " << sweep_run_status(map).substr(std::string("stopped: ").size())
                      << "; the map so far is in " << wrote
                      << (wrote != path ? " (the older " + path + " is kept as it was)" : "")
                      << '\n';
            return exit_not_complete;
          }
        if (!some_row_reached(map))
          {
            std::cerr << "cdea: no layout reached the inner voltage of "
                      << kV(settings.inner_voltage) << " kV (first row: "
                      << (map.rows.empty() ? std::string("none") : map.rows.front().message)
                      << "): the map is empty\n";
            return exit_not_complete;
          }
        return exit_success;
      }

      /// One line per layout, the maxima of both lines, the counts.
      void print_layouts(const ProductGroup &map) const
      {
        using namespace sweep_quantity;
        std::cout << "\nzero-voltage displacement under the dead load: " << std::setprecision(7)
                  << map.at(sweep_quantity::zero_voltage_displacement).value(0) << " mm\n";
        const std::size_t n = map.at(rv_over_a).size();
        std::vector<std::size_t> rows(n);
        for (std::size_t i = 0; i < n; ++i)
          rows[i] = i;
        print_table(std::cout, map,
                    {{&rv_over_a, "r_v/a", 7, CellStyle::plain},
                     {&base_displacement, "base (mm)", 11, CellStyle::fixed_or_dash, 4},
                     {&highest_outer, "reached kV", 12, CellStyle::fixed_or_dash, 3},
                     {&red_outer, "red kV", 10, CellStyle::fixed_or_dash, 4},
                     {&red_increase, "red %", 10, CellStyle::fixed_or_dash, 2},
                     {&blue_outer, "blue kV", 10, CellStyle::fixed_or_dash, 4},
                     {&blue_increase, "blue %", 10, CellStyle::fixed_or_dash, 2},
                     {&stop_message, "stop", 0, CellStyle::text, 60, "  "}},
                    rows);
        for (const auto &[name, outer, increase] :
             {std::tuple<const char *, const Quantity *, const Quantity *>{"red", &red_outer,
                                                                           &red_increase},
              {"blue", &blue_outer, &blue_increase}})
          {
            const std::size_t i = line_maximum(map, *increase);
            std::cout << "largest stroke increase on the " << name << " line: ";
            if (i == n)
              std::cout << "none in the range\n";
            else
              std::cout << format_fixed_or_dash(map.at(*increase).value(i), 2)
                        << " % at r_v/a = " << map.at(rv_over_a).value(i) << " (outer "
                        << format_fixed_or_dash(map.at(*outer).value(i), 4) << " kV)\n";
          }
        unsigned long solve_count = 0, iterations = 0;
        for (std::size_t i = 0; i < n; ++i)
          {
            solve_count += static_cast<unsigned long>(map.at(solves).values[i]);
            iterations += static_cast<unsigned long>(map.at(newton_iterations).values[i]);
          }
        std::cout << n * settings.outer_voltages.size() << " map points, " << solve_count
                  << " equilibrium solves, " << iterations << " Newton iterations, "
                  << std::setprecision(3) << seconds << " s on " << ranks_text() << '\n';
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> sweep_job()
  {
    return std::make_unique<Sweep>();
  }
} // namespace cdea
