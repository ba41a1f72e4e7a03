// `cdea optimize FILE.prm`: the starts of subsection Optimization over the MPI
// ranks (design/optimize.h), each evaluation printed as it comes, a table of
// the starts, the optimum, and the files <Base name>_optimum.h5 and
// <Base name>_optimum.prm. 0 converged, 2 not converged or interrupted (the
// best layout so far is written), 1 bad input.

#include <cdea/base/format.h>
#include <cdea/base/mpi_session.h>
#include <cdea/base/run_control.h>
#include <cdea/commands/command.h>
#include <cdea/design/optimize.h>
#include <cdea/model/quantities_optimize.h>
#include <cdea/output/product_file.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    class Optimize final : public CommandJob
    {
    public:
      void check(Invocation &invocation) override
      {
        base     = invocation.parameters.scene();
        settings = optimization_settings(invocation.parameters, base);
        const std::string prm_path = replay_path(invocation.parameters);
        if (const std::string why = refused_names(prm_path); !why.empty())
          throw InputError("cannot write '" + prm_path + "': " + why);
      }

      std::string output_path(const Invocation &invocation) const override
      {
        return invocation.parameters.results_path("_optimum");
      }

      int run(Invocation &invocation) override
      {
        const bool root       = invocation.root;
        const auto start_time = std::chrono::steady_clock::now();
        if (root)
          print_banner();
        const auto progress = [root](const HistoryRow &h) {
          if (root)
            print_evaluation(h);
        };
        const auto start_done = [root](const StartResult &r) {
          if (root)
            std::cout << "start " << r.start << ": " << r.status << std::endl;
        };
        OptimizationRun run =
          optimize_layouts(invocation.parameters, base, settings, progress, start_done);
        if (!root)
          return exit_success;
        run.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
        print_starts(run);
        const StartResult &best = run.starts[run.best];
        if (!best.at_best.ok)
          return nothing_reached(invocation, best);
        const Product product =
          optimum_product(run, settings, base, invocation.parameter_text);
        print_optimum(run, product.root());
        return write_and_report(invocation, run, product);
      }

    private:
      Scene                base;
      OptimizationSettings settings;

      std::string objective_header() const
      {
        return settings.objective == DesignObjective::stroke ? "stroke (mm)" : "dV (1e3 mm3)";
      }

      void print_banner() const
      {
        const auto &s = settings;
        std::cout << "cdea " << CDEA_VERSION << " optimize: " << s.n_rings
                  << " ring(s), maximise " << to_string(s.objective) << " by "
                  << to_string(s.algorithm) << ", " << s.starts << " start(s) on " << mpi::size()
                  << " rank(s)\nfree:";
        for (const auto &f : s.free_parameters())
          std::cout << "  " << f.name();
        std::cout << "\nconstraints: s2 >= " << units::kPa.from_si(s.min_hoop_stress) << " kPa";
        if (std::isfinite(s.max_field))
          std::cout << ", E <= " << units::MV_per_m.from_si(s.max_field) << " MV/m";
        std::cout << ", rings >= " << units::mm.from_si(s.min_ring_width * base.disk_radius)
                  << " mm, stable\n"
                  << std::setw(5) << "start" << std::setw(6) << "eval" << std::setw(14)
                  << objective_header() << std::setw(12) << "worst c"
                  << "  free variables (kV, r/a)\n";
      }

      static void print_evaluation(const HistoryRow &h)
      {
        std::cout << std::setw(5) << h.start << std::setw(6) << h.evaluation << std::setw(14)
                  << (std::isnan(h.objective) ? std::string("failed") :
                                                format_fixed(h.objective, 6))
                  << std::setw(12) << format_number(h.worst_constraint, 3) << " ";
        for (const double v : h.free_values)
          std::cout << ' ' << format_fixed(v, 4);
        if (!h.message.empty())
          std::cout << "  (" << h.message << ")";
        std::cout << std::endl;
      }

      /// One line per start, and the counts over all of them.
      void print_starts(const OptimizationRun &run) const
      {
        std::cout << "\n" << std::setw(5) << "start" << std::setw(14) << objective_header()
                  << std::setw(12) << "worst c" << std::setw(6) << "evals" << std::setw(8)
                  << "solves" << "  edges (r/a) | voltages (kV) | status\n";
        for (const auto &r : run.starts)
          std::cout << std::setw(5) << r.start << std::setw(14)
                    << (r.at_best.ok ? format_fixed(r.objective, 6) : std::string("-"))
                    << std::setw(12) << format_number(r.worst_constraint, 3) << std::setw(6)
                    << r.evaluations << std::setw(8) << r.solves << "  "
                    << format_fixed_list(r.best.edges, 4) << " | "
                    << format_fixed_list(r.best.voltages, 4, units::kV.multiply) << " | "
                    << r.status << '\n';
      }

      /// No start reached a layout: nothing is written.
      static int nothing_reached(Invocation &invocation, const StartResult &best)
      {
        const int signal = StopOnSignals::requested();
        std::cerr << "cdea: "
                  << (signal ? "interrupted by " + signal_name(signal) +
                                 " before any start reached a layout" :
                               "no start reached a layout the constraints could be evaluated "
                               "at (" + best.status + ")")
                  << "; nothing written\n";
        invocation.output.give_up();
        return exit_not_complete;
      }

      static void print_optimum(const OptimizationRun &run, const ProductGroup &optimum)
      {
        using namespace optimize_quantity;
        const StartResult &best        = run.starts[run.best];
        unsigned int       evaluations = 0, solve_count = 0, iterations = 0;
        for (const auto &r : run.starts)
          {
            evaluations += r.evaluations;
            solve_count += r.solves;
            iterations += r.newton_iterations;
          }
        const auto value = [&](const Quantity &q) { return optimum.at(q).value(0); };
        std::cout << "\nOptimum (start " << best.start << ", "
                  << (best.converged ? "converged" : "NOT converged")
                  << "):\n  ring edges (r/a): " << format_fixed_list(optimum.at(ring_edges).in_unit(), 4)
                  << "\n  voltages (kV):    " << format_fixed_list(optimum.at(voltages).in_unit(), 4)
                  << std::setprecision(7) << "\n  displacement " << value(displacement)
                  << " mm, stroke " << value(stroke) << " mm, enclosed volume change "
                  << value(volume_change) << " mm^3\n";
        if (best.at_best.ok && best.at_best.points.s2.size())
          std::cout << "  min s2 " << value(min_s2) << " kPa, max E " << value(max_field)
                    << " MV/m, smallest tangent eigenvalue " << value(min_tangent_eigenvalue)
                    << " N/m\n";
        std::cout << "  active constraints:\n";
        for (const auto &a : best.active)
          std::cout << "    " << a << '\n';
        std::cout << evaluations << " evaluations, " << solve_count << " equilibrium solves, "
                  << iterations << " Newton iterations, " << std::setprecision(3) << run.seconds
                  << " s\n";
      }

      static std::string replay_path(const Parameters &p)
      {
        return p.output.directory + "/" + p.output.base_name + "_optimum.prm";
      }

      /// The optimum file and the replay's parameter file (together or not
      /// at all; after a stop beside older ones, to their partial names),
      /// and how the run ended.
      int write_and_report(Invocation &invocation, const OptimizationRun &run,
                           const Product &product) const
      {
        const Parameters  &p       = invocation.parameters;
        const StartResult &best    = run.starts[run.best];
        const std::string &h5_path = invocation.output.path;
        const int          signal  = StopOnSignals::requested();
        std::vector<std::string> wrote;
        try
          {
            ReplaceTogether pair({h5_path, replay_path(p)});
            write_product_file(product, h5_path);
            write_replay_parameters(invocation.input, replay_path(p), best.best,
                                    p.output.base_name, settings.max_field);
            wrote = pair.commit(signal != 0);
          }
        catch (const std::exception &error)
          {
            std::cerr << "cdea: the results cannot be written: " << error.what()
                      << " (older files of this name stay as they were)\n";
            return exit_not_complete;
          }
        std::cout << "wrote " << wrote[0] << " and " << wrote[1] << '\n';
        if (signal)
          {
            std::cerr << "cdea: interrupted by " << signal_name(signal)
                      << "; the best layout found so far is in " << wrote[0]
                      << (wrote[0] != h5_path ? " (the older " + h5_path + " is kept as it was)" :
                                                "")
                      << '\n';
            return exit_not_complete;
          }
        if (!best.converged)
          {
            std::cerr << "cdea: the optimizer stopped without converging (" << best.status
                      << "); the best layout found is in " << h5_path << '\n';
            return exit_not_complete;
          }
        return exit_success;
      }
    };
  } // namespace

  std::unique_ptr<CommandJob> optimize_job()
  {
    return std::make_unique<Optimize>();
  }
} // namespace cdea
