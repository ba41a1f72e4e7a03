// The least-squares calibration by Ceres (Levenberg-Marquardt with the exact
// Jacobian), its error analysis, and the command `cdea fit`.

#include <cdea/analysis/commands.h>
#include <cdea/design/fit.h>
#include <cdea/input/parameters.h>
#include <cdea/base/run_control.h>
#include <cdea/base/format.h>
#include <cdea/output/hdf5_writer.h>
#include <cdea/output/safe_files.h>

#include <Eigen/SVD>
#include <ceres/ceres.h>


#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    /// Residuals in mm.
    constexpr double residual_unit = 1e-3;
    /// Condition number of the column-scaled Jacobian above which the data
    /// do not determine the parameters (no standard errors), and above which
    /// they determine them poorly (a warning).
    constexpr double singular_condition = 1e10, weak_condition = 1e4;

    /// The scaled problem: q_j = p_j / p0_j, residuals sqrt(w) (model -
    /// measured) in mm.
    class DisplacementResiduals final : public ceres::CostFunction
    {
    public:
      DisplacementResiduals(DisplacementModel &model, const CalibrationData &data,
                            const std::vector<double> &scale, unsigned int &evaluations)
        : model(model)
        , data(data)
        , scale(scale)
        , evaluations(evaluations)
      {
        set_num_residuals(int(data.size()));
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
        if (!model.evaluate(values, d, want ? &J : nullptr))
          return false;
        for (std::size_t i = 0; i < data.size(); ++i)
          {
            const double root_w = std::sqrt(data.weight[i]);
            residuals[i]        = root_w * (d[i] - data.displacement[i]) / residual_unit;
            if (want)
              for (std::size_t j = 0; j < K; ++j)
                jacobians[0][i * K + j] = root_w * J(i, j) * scale[j] / residual_unit;
          }
        return true;
      }

    private:
      DisplacementModel         &model;
      const CalibrationData     &data;
      const std::vector<double> &scale;
      unsigned int              &evaluations;
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

    /// A parameter in the units of its prm entry, with the unit.
    std::pair<double, std::string> shown(const SceneParameter &p, const double value)
    {
      switch (p.kind)
        {
          case ParameterKind::shear_modulus:
            return {value * 1e-3, "kPa"};
          case ParameterKind::mass:
            return {value * 1e3, "g"};
          case ParameterKind::permittivity:
            return {value, "F/m"};
          default:
            return {value, ""};
        }
    }

    std::string label(const SceneParameter &p)
    {
      switch (p.kind)
        {
          case ParameterKind::shear_modulus:
            return "shear modulus";
          case ParameterKind::jlim:
            return "Jlim";
          case ParameterKind::permittivity:
            return "permittivity";
          case ParameterKind::mass:
            return "mass";
          case ParameterKind::prestretch:
            return "pre-stretch";
          default:
            return p.name();
        }
    }

    /// The free parameters with large entries in @p v (a singular vector).
    std::string parameter_names(const Eigen::VectorXd &v, const FitSettings &settings)
    {
      std::string list;
      for (std::size_t j = 0; j < settings.free.size(); ++j)
        if (std::abs(v[j]) > 0.1)
          list += (list.empty() ? "" : ", ") + label(settings.free[j]);
      return list;
    }

    /// Bounds inside the laws' range: positive constants, a taut film, Jlim
    /// above the pre-stretched film's I - 3 (in the scaled variables q).
    void set_lower_bounds(ceres::Problem &problem, std::vector<double> &q, const Scene &base,
                          const FitSettings &settings, const std::vector<double> &scale)
    {
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
        norms[j] = Jw.col(j).norm();
      const Eigen::MatrixXd             Jn = Jw * norms.cwiseInverse().asDiagonal();
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
      const Eigen::VectorXd            &sv = svd.singularValues();
      r.condition = sv[K - 1] > 0. ? sv[0] / sv[K - 1] : std::numeric_limits<double>::infinity();
      r.standard_errors.assign(K, nan);
      r.correlation = Eigen::MatrixXd::Constant(K, K, nan);
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
    const std::size_t K = settings.free.size(), M = data.size();
    FitResult         r;
    for (const auto &p : settings.free)
      r.initial.push_back(parameter_value(base, p));
    const std::vector<double> scale = r.initial;
    std::vector<double>       q(K, 1.);

    ceres::Problem problem;
    problem.AddResidualBlock(new DisplacementResiduals(model, data, scale, r.evaluations), nullptr,
                             q.data());
    set_lower_bounds(problem, q, base, settings, scale);
    ceres::Solver::Options options = solver_options(settings);
    Progress               callback(progress, q, scale);
    options.callbacks.push_back(&callback);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    r.iterations = unsigned(summary.iterations.size());
    r.converged  = summary.termination_type == ceres::CONVERGENCE;
    r.status     = summary.message;
    for (std::size_t j = 0; j < K; ++j)
      r.values.push_back(q[j] * scale[j]);

    // Residuals and the Jacobian at the optimum.
    Eigen::VectorXd d;
    Eigen::MatrixXd J;
    if (!model.evaluate(r.values, d, &J, &r.status))
      {
        r.converged = false;
        return r;
      }
    r.fitted    = d;
    r.residuals = d - Eigen::Map<const Eigen::VectorXd>(data.displacement.data(), M);
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

  int run_fit(const std::string &prm_file, const std::string &data_file)
  {
    Parameters      p;
    Scene           base;
    FitSettings     settings;
    CalibrationData data;
    std::string     text;
    try
      {
        p        = read_parameters(prm_file, &text);
        base     = p.scene();
        settings = fit_settings(p);
        data     = read_calibration_data(data_file, base.n_rings());
        if (data.size() < settings.free.size())
          throw InputError(data_file + ": " + std::to_string(data.size()) + " data points for " +
                           std::to_string(settings.free.size()) +
                           " free parameters (Calibration/Free parameters): give at least as "
                           "many points as parameters");
      }
    catch (const InputError &e)
      {
        std::cerr << "cdea: " << e.what() << '\n';
        return exit_input_error;
      }
    const std::string h5_path  = p.results_path("_fit");
    const std::string prm_path = p.output.directory + "/" + p.output.base_name + "_fit.prm";
    // The output must be writable, and ours alone (a lock on the .h5 file),
    // before anything is computed.
    OutputLock lock;
    {
      std::string why;
      if (!claim_output(h5_path, lock, why))
        {
          std::cerr << "cdea: cannot write '" << h5_path << "': " << why << '\n';
          return exit_input_error;
        }
    }
    // SIGINT, SIGTERM: the fit stops after its current iteration and writes
    // the values reached (exit code 2).
    const StopOnSignals stop_on_signals;

    const auto start = std::chrono::steady_clock::now();
    std::cout << "cdea " << CDEA_VERSION << " fit: " << data.size() << " points of " << data_file
              << ", " << base.n_rings() << " ring(s); free:";
    for (const auto &f : settings.free)
      std::cout << "  " << label(f);
    std::cout << "\n" << std::setw(5) << "iter" << std::setw(16) << "cost (mm^2)"
              << "  parameters\n";
    SteppingSettings stepping = stepping_settings(p);
    stepping.arc_length       = false;
    stepping.stability_check  = false;
    stepping.breakdown_field  = 0.;
    DisplacementModel model(base, data, settings.free, fe_discretization(p), newton_settings(p),
                            stepping);
    const FitResult   r = fit(base, data, settings, model,
                            [&](unsigned int k, double cost, const std::vector<double> &v) {
                              std::cout << std::setw(5) << k << std::setw(16)
                                        << format_number(cost, 8);
                              for (std::size_t j = 0; j < v.size(); ++j)
                                std::cout << "  " << format_number(shown(settings.free[j], v[j]).first, 8);
                              std::cout << std::endl;
                            });
    std::vector<std::vector<double>> curve_kV;
    std::vector<double>              curve_mm;
    if (r.fitted.size() > 0)
      {
        std::vector<std::vector<double>> v;
        std::vector<double>              d;
        model.curve(r.values, 8, v, d);
        for (std::size_t k = 0; k < v.size(); ++k)
          {
            std::vector<double> kV;
            for (const double x : v[k])
              kV.push_back(x * 1e-3);
            curve_kV.push_back(kV);
            curve_mm.push_back(d[k] * 1e3);
          }
      }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::cout << "\n" << (r.converged ? "Converged" : "NOT converged") << ": " << r.status << "\n"
              << std::left << std::setw(22) << "parameter" << std::right << std::setw(16)
              << "start" << std::setw(16) << "fitted" << std::setw(16) << "std. error"
              << std::setw(10) << "rel." << '\n';
    for (std::size_t j = 0; j < settings.free.size(); ++j)
      {
        const auto [v0, unit] = shown(settings.free[j], r.initial[j]);
        const double v        = shown(settings.free[j], r.values[j]).first;
        const double e        = shown(settings.free[j], r.standard_errors[j]).first;
        std::cout << std::left << std::setw(22) << label(settings.free[j]) + (unit.empty() ? "" : " (" + unit + ")")
                  << std::right << std::setw(16) << format_number(v0, 8) << std::setw(16)
                  << format_number(v, 8) << std::setw(16) << format_number(e, 3) << std::setw(10)
                  << format_number(e / std::abs(v), 2) << '\n';
      }
    if (settings.free.size() > 1)
      {
        std::cout << "correlation:\n";
        for (std::size_t i = 0; i < settings.free.size(); ++i)
          {
            std::cout << "  " << std::left << std::setw(16) << label(settings.free[i]) << std::right;
            for (std::size_t j = 0; j < settings.free.size(); ++j)
              std::cout << std::setw(9) << format_fixed(r.correlation(i, j), 4);
            std::cout << '\n';
          }
      }
    if (r.fitted.size() > 0)
      {
        std::cout << "residuals (model - measured):\n" << std::setw(6) << "point" << std::setw(24)
                  << "voltages (kV)" << std::setw(16) << "measured (mm)" << std::setw(16)
                  << "model (mm)" << std::setw(16) << "residual (mm)" << '\n';
        for (std::size_t i = 0; i < data.size(); ++i)
          std::cout << std::setw(6) << i + 1 << std::setw(24) << format_kV(data.voltages[i], 5)
                    << std::setw(16) << format_fixed(data.displacement[i] * 1e3, 6) << std::setw(16)
                    << format_fixed(r.fitted[i] * 1e3, 6) << std::setw(16)
                    << format_number(r.residuals[i] * 1e3, 3) << '\n';
        std::cout << "weighted rms residual " << format_number(r.rms * 1e3, 4)
                  << " mm, condition number of the scaled Jacobian "
                  << format_number(r.condition, 3) << '\n';
      }
    for (const auto &w : r.warnings)
      std::cout << "WARNING: " << w << '\n';
    std::cout << r.iterations << " iterations, " << r.evaluations << " evaluations, "
              << model.solves() << " equilibrium solves (" << model.ramps() << " ramps), "
              << std::setprecision(3) << seconds << " s\n";

    try
      {
        write_fit_file(h5_path, text, data, settings, r, curve_kV, curve_mm, model.solves());
        if (r.fitted.size() > 0)
          {
            std::vector<ParameterChange> changes;
            for (std::size_t j = 0; j < settings.free.size(); ++j)
              changes.push_back(fitted_entry(settings.free[j], r.values[j]));
            write_changed_parameters(prm_file, prm_path, changes,
                                     "# Written by cdea fit: the parameter file with the fitted "
                                     "values.\n");
          }
      }
    catch (const std::exception &e)
      {
        std::cerr << "cdea: the results cannot be written: " << e.what()
                  << " (older files of this name stay as they were)\n";
        return exit_not_complete;
      }
    std::cout << "wrote " << h5_path << (r.fitted.size() ? " and " + prm_path : "") << '\n';
    if (const int signal = StopOnSignals::requested())
      {
        std::cerr << "cdea: interrupted by " << signal_name(signal) << "; the values reached are in "
                  << h5_path << '\n';
        return exit_not_complete;
      }
    if (!r.converged)
      {
        std::cerr << "cdea: the fit did not converge (" << r.status << "); the last values are in "
                  << h5_path << '\n';
        return exit_not_complete;
      }
    return exit_success;
  }
} // namespace cdea
