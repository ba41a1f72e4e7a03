// The starts of `cdea optimize` over the MPI ranks (round-robin; rank 0
// gathers them and chooses the best). The command is commands/optimize.cc.

#include <cdea/base/mpi_session.h>
#include <cdea/base/run_control.h>
#include <cdea/design/optimize.h>
#include <cdea/input/parameters.h>
#include <cdea/input/solver_settings.h>

#include <algorithm>
#include <chrono>
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
    const auto      start_time = std::chrono::steady_clock::now();
    LayoutEvaluator evaluator(base, s, fe_discretization(p), newton_settings(p),
                              study_stepping_settings(p));
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
} // namespace cdea
