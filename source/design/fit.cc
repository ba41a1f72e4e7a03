// The least-squares calibration by Ceres (Levenberg-Marquardt with the exact
// Jacobian) and its error analysis. The command is commands/fit.cc.

#include <cdea/design/fit.h>
#include <cdea/base/run_control.h>
#include <cdea/base/format.h>
#include <cdea/base/units.h>

#include <Eigen/SVD>
#include <ceres/ceres.h>

#include <cmath>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    /// Condition number of the column-scaled Jacobian above which the data
    /// do not determine the parameters (no standard errors), and above which
    /// they determine them poorly (a warning).
    constexpr double singular_condition = 1e10, weak_condition = 1e4;

    /// The scaled problem: q_j = p_j / p0_j, residuals sqrt(w) (model -
    /// measured) in the observations' unit (mm for displacements).
    class ObservationResiduals final : public ceres::CostFunction
    {
    public:
      ObservationResiduals(const FitFunction &model, const FitObservations &data,
                           const std::vector<double> &scale, unsigned int &evaluations,
                           std::string &failure)
        : model(model)
        , data(data)
        , scale(scale)
        , evaluations(evaluations)
        , failure(failure)
      {
        set_num_residuals(int(data.measured.size()));
        mutable_parameter_block_sizes()->push_back(int(scale.size()));
      }

      bool Evaluate(double const *const *q, double *residuals, double **jacobians) const override
      {
        const std::size_t   K = scale.size();
        std::vector<double> values(K);
        for (std::size_t j = 0; j < K; ++j)
          values[j] = q[0][j] * scale[j];
        Eigen::VectorXd d;
        Eigen::MatrixXd J;
        const bool      want = jacobians != nullptr && jacobians[0] != nullptr;
        ++evaluations;
        try
          {
            if (!model(values, d, want ? &J : nullptr, &failure))
              return false;
          }
        catch (const std::exception &e)
          {
            // Nothing may leave Ceres by an exception: a failed evaluation.
            failure = e.what();
            return false;
          }
        for (Eigen::Index i = 0; i < data.measured.size(); ++i)
          {
            const double root_w = std::sqrt(data.weight[i]);
            residuals[i]        = root_w * (d[i] - data.measured[i]) / data.unit;
            if (want)
              for (std::size_t j = 0; j < K; ++j)
                jacobians[0][i * K + j] = root_w * J(i, j) * scale[j] / data.unit;
          }
        return true;
      }

    private:
      const FitFunction         &model;
      const FitObservations     &data;
      const std::vector<double> &scale;
      unsigned int              &evaluations;
      std::string               &failure; ///< why the last failed evaluation failed
    };

    class Progress final : public ceres::IterationCallback
    {
    public:
      Progress(const std::function<void(unsigned int, double, const std::vector<double> &)> &f,
               const std::vector<double> &q, const std::vector<double> &scale)
        : f(f)
        , q(q)
        , scale(scale)
      {}
      ceres::CallbackReturnType operator()(const ceres::IterationSummary &s) override
      {
        std::vector<double> values(q.size());
        for (std::size_t j = 0; j < q.size(); ++j)
          values[j] = q[j] * scale[j];
        if (f)
          f(unsigned(s.iteration), s.cost, values);
        // SIGINT, SIGTERM (cdea fit): stop with the values reached so far.
        return StopOnSignals::requested() != 0 ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
      }

    private:
      const std::function<void(unsigned int, double, const std::vector<double> &)> &f;
      const std::vector<double> &q, &scale;
    };



    /// The free parameters with large entries in @p v (a singular vector);
    /// the largest one if none is large.
    std::string parameter_names(const Eigen::VectorXd &v, const FitSettings &settings)
    {
      std::string list;
      for (std::size_t j = 0; j < settings.free.size(); ++j)
        if (std::abs(v[j]) > 0.1)
          list += (list.empty() ? "" : ", ") + label(settings.free[j]);
      if (list.empty())
        {
          Eigen::Index largest = 0;
          v.cwiseAbs().maxCoeff(&largest);
          list = label(settings.free[std::size_t(largest)]);
        }
      return list;
    }

    /// The interval of a law constant @p p that the law @p law declares.
    LawConstant declared_range(const MembraneLaw &law, const SceneParameter &p)
    {
      for (const LawConstant &c : law.own_constants())
        if (c.entry == p.entry)
          return c;
      return {p.entry};
    }

    /// Bounds inside the laws' range: positive film constants, a taut film,
    /// Jlim above the pre-stretched film's I - 3, a law's own constants in
    /// the interval the law declares (in the scaled variables q). A law's
    /// further checks (Ogden's mu_p alpha_p >= 0) fail the evaluation of a
    /// step beyond them, which Levenberg-Marquardt rejects and shortens.
    void set_bounds(ceres::Problem &problem, std::vector<double> &q, const Scene &base,
                    const FitSettings &settings, const std::vector<double> &scale)
    {
      const auto law = base.law();
      for (std::size_t j = 0; j < settings.free.size(); ++j)
        {
          double lower = 1e-3;
          if (settings.free[j].kind == ParameterKind::prestretch)
            lower = 1.01 / scale[j];
          if (settings.free[j].kind == ParameterKind::jlim)
            {
              const double l = base.prestretch;
              lower          = 1.001 * (2. * l * l + std::pow(l, -4) - 3.) / scale[j];
            }
          if (settings.free[j].kind == ParameterKind::law_constant)
            {
              const LawConstant range = declared_range(*law, settings.free[j]);
              if (std::isfinite(range.upper))
                problem.SetParameterUpperBound(q.data(), int(j), range.upper / scale[j]);
              lower = range.lower / scale[j];
              if (!std::isfinite(lower))
                continue;
            }
          if (j < settings.window.size())
            {
              lower = std::max(lower, settings.window[j].first / scale[j]);
              if (std::isfinite(settings.window[j].second))
                problem.SetParameterUpperBound(q.data(), int(j), settings.window[j].second / scale[j]);
            }
          problem.SetParameterLowerBound(q.data(), int(j), lower);
        }
    }

    ceres::Solver::Options solver_options(const FitSettings &settings)
    {
      ceres::Solver::Options options;
      options.linear_solver_type           = ceres::DENSE_QR;
      options.max_num_iterations           = int(settings.max_iterations);
      options.function_tolerance           = settings.tolerance;
      options.parameter_tolerance          = settings.tolerance;
      options.gradient_tolerance           = 1e-3 * settings.tolerance;
      options.logging_type                 = ceres::SILENT;
      options.minimizer_progress_to_stdout = false;
      options.update_state_every_iteration = true;
      return options;
    }

    /// Standard errors from s^2 (J^T W J)^-1 with the weighted Jacobian
    /// @p Jw and residuals @p weighted at the optimum, in the column-scaled
    /// variables p_j / |column j| so that the condition number is
    /// scale-free; correlations, and warnings about parameters the data do
    /// not determine.
    void analyse_errors(const Eigen::MatrixXd &Jw, const Eigen::VectorXd &weighted,
                        const FitSettings &settings, FitResult &r)
    {
      const std::size_t K = settings.free.size(), M = std::size_t(Jw.rows());
      Eigen::VectorXd   norms(K);
      for (std::size_t j = 0; j < K; ++j)
        {
          // A column of zeros (the displacements do not depend on that
          // parameter) stays zero: its singular vector names it.
          norms[j] = Jw.col(j).norm();
          if (!(norms[j] > 0.))
            norms[j] = 1.;
        }
      const Eigen::MatrixXd             Jn = Jw * norms.cwiseInverse().asDiagonal();
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
      const Eigen::VectorXd            &sv = svd.singularValues();
      r.condition = sv[K - 1] > 0. ? sv[0] / sv[K - 1] : std::numeric_limits<double>::infinity();
      r.standard_errors.assign(K, nan);
      r.correlation = Eigen::MatrixXd::Constant(K, K, nan);
      r.covariance  = r.correlation;
      if (!(r.condition < singular_condition))
        {
          r.warnings.push_back("the data do not determine " +
                               parameter_names(svd.matrixV().col(K - 1), settings) +
                               " separately (condition number of the scaled Jacobian " +
                               format_number(r.condition, 3) +
                               "): changing them together leaves every displacement the same; "
                               "fix all but one of them (Calibration/Free parameters)");
          return;
        }
      if (M <= K)
        {
          r.warnings.push_back("as many data points as free parameters: no standard errors");
          return;
        }
      const double          s2 = weighted.squaredNorm() / double(M - K);
      const Eigen::MatrixXd V  = svd.matrixV();
      const Eigen::MatrixXd cn =
        s2 * V * sv.array().square().inverse().matrix().asDiagonal() * V.transpose();
      const Eigen::MatrixXd cov =
        norms.cwiseInverse().asDiagonal() * cn * norms.cwiseInverse().asDiagonal();
      r.covariance = cov;
      for (std::size_t j = 0; j < K; ++j)
        r.standard_errors[j] = std::sqrt(cov(j, j));
      for (std::size_t i = 0; i < K; ++i)
        for (std::size_t j = 0; j < K; ++j)
          r.correlation(i, j) = cn(i, j) / std::sqrt(cn(i, i) * cn(j, j));
      if (r.condition > weak_condition)
        r.warnings.push_back("the data determine " + parameter_names(V.col(K - 1), settings) +
                             " only poorly together (condition number " +
                             format_number(r.condition, 3) + "): see their correlation");
      for (std::size_t i = 0; i < K; ++i)
        for (std::size_t j = i + 1; j < K; ++j)
          if (std::abs(r.correlation(i, j)) > 0.99)
            r.warnings.push_back(label(settings.free[i]) + " and " + label(settings.free[j]) +
                                 " are correlated (" + format_number(r.correlation(i, j), 4) +
                                 "): the data constrain mainly a combination of them");
    }
  } // namespace

  FitResult fit(const Scene &base, const CalibrationData &data, const FitSettings &settings,
                DisplacementModel &model,
                const std::function<void(unsigned int, double, const std::vector<double> &)> &progress)
  {
    // Residuals in mm.
    FitObservations observations{
      Eigen::Map<const Eigen::VectorXd>(data.displacement.data(), Eigen::Index(data.size())),
      Eigen::Map<const Eigen::VectorXd>(data.weight.data(), Eigen::Index(data.size())),
      units::mm.to_si};
    const FitFunction function = [&model](const std::vector<double> &values, Eigen::VectorXd &d,
                                          Eigen::MatrixXd *J, std::string *message) {
      return model.evaluate(values, d, J, message);
    };
    return fit_observations(base, observations, settings, function, progress);
  }

  FitResult fit_observations(
    const Scene &base, const FitObservations &data, const FitSettings &settings,
    const FitFunction                                                            &model,
    const std::function<void(unsigned int, double, const std::vector<double> &)> &progress)
  {
    const std::size_t K = settings.free.size(), M = std::size_t(data.measured.size());
    FitResult         r;
    for (const auto &p : settings.free)
      r.initial.push_back(parameter_value(base, p));
    // q_j = p_j / |p0_j|: 1 in size at the start (a law constant that
    // starts at 0, such as a Mooney-Rivlin C2, in units of its entry).
    std::vector<double> scale;
    for (const double p0 : r.initial)
      scale.push_back(p0 != 0. ? std::abs(p0) : 1.);
    std::vector<double> q(K);
    for (std::size_t j = 0; j < K; ++j)
      q[j] = r.initial[j] / scale[j];

    r.standard_errors.assign(K, nan);
    r.correlation = Eigen::MatrixXd::Constant(K, K, nan);
    r.covariance  = r.correlation;
    r.values      = r.initial;
    r.rms         = nan;
    r.condition   = nan;

    // Ceres' own log lines (glog) would repeat on stderr what the result says.
    FLAGS_minloglevel = google::GLOG_FATAL;
    std::string    failure;
    ceres::Problem problem;
    problem.AddResidualBlock(
      new ObservationResiduals(model, data, scale, r.evaluations, failure), nullptr, q.data());
    set_bounds(problem, q, base, settings, scale);
    ceres::Solver::Options options = solver_options(settings);
    Progress               callback(progress, q, scale);
    options.callbacks.push_back(&callback);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    r.iterations = unsigned(summary.iterations.size());
    r.converged  = summary.termination_type == ceres::CONVERGENCE;
    r.status     = summary.message;
    if (summary.iterations.empty())
      {
        // The start itself failed: no iteration, nothing fitted.
        r.started   = false;
        r.converged = false;
        r.status    = "the fit cannot start: " + (failure.empty() ? r.status : failure);
        return r;
      }
    for (std::size_t j = 0; j < K; ++j)
      r.values[j] = q[j] * scale[j];

    // Residuals and the Jacobian at the optimum.
    Eigen::VectorXd d;
    Eigen::MatrixXd J;
    if (!model(r.values, d, &J, &r.status))
      {
        r.converged = false;
        return r;
      }
    r.fitted    = d;
    r.residuals = d - data.measured;
    Eigen::VectorXd root_w(M);
    double          sum_w = 0.;
    for (std::size_t i = 0; i < M; ++i)
      {
        root_w[i] = std::sqrt(data.weight[i]);
        sum_w += data.weight[i];
      }
    const Eigen::VectorXd weighted = root_w.cwiseProduct(r.residuals);
    r.rms                          = std::sqrt(weighted.squaredNorm() / sum_w);
    analyse_errors(root_w.asDiagonal() * J, weighted, settings, r);
    return r;
  }
} // namespace cdea
