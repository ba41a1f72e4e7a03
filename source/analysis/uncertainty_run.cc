// The uncertainty of a quasi-static FE run's answers, linear and Monte-Carlo
// (analysis/uncertainty_run.h).

#include <cdea/analysis/run_setup.h>
#include <cdea/analysis/uncertainty_run.h>
#include <cdea/base/format.h>
#include <cdea/base/progress.h>
#include <cdea/base/run_control.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/sensitivities.h>
#include <cdea/input/solver_settings.h>
#include <cdea/model/quantities_uncertainty.h>

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace cdea
{
  namespace
  {
    namespace q = uncertainty_quantity;

    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// dV_k/dt of the voltage path on the segment that ends at or after @p t.
    std::vector<double> path_rate(const VoltagePath &path, const double t)
    {
      std::vector<std::vector<double>> points = path.waypoints();
      points.insert(points.begin(), std::vector<double>(path.n_rings(), 0.));
      const unsigned int segment =
        std::min<unsigned int>(path.n_segments() - 1, unsigned(std::max(0., std::ceil(t) - 1.)));
      std::vector<double> rate(path.n_rings());
      for (unsigned int k = 0; k < rate.size(); ++k)
        rate[k] = points[segment + 1][k] - points[segment][k];
      return rate;
    }
  } // namespace

  RunAnswers run_answers(const StepSummary &final_step, const RunResult &result)
  {
    RunAnswers a;
    a.completed      = result.completed;
    a.displacement   = final_step.displacement;
    a.stroke         = final_step.stroke;
    a.volume_change  = final_step.columns.get(summary_column::volume_change);
    a.onset          = result.onset.found;
    a.onset_voltages = result.onset.voltages;
    return a;
  }

  LinearRunUncertainty::LinearRunUncertainty(const UncertainConstants &constants,
                                             const Scene              &scene)
    : constants(constants)
    , scene(scene)
  {}

  void LinearRunUncertainty::follow(LoadStepper &stepper, MembraneModel &model)
  {
    stepper.on_step = [this, &model, then = stepper.on_step](const StepSummary &s) {
      if (s.stage == Stage::dead_load && s.load_factor == 1.)
        reference(model);
      if (then)
        then(s);
    };
    stepper.on_onset = [this, &model, then = stepper.on_onset](const OnsetRecord &o) {
      onset(model, o);
      if (then)
        then(o);
    };
    stepper.on_limit_point = [this, &model, then = stepper.on_limit_point](const LimitPoint &l) {
      limit_point(model, l);
      if (then)
        then(l);
    };
  }

  void LinearRunUncertainty::reference(MembraneModel &model)
  {
    const StateSensitivity at(model, constants.parameters);
    reference_displacement = at.d_displacement();
    reference_volume       = at.d_volume();
  }

  std::vector<SceneParameter> LinearRunUncertainty::with_voltages() const
  {
    std::vector<SceneParameter> list = constants.parameters;
    for (unsigned int k = 0; k < scene.n_rings(); ++k)
      list.push_back({ParameterKind::voltage, k});
    return list;
  }

  void LinearRunUncertainty::limit_point(MembraneModel &model, const LimitPoint &limit)
  {
    const Eigen::Index     P = Eigen::Index(constants.parameters.size());
    const Eigen::Index     N = Eigen::Index(scene.n_rings());
    const StateSensitivity at(model, with_voltages());
    const std::vector<double> rate = path_rate(scene.path, limit.load_factor);
    const Eigen::VectorXd     v    = Eigen::Map<const Eigen::VectorXd>(rate.data(), N);
    const Eigen::VectorXd     dR_dt = at.residual_derivative().rightCols(N) * v;
    Eigen::VectorXd           phi   = -(at.state_derivative().rightCols(N) * v);
    phi.normalize();
    limit_gradients.push_back(-(phi.transpose() * at.residual_derivative().leftCols(P)).transpose() /
                              phi.dot(dR_dt));
    limit_rates.push_back(rate);
  }

  void LinearRunUncertainty::onset(MembraneModel &model, const OnsetRecord &onset)
  {
    const std::size_t      P = constants.parameters.size();
    const StateSensitivity at(model, with_voltages());
    const PointValues      points = at.points();
    Eigen::Index           first  = 0; // where s2 vanishes: its smallest value
    points.s2.minCoeff(&first);
    const std::vector<double> rate = path_rate(scene.path, onset.load_factor);
    double                    ds2_dt = 0.;
    for (unsigned int k = 0; k < rate.size(); ++k)
      ds2_dt += points.d_s2(first, Eigen::Index(P + k)) * rate[k];
    const Eigen::VectorXd dt_dp =
      -points.d_s2.row(first).head(Eigen::Index(P)).transpose() / ds2_dt;
    onset_gradients.clear();
    for (const double r : rate)
      onset_gradients.push_back(r * dt_dp);
  }

  ProductGroup LinearRunUncertainty::finish(MembraneModel &model) const
  {
    const StateSensitivity at(model, constants.parameters);
    ProductGroup           g("/summary");
    g.set(q::displacement_std, constants.linear_sd(at.d_displacement()));
    g.set(q::stroke_std, reference_displacement.size() ?
                           constants.linear_sd(at.d_displacement() - reference_displacement) :
                           nan);
    g.set(q::volume_change_std,
          reference_volume.size() ? constants.linear_sd(at.d_volume() - reference_volume) : nan);
    std::vector<double> onset_sd(scene.n_rings(), nan);
    for (std::size_t k = 0; k < onset_gradients.size(); ++k)
      onset_sd[k] = constants.linear_sd(onset_gradients[k]);
    g.set(q::onset_voltage_std, onset_sd);
    std::vector<double> limit_sd;
    for (std::size_t i = 0; i < limit_gradients.size(); ++i)
      for (const double rate : limit_rates[i])
        limit_sd.push_back(std::abs(rate) * constants.linear_sd(limit_gradients[i]));
    g.set(q::limit_point_voltage_std, limit_sd, {limit_gradients.size(), scene.n_rings()});
    return g;
  }

  RunAnswers quiet_run(const RunInput &input, const Scene &scene, ProductGroup *linear_rows)
  {
    const std::unique_ptr<MembraneModel> model = make_fe_model(input.parameters, scene);
    LoadStepper stepper(scene, *model, stepping_settings(input.parameters));
    add_run_postprocessors(stepper, input.parameters, scene);
    StepSummary last;
    stepper.on_step = [&](const StepSummary &s) { last = s; };
    std::optional<LinearRunUncertainty> linear;
    if (linear_rows)
      linear.emplace(input.uncertainty, scene).follow(stepper, *model);
    try
      {
        const RunResult result = stepper.run();
        if (linear && result.completed)
          *linear_rows = linear->finish(*model);
        return run_answers(last, result);
      }
    catch (const std::exception &)
      {
        return {}; // a sample outside the model's range: not completed
      }
  }

  namespace
  {
    /// Statistics of every answer over the completed samples, as rows.
    ProductGroup sample_rows(const std::vector<RunAnswers> &runs, const unsigned int n_rings)
    {
      std::vector<double>              displacement, stroke, volume;
      std::vector<std::vector<double>> onset(n_rings);
      std::size_t                      with_onset = 0;
      for (const RunAnswers &a : runs)
        {
          if (!a.completed)
            continue;
          displacement.push_back(a.displacement);
          stroke.push_back(a.stroke);
          volume.push_back(a.volume_change);
          if (a.onset)
            {
              ++with_onset;
              for (unsigned int k = 0; k < n_rings; ++k)
                onset[k].push_back(a.onset_voltages[k]);
            }
        }
      ProductGroup g("/summary");
      g.set(q::samples, displacement.size()).set(q::onset_samples, with_onset);
      const auto scalar = [&](const std::vector<double> &v, const Quantity &mean,
                              const Quantity &sd, const Quantity &percentiles) {
        const SampleStatistics s = sample_statistics(v);
        g.set(mean, s.mean).set(sd, s.sd).set(percentiles, s.percentiles);
      };
      scalar(displacement, q::displacement_mean, q::displacement_std, q::displacement_percentiles);
      scalar(stroke, q::stroke_mean, q::stroke_std, q::stroke_percentiles);
      scalar(volume, q::volume_change_mean, q::volume_change_std, q::volume_change_percentiles);
      std::vector<double> mean(n_rings), sd(n_rings), percentiles(3 * n_rings);
      for (unsigned int k = 0; k < n_rings; ++k)
        {
          const SampleStatistics s = sample_statistics(onset[k]);
          mean[k]                  = s.mean;
          sd[k]                    = s.sd;
          for (std::size_t i = 0; i < 3; ++i)
            percentiles[i * n_rings + k] = s.percentiles[i];
        }
      g.set(q::onset_voltage_mean, mean)
        .set(q::onset_voltage_std, sd)
        .set(q::onset_voltage_percentiles, percentiles, {3, n_rings});
      return g;
    }
  } // namespace

  ProductGroup monte_carlo_run(const RunInput &input, const UncertainConstants &constants,
                               const bool show_progress)
  {
    const Eigen::MatrixXd values =
      sample_constants(constants, input.scene, constants.samples, constants.seed);
    std::vector<RunAnswers> runs;
    Progress                progress(constants.samples, show_progress, "samples");
    for (unsigned int i = 0; i < constants.samples && !StopOnSignals::requested(); ++i)
      {
        const Eigen::VectorXd p = values.row(i).transpose();
        runs.push_back(quiet_run(input, with_constants(input.scene, constants, p)));
        progress.add(1);
      }
    progress.finish();
    return sample_rows(runs, input.scene.n_rings());
  }

  std::string uncertainty_report(const UncertainConstants &constants, const ProductGroup &rows)
  {
    std::ostringstream o;
    std::string        names;
    for (const std::string &n : constants.names)
      names += (names.empty() ? "" : ", ") + n;
    o << "Uncertainty (" << to_string(constants.mode) << ", one standard deviation; " << names
      << "):";
    const ProductEntry *samples = rows.find(q::samples);
    if (samples)
      o << ' ' << samples->values[0] << " of " << constants.samples << " samples completed, "
        << rows.at(q::onset_samples).values[0] << " with an onset";
    o << '\n';
    // Each answer: its sd, and of Monte-Carlo the mean and percentiles, per ring for the onset.
    const auto line = [&](const char *what, const Quantity &sd, const Quantity &mean,
                          const Quantity &percentiles) {
      const ProductEntry &e = rows.at(sd);
      const std::size_t   n = e.size();
      for (std::size_t k = 0; k < n; ++k)
        {
          o << "  " << what << (n > 1 ? " (ring " + std::to_string(k + 1) + ")" : "") << ": ";
          if (std::isnan(e.values[k]))
            {
              o << "-\n";
              continue;
            }
          o << "sd " << format_number(e.value(k), 4) << ' ' << sd.unit.name;
          if (const ProductEntry *m = rows.find(mean))
            o << ", mean " << format_number(m->value(k), 7);
          if (const ProductEntry *p = rows.find(percentiles))
            o << ", 5/50/95 % " << format_number(p->value(k), 6) << " / "
              << format_number(p->value(n + k), 6) << " / " << format_number(p->value(2 * n + k), 6);
          o << '\n';
        }
    };
    line("displacement", q::displacement_std, q::displacement_mean, q::displacement_percentiles);
    line("stroke", q::stroke_std, q::stroke_mean, q::stroke_percentiles);
    line("volume change", q::volume_change_std, q::volume_change_mean,
         q::volume_change_percentiles);
    line("onset voltage", q::onset_voltage_std, q::onset_voltage_mean,
         q::onset_voltage_percentiles);
    if (const ProductEntry *limits = rows.find(q::limit_point_voltage_std))
      for (std::size_t i = 0; limits->dims.size() == 2 && i < limits->dims[0]; ++i)
        {
          o << "  limit point " << i + 1 << " voltage: sd";
          for (std::size_t k = 0; k < limits->dims[1]; ++k)
            o << ' ' << format_number(limits->value(i * limits->dims[1] + k), 4);
          o << " kV\n";
        }
    return o.str();
  }
} // namespace cdea
