// One start of the layout optimization with NLopt: the scaled problem
// (variables in [0, 1] between their bounds, objective and constraints of
// order one) and the best layout, confirmed by a ramp. The starting layouts
// and the constraints are optimize_problem.cc.

#include <cdea/design/optimize.h>
#include <cdea/base/run_control.h>
#include <cdea/base/format.h>

#include <Eigen/QR>
#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    /// NLopt aims at constraints below this (scaled: s2 in units of mu) ...
    constexpr double constraint_tolerance = 1e-8;
    /// ... and a layout counts as feasible up to this, the accuracy of s2
    /// from Newton-converged states (s2 >= -1e-6 mu).
    constexpr double feasibility_tolerance = 1e-6;
    /// Scaled constraints above this at the optimum are reported as active.
    constexpr double active_tolerance = 1e-6;
    /// Relative first-order (KKT) residual of a converged optimum.
    constexpr double optimality_tolerance = 1e-3;

    std::string nlopt_status(const nlopt::result r)
    {
      switch (r)
        {
          case nlopt::SUCCESS:
            return "success";
          case nlopt::STOPVAL_REACHED:
            return "objective limit reached";
          case nlopt::FTOL_REACHED:
            return "objective tolerance reached";
          case nlopt::XTOL_REACHED:
            return "variable tolerance reached";
          case nlopt::MAXEVAL_REACHED:
            return "Optimization/Max evaluations reached";
          case nlopt::MAXTIME_REACHED:
            return "time limit";
          case nlopt::ROUNDOFF_LIMITED:
            return "no further progress (round-off)";
          case nlopt::FORCED_STOP:
            return "forced stop";
          default:
            return "failure (" + std::to_string(int(r)) + ")";
        }
    }

  } // namespace

  namespace
  {
    /// First-order optimality of an evaluated layout in the scaled
    /// variables: grad f + A lambda = 0 over the active constraints and
    /// bounds with lambda >= 0.
    struct Assessment
    {
      double                   objective = nan, worst = nan, optimality = nan;
      bool                     signs = true, converged = false;
      std::vector<std::string> active;
    };

    /// One start of the optimization: the scaled problem NLopt solves
    /// (variables y in [0, 1] between their bounds, the objective in mm or
    /// 1000 mm^3, constraints of order one), the evaluation of the last point
    /// it asked for, and the best layout met.
    class StartOptimizer
    {
    public:
      StartOptimizer(const Scene &base, const OptimizationSettings &s,
                     LayoutEvaluator &evaluator,
                     const std::function<void(const HistoryRow &)> &on_evaluation,
                     StartResult &result)
        : base(base)
        , s(s)
        , evaluator(evaluator)
        , on_evaluation(on_evaluation)
        , result(result)
        , free(s.free_parameters())
        , n(free.size())
        , stroke(s.objective == DesignObjective::stroke)
        , scale(stroke ? 1e-3 : 1e-6)
        , lower(n)
        , upper(n)
      {
        for (unsigned int j = 0; j < n; ++j)
          {
            const bool voltage = free[j].kind == ParameterKind::voltage;
            lower[j]           = voltage ? s.voltage_lower : s.edge_lower;
            upper[j]           = voltage ? s.voltage_upper : s.edge_upper;
          }
      }

      /// The start must be reachable from zero voltage: its voltages are
      /// lowered until the ramp passes no fold. False (with the status) if
      /// no such start is found.
      bool reach_start(const Layout &start)
      {
        layout = start;
        first  = evaluator.ramp(layout);
        for (unsigned int k = 0; k < 20 && !first.ok; ++k)
          {
            for (double &v : layout.voltages)
              v *= 0.9;
            first = evaluator.ramp(layout);
          }
        result.initial = layout;
        if (!first.ok)
          {
            result.status =
              "stopped: no starting layout reachable from zero voltage: " + first.message;
            return false;
          }
        evaluation = first;
        evaluated  = layout;
        best       = layout;
        return true;
      }

      /// NLopt from the best layout, in up to three rounds: SLSQP's merit
      /// function can stall a little outside the feasible set (its penalty
      /// approaching the multipliers); a fresh start from the best layout
      /// (new quasi-Newton matrix and penalty) then finishes the job.
      void optimize()
      {
        nlopt::opt opt(s.algorithm == DesignAlgorithm::mma ? nlopt::LD_MMA : nlopt::LD_SLSQP, n);
        configure(opt);
        std::vector<double> y(n);
        nlopt::result       status = nlopt::SUCCESS;
        for (unsigned int round = 0; round < 3 && result.evaluations < s.max_evaluations; ++round)
          {
            const auto values0 = best.free_values(free);
            for (unsigned int j = 0; j < n; ++j)
              y[j] = std::clamp((values0[j] - lower[j]) / (upper[j] - lower[j]), 0., 1.);
            opt.set_maxeval(int(s.max_evaluations - result.evaluations));
            double f = 0.;
            try
              {
                status = opt.optimize(y, f);
              }
            catch (const std::exception &)
              {
                status = opt.last_optimize_result();
              }
            if (StopOnSignals::requested() != 0 ||
                assess(best, evaluator.evaluate(best)).converged)
              break;
          }
        result.status = nlopt_status(status);
      }

      void move_onto_boundary();
      void confirm();

    private:
      const Scene                                   &base;
      const OptimizationSettings                    &s;
      LayoutEvaluator                               &evaluator;
      const std::function<void(const HistoryRow &)> &on_evaluation;
      StartResult                                   &result;
      const std::vector<SceneParameter>              free;
      const unsigned int                             n;
      const bool                                     stroke;
      const double                                   scale;
      std::vector<double>                            lower, upper;

      Layout              layout; ///< the start reached
      LayoutEvaluation    first;  ///< its evaluation
      std::vector<double> cached_y;
      LayoutEvaluation    evaluation; ///< of the last point NLopt asked for
      Layout              evaluated;  ///< that point
      Eigen::VectorXd     c;          ///< constraints of the last layout looked at
      Eigen::MatrixXd     dc;
      bool                have_first     = true;
      double              best_objective = -std::numeric_limits<double>::infinity();
      double              best_violation = std::numeric_limits<double>::infinity();
      Layout              best;
      unsigned int        m = 0; ///< number of constraints

      double objective_of(const LayoutEvaluation &e) const
      {
        return (stroke ? e.stroke : e.volume_change) / scale;
      }

      Layout to_layout(const double *y) const
      {
        std::vector<double> values(n);
        for (unsigned int j = 0; j < n; ++j)
          values[j] = lower[j] + (upper[j] - lower[j]) * y[j];
        Layout l = layout;
        l.set_free_values(free, values);
        return l;
      }

      void     configure(nlopt::opt &opt);
      void     evaluate_at(const double *y);
      void     record_evaluation();
      double   objective(const double *y, double *grad);
      void     constraint(double *out, const double *y, double *grad);
      Assessment assess(const Layout &l, const LayoutEvaluation &e);
    };

    void StartOptimizer::configure(nlopt::opt &opt)
    {
      {
        Eigen::VectorXd c0;
        Eigen::MatrixXd d0;
        constraints(s, base, layout, first, c0, d0);
        m = unsigned(c0.size());
      }
      opt.set_lower_bounds(std::vector<double>(n, 0.));
      opt.set_upper_bounds(std::vector<double>(n, 1.));
      opt.set_min_objective(
        [](unsigned, const double *y, double *g, void *data) {
          return static_cast<StartOptimizer *>(data)->objective(y, g);
        },
        this);
      if (m > 0)
        opt.add_inequality_mconstraint(
          [](unsigned, double *out, unsigned, const double *y, double *g, void *data) {
            static_cast<StartOptimizer *>(data)->constraint(out, y, g);
          },
          this, std::vector<double>(m, constraint_tolerance));
      opt.set_xtol_rel(s.tolerance);
      opt.set_xtol_abs(std::vector<double>(n, s.tolerance));
      opt.set_ftol_rel(s.tolerance);
    }

    // The evaluation of the point y unless it is the last one asked for.
    void StartOptimizer::evaluate_at(const double *y)
    {
      if (cached_y.size() == n && std::equal(cached_y.begin(), cached_y.end(), y))
        return;
      cached_y.assign(y, y + n);
      evaluated = to_layout(y);
      if (have_first && evaluated.voltages == layout.voltages && evaluated.edges == layout.edges)
        evaluation = first;
      else
        try
          {
            evaluation = evaluator.evaluate(evaluated);
          }
        catch (const std::exception &error)
          {
            // A singular tangent or a state outside the material's range:
            // this layout is rejected like one behind a fold.
            evaluation         = LayoutEvaluation();
            evaluation.message = error.what();
          }
      have_first = false;
      record_evaluation();
    }

    // The history row of the last evaluation; the best layout so far:
    // the best feasible one, or while there is none the least infeasible.
    void StartOptimizer::record_evaluation()
    {
      HistoryRow row;
      row.start      = result.start;
      row.evaluation = ++result.evaluations;
      row.objective  = nan;
      if (evaluation.ok)
        {
          constraints(s, base, evaluated, evaluation, c, dc);
          row.objective        = objective_of(evaluation);
          row.worst_constraint = c.size() ? c.maxCoeff() : 0.;
          const bool feasible  = row.worst_constraint <= feasibility_tolerance;
          if ((feasible && (best_violation > feasibility_tolerance ||
                            row.objective > best_objective)) ||
              (!feasible && row.worst_constraint < best_violation &&
               best_violation > feasibility_tolerance))
            {
              best_objective = row.objective;
              best_violation = row.worst_constraint;
              best           = evaluated;
            }
        }
      else
        {
          row.worst_constraint = nan;
          row.message          = evaluation.message;
        }
      const std::vector<double> values = evaluated.free_values(free);
      for (unsigned int j = 0; j < n; ++j)
        row.free_values.push_back(values[j] *
                                  (free[j].kind == ParameterKind::voltage ? 1e-3 : 1.));
      result.history.push_back(row);
      if (on_evaluation)
        on_evaluation(row);
    }

    double StartOptimizer::objective(const double *y, double *grad)
    {
      if (StopOnSignals::requested() != 0)
        throw nlopt::forced_stop(); // NLopt returns, with FORCED_STOP
      evaluate_at(y);
      if (!evaluation.ok)
        {
          if (grad)
            std::fill(grad, grad + n, 0.);
          return HUGE_VAL;
        }
      const Eigen::VectorXd &d = stroke ? evaluation.d_stroke : evaluation.d_volume_change;
      if (grad)
        for (unsigned int j = 0; j < n; ++j)
          grad[j] = -d[j] * (upper[j] - lower[j]) / scale;
      return -(stroke ? evaluation.stroke : evaluation.volume_change) / scale;
    }

    void StartOptimizer::constraint(double *out, const double *y, double *grad)
    {
      evaluate_at(y);
      for (unsigned int i = 0; i < m; ++i)
        {
          out[i] = evaluation.ok ? c[i] : nan;
          if (grad)
            for (unsigned int j = 0; j < n; ++j)
              grad[i * n + j] = evaluation.ok ? dc(i, j) * (upper[j] - lower[j]) : 0.;
        }
    }

    Assessment StartOptimizer::assess(const Layout &l, const LayoutEvaluation &e)
    {
      Assessment               a;
      std::vector<std::string> names;
      if (!e.ok)
        return a;
      constraints(s, base, l, e, c, dc, &names);
      a.objective              = objective_of(e);
      a.worst                  = c.size() ? c.maxCoeff() : 0.;
      const Eigen::VectorXd &d = stroke ? e.d_stroke : e.d_volume_change;
      Eigen::VectorXd        g(n);
      for (unsigned int j = 0; j < n; ++j)
        g[j] = -d[j] * (upper[j] - lower[j]) / scale;
      std::vector<Eigen::VectorXd> columns;
      for (int i = 0; i < c.size(); ++i)
        if (c[i] > -active_tolerance)
          {
            a.active.push_back(names[i]);
            columns.push_back(dc.row(i).transpose().cwiseProduct(
              Eigen::Map<const Eigen::VectorXd>(upper.data(), n) -
              Eigen::Map<const Eigen::VectorXd>(lower.data(), n)));
          }
      const auto values = l.free_values(free);
      for (unsigned int j = 0; j < n; ++j)
        {
          const double t = (values[j] - lower[j]) / (upper[j] - lower[j]);
          if (t < 1e-9 || t > 1. - 1e-9)
            {
              a.active.push_back(free[j].name() + " at its " + (t < 0.5 ? "lower" : "upper") +
                                 " bound");
              columns.push_back((t < 0.5 ? -1. : 1.) * Eigen::VectorXd::Unit(n, j));
            }
        }
      Eigen::MatrixXd A(n, columns.size());
      for (std::size_t k = 0; k < columns.size(); ++k)
        A.col(k) = columns[k];
      const Eigen::VectorXd lambda =
        columns.empty() ? Eigen::VectorXd() :
                          Eigen::VectorXd(A.completeOrthogonalDecomposition().solve(-g));
      const Eigen::VectorXd residual = columns.empty() ? g : Eigen::VectorXd(g + A * lambda);
      a.optimality = residual.norm() / std::max(g.norm(), 1e-300);
      a.signs      = lambda.size() == 0 || lambda.minCoeff() >= -1e-6 * g.norm();
      a.converged  = a.worst <= feasibility_tolerance && a.optimality <= optimality_tolerance &&
                    a.signs;
      return a;
    }

    // The optimizer ends on the constraint boundary from either side, and
    // the best layout is often a little outside (within the feasibility
    // tolerance), where the replay by `cdea run` would see s2 just below
    // zero. One Gauss-Newton step on the active constraints, to a small
    // margin inside, moves it onto the boundary; kept only if it is
    // feasible and loses no more than a relative 1e-5 of the objective
    // (the step is of the size of the violation, at most 1e-6).
    void StartOptimizer::move_onto_boundary()
    {
      const LayoutEvaluation at = evaluator.evaluate(best);
      if (!at.ok)
        return;
      constraints(s, base, best, at, c, dc);
      const double     objective = objective_of(at);
      std::vector<int> active;
      for (int i = 0; i < c.size(); ++i)
        if (c[i] > -active_tolerance)
          active.push_back(i);
      if (!(c.size() && c.maxCoeff() > 0. && c.maxCoeff() <= feasibility_tolerance))
        return;
      constexpr double margin = 1e-9; // in units of mu (s2), of the limit (E)
      Eigen::MatrixXd  A(active.size(), n);
      Eigen::VectorXd  target(active.size());
      for (std::size_t k = 0; k < active.size(); ++k)
        {
          for (unsigned int j = 0; j < n; ++j)
            A(k, j) = dc(active[k], j) * (upper[j] - lower[j]);
          target[k] = -margin - c[active[k]];
        }
      const Eigen::VectorXd step   = A.completeOrthogonalDecomposition().solve(target);
      const auto            values = best.free_values(free);
      std::vector<double>   moved(n);
      for (unsigned int j = 0; j < n; ++j)
        moved[j] = std::clamp(values[j] + step[j] * (upper[j] - lower[j]), lower[j], upper[j]);
      Layout candidate = best;
      candidate.set_free_values(free, moved);
      const LayoutEvaluation there = evaluator.evaluate(candidate);
      if (!there.ok)
        return;
      constraints(s, base, candidate, there, c, dc);
      if (c.maxCoeff() <= 0. && objective_of(there) >= objective - 1e-5 * std::abs(objective))
        best = candidate;
    }

    // The best layout, confirmed from zero voltage as `cdea run` would reach it.
    void StartOptimizer::confirm()
    {
      result.best    = best;
      result.at_best = evaluator.ramp(best);
      if (!result.at_best.ok)
        {
          result.status += "; the best layout could not be confirmed by a ramp from zero: " +
                           result.at_best.message;
          result.worst_constraint = nan;
          return;
        }
      const Assessment a      = assess(best, result.at_best);
      result.objective        = a.objective;
      result.worst_constraint = a.worst;
      result.optimality       = a.optimality;
      result.active           = a.active;
      result.converged        = a.converged;
      const std::string nlopt = "NLopt: " + result.status;
      if (result.converged)
        result.status = "optimal (first-order residual " + format_number(result.optimality, 2) +
                        "; " + nlopt + ")";
      else
        result.status = (result.worst_constraint > feasibility_tolerance ?
                           std::string("NOT converged: no feasible layout found") :
                           "NOT converged: first-order residual " +
                             format_number(result.optimality, 2) +
                             (a.signs ? "" : ", a constraint pushes the wrong way")) +
                        " (" + nlopt + ")";
    }
  } // namespace

  StartResult optimize_from(const Scene &base, const OptimizationSettings &s,
                            LayoutEvaluator &evaluator, const unsigned int index,
                            const Layout &start,
                            const std::function<void(const HistoryRow &)> &on_evaluation)
  {
    const auto         clock_start = std::chrono::steady_clock::now();
    const unsigned int solves0 = evaluator.solves(), iterations0 = evaluator.newton_iterations();
    StartResult        result;
    result.start   = index;
    result.initial = start;
    StartOptimizer optimizer(base, s, evaluator, on_evaluation, result);
    if (!optimizer.reach_start(start))
      return result;
    optimizer.optimize();
    optimizer.move_onto_boundary();
    optimizer.confirm();
    result.solves            = evaluator.solves() - solves0;
    result.newton_iterations = evaluator.newton_iterations() - iterations0;
    result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    return result;
  }
} // namespace cdea
