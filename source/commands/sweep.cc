// `cdea sweep FILE.prm`: the design map of subsection Sweep over the MPI
// ranks (design/sweep.h), a progress display, the map file, and a table of
// the layouts with the largest stroke increase of each line.

#include <cdea/base/format.h>
#include <cdea/base/mpi_session.h>
#include <cdea/base/progress.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/design/sweep.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    /// The row with the largest stroke increase on @p line (rows.size() if none).
    std::size_t line_maximum(const SweepMap &map, SweepLine SweepRow::*line)
    {
      std::size_t best = map.rows.size();
      for (std::size_t i = 0; i < map.rows.size(); ++i)
        {
          const double x = (map.rows[i].*line).stroke_increase;
          if (!std::isnan(x) &&
              (best == map.rows.size() || x > (map.rows[best].*line).stroke_increase))
            best = i;
        }
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

      void print_banner(const Parameters &p, const std::string &path) const
      {
        const auto &s = settings;
        std::cout << "cdea " << CDEA_VERSION << " sweep: " << s.ring_edge_values.size()
                  << " layouts r_v/a = " << s.ring_edge_values.front() << " .. "
                  << s.ring_edge_values.back() << " x " << s.outer_voltages.size()
                  << " outer voltages " << s.outer_from / 1e3 << " .. "
                  << s.outer_voltages.back() / 1e3 << " kV (step " << s.outer_step / 1e3
                  << " kV), inner ring at " << s.inner_voltage / 1e3 << " kV\n"
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
        try
          {
            ReplaceTogether file({path});
            write_sweep_file(path, map, invocation.parameter_text);
            wrote = file.commit(skipped > 0).front();
          }
        catch (const std::exception &e)
          {
            std::cerr << "cdea: " << e.what() << " (the map is lost; an older map stays)\n";
            return exit_not_complete;
          }
        print_table();
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
                      << settings.inner_voltage / 1e3 << " kV (first row: "
                      << (map.rows.empty() ? std::string("none") : map.rows.front().message)
                      << "): the map is empty\n";
            return exit_not_complete;
          }
        return exit_success;
      }

      /// One line per layout, the maxima of both lines, the counts.
      void print_table() const
      {
        std::cout << "\nzero-voltage displacement under the dead load: " << std::setprecision(7)
                  << map.zero_voltage_displacement * 1e3 << " mm\n"
                  << std::setw(7) << "r_v/a" << std::setw(11) << "base (mm)" << std::setw(12)
                  << "reached kV" << std::setw(10) << "red kV" << std::setw(10) << "red %"
                  << std::setw(10) << "blue kV" << std::setw(10) << "blue %" << "  stop\n";
        unsigned long solves = 0, iterations = 0;
        for (const SweepRow &r : map.rows)
          {
            solves += r.solves;
            iterations += r.newton_iterations;
            std::cout << std::setw(7) << r.rv_over_a << std::setw(11)
                      << format_fixed_or_dash(r.base_displacement * 1e3, 4) << std::setw(12)
                      << format_fixed_or_dash(r.highest_voltage / 1e3, 3) << std::setw(10)
                      << format_fixed_or_dash(r.red.outer_voltage / 1e3, 4) << std::setw(10)
                      << format_fixed_or_dash(r.red.stroke_increase, 2) << std::setw(10)
                      << format_fixed_or_dash(r.blue.outer_voltage / 1e3, 4) << std::setw(10)
                      << format_fixed_or_dash(r.blue.stroke_increase, 2) << "  "
                      << (r.message.empty() ? "-" : shorten_at_word(r.message, 60)) << '\n';
          }
        for (const auto &[name, line] :
             {std::pair<const char *, SweepLine SweepRow::*>{"red", &SweepRow::red},
              std::pair<const char *, SweepLine SweepRow::*>{"blue", &SweepRow::blue}})
          {
            const std::size_t i = line_maximum(map, line);
            std::cout << "largest stroke increase on the " << name << " line: ";
            if (i == map.rows.size())
              std::cout << "none in the range\n";
            else
              std::cout << format_fixed_or_dash((map.rows[i].*line).stroke_increase, 2)
                        << " % at r_v/a = " << map.rows[i].rv_over_a << " (outer "
                        << format_fixed_or_dash((map.rows[i].*line).outer_voltage / 1e3, 4)
                        << " kV)\n";
          }
        std::cout << map.rows.size() * settings.outer_voltages.size() << " map points, "
                  << solves << " equilibrium solves, " << iterations << " Newton iterations, "
                  << std::setprecision(3) << seconds << " s on " << ranks_text() << '\n';
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> sweep_job()
  {
    return std::make_unique<Sweep>();
  }
} // namespace cdea
