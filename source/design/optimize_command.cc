// `cdea optimize FILE.prm`: the input, the starts over the MPI ranks
// (round-robin; rank 0 gathers them), progress, the summary and the files.

#include <cdea/analysis/commands.h>
#include <cdea/base/mpi_session.h>
#include <cdea/design/optimize.h>
#include <cdea/input/parameters.h>
#include <cdea/base/run_control.h>
#include <cdea/base/format.h>
#include <cdea/output/safe_files.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace cdea
{
  namespace
  {
    // ---------------------------------------------------------------------
    // A start's result as text for the gather (doubles in hexadecimal, so
    // they arrive bit for bit; strings with their length).

    void write_value(std::ostream &o, const double x) { o << std::hexfloat << x << ' '; }
    void write_value(std::ostream &o, const unsigned int x) { o << x << ' '; }
    void write_value(std::ostream &o, const std::string &s) { o << s.size() << ' ' << s << ' '; }
    template <typename T>
    void write_value(std::ostream &o, const std::vector<T> &v)
    {
      o << v.size() << ' ';
      for (const auto &x : v)
        write_value(o, x);
    }

    double read_double(std::istream &in)
    {
      std::string token;
      in >> token;
      return std::strtod(token.c_str(), nullptr); // hexfloat and nan/inf
    }
    unsigned int read_unsigned(std::istream &in)
    {
      unsigned int x = 0;
      in >> x;
      return x;
    }
    std::string read_string(std::istream &in)
    {
      const std::size_t n = read_unsigned(in);
      in.get();
      std::string s(n, '\0');
      in.read(s.data(), std::streamsize(n));
      return s;
    }
    std::vector<double> read_doubles(std::istream &in)
    {
      std::vector<double> v(read_unsigned(in));
      for (double &x : v)
        x = read_double(in);
      return v;
    }

    std::string serialize(const StartResult &r)
    {
      std::ostringstream o;
      for (const unsigned int x : {r.start, unsigned(r.converged), r.evaluations, r.solves,
                                   r.newton_iterations, unsigned(r.at_best.ok),
                                   r.at_best.points.n_quadrature_points})
        write_value(o, x);
      for (const double x : {r.seconds, r.objective, r.worst_constraint, r.optimality,
                             r.at_best.displacement,
                             r.at_best.stroke, r.at_best.volume_change, r.at_best.min_eigenvalue})
        write_value(o, x);
      write_value(o, r.status);
      write_value(o, r.at_best.message);
      write_value(o, r.active);
      for (const Layout *l : {&r.initial, &r.best})
        {
          write_value(o, l->edges);
          write_value(o, l->voltages);
        }
      const PointValues &p = r.at_best.points;
      write_value(o, p.R);
      write_value(o, p.ring);
      write_value(o, std::vector<double>(p.s2.data(), p.s2.data() + p.s2.size()));
      write_value(o, std::vector<double>(p.field.data(), p.field.data() + p.field.size()));
      write_value(o, unsigned(r.history.size()));
      for (const HistoryRow &h : r.history)
        {
          write_value(o, h.evaluation);
          write_value(o, h.objective);
          write_value(o, h.worst_constraint);
          write_value(o, h.free_values);
          write_value(o, h.message);
        }
      return o.str();
    }

    StartResult deserialize(std::istream &in)
    {
      StartResult r;
      r.start                               = read_unsigned(in);
      r.converged                           = read_unsigned(in) != 0;
      r.evaluations                         = read_unsigned(in);
      r.solves                              = read_unsigned(in);
      r.newton_iterations                   = read_unsigned(in);
      r.at_best.ok                          = read_unsigned(in) != 0;
      r.at_best.points.n_quadrature_points  = read_unsigned(in);
      r.seconds                             = read_double(in);
      r.objective                           = read_double(in);
      r.worst_constraint                    = read_double(in);
      r.optimality                          = read_double(in);
      r.at_best.displacement                = read_double(in);
      r.at_best.stroke                      = read_double(in);
      r.at_best.volume_change               = read_double(in);
      r.at_best.min_eigenvalue              = read_double(in);
      r.status                              = read_string(in);
      r.at_best.message                     = read_string(in);
      r.active.resize(read_unsigned(in));
      for (auto &a : r.active)
        a = read_string(in);
      for (Layout *l : {&r.initial, &r.best})
        {
          l->edges    = read_doubles(in);
          l->voltages = read_doubles(in);
        }
      PointValues &p = r.at_best.points;
      p.R            = read_doubles(in);
      p.ring.resize(read_unsigned(in));
      for (auto &k : p.ring)
        k = read_unsigned(in);
      const auto s2 = read_doubles(in), field = read_doubles(in);
      p.s2          = Eigen::Map<const Eigen::VectorXd>(s2.data(), s2.size());
      p.field       = Eigen::Map<const Eigen::VectorXd>(field.data(), field.size());
      r.history.resize(read_unsigned(in));
      for (HistoryRow &h : r.history)
        {
          h.start            = r.start;
          h.evaluation       = read_unsigned(in);
          h.objective        = read_double(in);
          h.worst_constraint = read_double(in);
          h.free_values      = read_doubles(in);
          h.message          = read_string(in);
        }
      if (!in)
        throw std::runtime_error("cdea optimize: garbled start result in the gather");
      return r;
    }

    /// Every rank's results on rank 0 (the others keep their own).
    std::vector<StartResult> gather(const std::vector<StartResult> &mine)
    {
      if (mpi::size() == 1)
        return mine;
      std::string text;
      for (const auto &r : mine)
        text += serialize(r);
      const std::vector<std::string> per_rank = mpi::gather_bytes(text);
      if (mpi::rank() != 0)
        return mine;
      std::vector<StartResult> results;
      for (const std::string &bytes : per_rank)
        {
          std::istringstream in(bytes);
          while (in >> std::ws && in.peek() != EOF)
            results.push_back(deserialize(in));
        }
      std::sort(results.begin(), results.end(),
                [](const StartResult &a, const StartResult &b) { return a.start < b.start; });
      return results;
    }
  } // namespace

  OptimizationRun optimize_layouts(const Parameters &p, const Scene &base,
                                   const OptimizationSettings                    &s,
                                   const std::function<void(const HistoryRow &)>  &on_evaluation,
                                   const std::function<void(const StartResult &)> &on_start)
  {
    const auto       start_time = std::chrono::steady_clock::now();
    SteppingSettings stepping   = stepping_settings(p);
    stepping.arc_length         = false;
    stepping.stability_check    = false;
    stepping.breakdown_field    = 0.;
    LayoutEvaluator evaluator(base, s, fe_discretization(p), newton_settings(p), stepping);
    const auto      layouts = starting_layouts(s);
    std::vector<StartResult> mine;
    for (unsigned int k = mpi::rank(); k < layouts.size(); k += mpi::size())
      {
        // After a stop request only a rank's first start runs (and stops at
        // its first evaluation), so that every rank has a result to gather.
        if (StopOnSignals::requested() != 0 && !mine.empty())
          break;
        mine.push_back(optimize_from(base, s, evaluator, k, layouts[k], on_evaluation));
        if (on_start)
          on_start(mine.back());
      }
    OptimizationRun run;
    run.starts = gather(mine);
    if (mpi::rank() == 0)
      run.best = best_start(run.starts);
    run.ranks   = mpi::size();
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    return run;
  }

  int run_optimize(const std::string &prm_file)
  {
    const bool           root = mpi::rank() == 0;
    Parameters           p;
    Scene                base;
    OptimizationSettings s;
    std::string          text;
    try
      {
        p    = read_parameters(prm_file, &text);
        base = p.scene();
        s    = optimization_settings(p, base);
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "cdea: " << e.what() << '\n';
        return exit_input_error;
      }
    const std::string h5_path  = p.results_path("_optimum");
    const std::string prm_path = p.output.directory + "/" + p.output.base_name + "_optimum.prm";
    // The output must be writable, and ours alone (a lock on the .h5 file),
    // before anything is computed; rank 0 writes, the others follow its
    // verdict. Directories made here go again if nothing is written.
    int                      writable = 1;
    OutputLock               lock;
    std::vector<std::string> created;
    if (root)
      {
        std::string why;
        if (!claim_output(h5_path, lock, why, &created))
          {
            std::cerr << "cdea: cannot write '" << h5_path << "': " << why << '\n';
            writable = 0;
          }
      }
    mpi::broadcast(writable);
    if (!writable)
      return exit_input_error;
    // SIGINT, SIGTERM: the starts stop at their next evaluation and the best
    // layout so far is written (exit code 2).
    const StopOnSignals stop_on_signals;

    const auto start_time = std::chrono::steady_clock::now();
    const auto free       = s.free_parameters();
    const bool stroke     = s.objective == DesignObjective::stroke;
    if (root)
      {
        std::cout << "cdea " << CDEA_VERSION << " optimize: " << s.n_rings << " ring(s), maximise "
                  << to_string(s.objective) << " by " << to_string(s.algorithm) << ", "
                  << s.starts << " start(s) on " << mpi::size() << " rank(s)\nfree:";
        for (const auto &f : free)
          std::cout << "  " << f.name();
        std::cout << "\nconstraints: s2 >= " << s.min_hoop_stress * 1e-3 << " kPa";
        if (std::isfinite(s.max_field))
          std::cout << ", E <= " << s.max_field * 1e-6 << " MV/m";
        std::cout << ", rings >= " << s.min_ring_width * base.disk_radius * 1e3
                  << " mm, stable\n"
                  << std::setw(5) << "start" << std::setw(6) << "eval" << std::setw(14)
                  << (stroke ? "stroke (mm)" : "dV (1e3 mm3)") << std::setw(12) << "worst c"
                  << "  free variables (kV, r/a)\n";
      }

    const auto progress = [&](const HistoryRow &h) {
      if (!root)
        return;
      std::cout << std::setw(5) << h.start << std::setw(6) << h.evaluation << std::setw(14)
                << (std::isnan(h.objective) ? std::string("failed") : format_fixed(h.objective, 6))
                << std::setw(12) << format_number(h.worst_constraint, 3) << " ";
      for (const double v : h.free_values)
        std::cout << ' ' << format_fixed(v, 4);
      if (!h.message.empty())
        std::cout << "  (" << h.message << ")";
      std::cout << std::endl;
    };
    const auto start_done = [&](const StartResult &r) {
      if (root)
        std::cout << "start " << r.start << ": " << r.status << std::endl;
    };
    OptimizationRun run = optimize_layouts(p, base, s, progress, start_done);
    if (!root)
      return exit_success;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();

    std::cout << "\n" << std::setw(5) << "start" << std::setw(14)
              << (stroke ? "stroke (mm)" : "dV (1e3 mm3)") << std::setw(12) << "worst c"
              << std::setw(6) << "evals" << std::setw(8) << "solves"
              << "  edges (r/a) | voltages (kV) | status\n";
    unsigned int evaluations = 0, solves = 0, iterations = 0;
    for (const auto &r : run.starts)
      {
        evaluations += r.evaluations;
        solves += r.solves;
        iterations += r.newton_iterations;
        std::cout << std::setw(5) << r.start << std::setw(14)
                  << (r.at_best.ok ? format_fixed(r.objective, 6) : std::string("-"))
                  << std::setw(12) << format_number(r.worst_constraint, 3) << std::setw(6)
                  << r.evaluations << std::setw(8) << r.solves << "  " << format_fixed_list(r.best.edges, 4)
                  << " | " << format_fixed_list(r.best.voltages, 4, 1e-3) << " | " << r.status << '\n';
      }
    const StartResult      &best = run.starts[run.best];
    const LayoutEvaluation &e    = best.at_best;
    const int               signal = StopOnSignals::requested();
    if (!e.ok)
      {
        std::cerr << "cdea: "
                  << (signal ? "interrupted by " + signal_name(signal) + " before any start "
                                                                          "reached a layout" :
                               "no start reached a layout the constraints could be evaluated "
                               "at (" + best.status + ")")
                  << "; nothing written\n";
        lock.release();
        remove_created_directories(created);
        return exit_not_complete;
      }
    std::cout << "\nOptimum (start " << best.start << ", " << (best.converged ? "converged" : "NOT converged")
              << "):\n  ring edges (r/a): " << format_fixed_list(best.best.edges, 4)
              << "\n  voltages (kV):    " << format_fixed_list(best.best.voltages, 4, 1e-3) << std::setprecision(7)
              << "\n  displacement " << e.displacement * 1e3 << " mm, stroke " << e.stroke * 1e3
              << " mm, enclosed volume change " << e.volume_change * 1e9 << " mm^3\n";
    if (e.ok && e.points.s2.size())
      std::cout << "  min s2 " << e.points.s2.minCoeff() * 1e-3 << " kPa, max E "
                << e.points.field.maxCoeff() * 1e-6 << " MV/m, smallest tangent eigenvalue "
                << e.min_eigenvalue << " N/m\n";
    std::cout << "  active constraints:\n";
    for (const auto &a : best.active)
      std::cout << "    " << a << '\n';
    std::cout << evaluations << " evaluations, " << solves << " equilibrium solves, " << iterations
              << " Newton iterations, " << std::setprecision(3) << run.seconds << " s\n";

    try
      {
        write_optimum_file(h5_path, run, s, base, text);
        write_replay_parameters(prm_file, prm_path, best.best, p.output.base_name, s.max_field);
      }
    catch (const std::exception &error)
      {
        std::cerr << "cdea: the results cannot be written: " << error.what()
                  << " (older files of this name stay as they were)\n";
        return exit_not_complete;
      }
    std::cout << "wrote " << h5_path << " and " << prm_path << '\n';
    if (signal)
      {
        std::cerr << "cdea: interrupted by " << signal_name(signal)
                  << "; the best layout found so far is in " << h5_path << '\n';
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
} // namespace cdea
