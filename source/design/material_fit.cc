// The material-test fit (material_fit.h): the model of every test's
// stresses with its Jacobian, the measures per test, and the least squares
// from several starts (design/fit.cc's fit_observations()).

#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/design/material_fit.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/material/two_network_gent.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cdea
{
  MaterialTestModel::MaterialTestModel(const Scene &base_in, const std::vector<MaterialTestData> &tests,
                                       const std::vector<SceneParameter> &free_in,
                                       const MaterialPointSettings       &settings_in)
    : base(base_in)
    , data(tests)
    , free(free_in)
    , settings(settings_in)
    , offsets{0}
  {
    for (const SceneParameter &p : free)
      {
        if (p.kind != ParameterKind::shear_modulus && p.kind != ParameterKind::jlim &&
            p.kind != ParameterKind::law_constant)
          throw InputError("a material test depends on the film's law only: '" + label(p) +
                           "' cannot be fitted to it (shear modulus, Jlim or a constant of "
                           "Material/Model)");
        law_parameters.push_back(law_parameter_of(base, p));
      }
    for (const MaterialTestData &t : data)
      offsets.push_back(offsets.back() + t.size());
  }

  bool MaterialTestModel::evaluate(const std::vector<double> &values, Eigen::VectorXd &stress,
                                   Eigen::MatrixXd *jacobian, std::string *message) const
  {
    std::shared_ptr<const MembraneLaw> law;
    try
      {
        law = scene_with(base, free, values).law();
      }
    catch (const InputError &e)
      {
        if (message)
          *message = e.what();
        return false;
      }
    stress.resize(Eigen::Index(size()));
    if (jacobian)
      jacobian->resize(Eigen::Index(size()), Eigen::Index(free.size()));
    MaterialPoint        point(*law, settings);
    MaterialPointResult  r;
    const std::vector<LawParameter> none;
    for (std::size_t k = 0; k < data.size(); ++k)
      {
        std::string why;
        if (!point.run(data[k].history, jacobian ? law_parameters : none, r, why))
          {
            if (message)
              {
                const std::size_t i = std::min(r.failed_sample, data[k].size() - 1);
                *message = data[k].name + ", line " + std::to_string(data[k].lines[i]) +
                           ": the model cannot follow the test there: " + why;
              }
            return false;
          }
        const Eigen::Index first = Eigen::Index(offsets[k]), n = Eigen::Index(data[k].size());
        stress.segment(first, n) = Eigen::Map<const Eigen::VectorXd>(r.stress.data(), n);
        if (jacobian)
          jacobian->middleRows(first, n) = r.jacobian;
      }
    return true;
  }

  std::vector<TestMeasures> test_measures(const MaterialTestModel &model,
                                          const Eigen::VectorXd   &stress)
  {
    std::vector<TestMeasures> out;
    for (std::size_t k = 0; k < model.tests().size(); ++k)
      {
        const MaterialTestData &t = model.tests()[k];
        TestMeasures            m;
        m.name    = t.name;
        m.samples = t.size();
        double sum = 0., sum_w = 0.;
        for (std::size_t i = 0; i < t.size(); ++i)
          {
            const double r = stress[Eigen::Index(model.offset(k) + i)] - t.stress[i];
            sum += t.weight[i] * r * r;
            sum_w += t.weight[i];
            m.largest = std::max(m.largest, std::abs(t.stress[i]));
          }
        m.rms      = std::sqrt(sum / sum_w);
        m.relative = m.largest > 0. ? m.rms / m.largest : std::numeric_limits<double>::infinity();
        out.push_back(m);
      }
    return out;
  }

  namespace
  {
    /// Residuals in kPa, each sample weighted by its test's and its row's weight.
    FitObservations observations(const std::vector<MaterialTestData> &tests,
                                 const std::vector<double>           &test_weights)
    {
      std::size_t n = 0;
      for (const MaterialTestData &t : tests)
        n += t.size();
      FitObservations o;
      o.unit = 1e3;
      o.measured.resize(Eigen::Index(n));
      o.weight.resize(Eigen::Index(n));
      Eigen::Index row = 0;
      for (std::size_t k = 0; k < tests.size(); ++k)
        for (std::size_t i = 0; i < tests[k].size(); ++i, ++row)
          {
            o.measured[row] = tests[k].stress[i];
            o.weight[row] = (test_weights.empty() ? 1. : test_weights.at(k)) * tests[k].weight[i];
          }
      return o;
    }

    /// The relaxation times a fit keeps the branches in: from a hundredth of
    /// the shortest sample interval to a hundred times the longest test.
    FitSettings windowed(const Scene &base, const std::vector<MaterialTestData> &tests,
                         const FitSettings &settings)
    {
      double shortest = HUGE_VAL, longest = 0.;
      for (const MaterialTestData &t : tests)
        {
          const std::vector<double> &time = t.history.time;
          for (std::size_t i = 1; i < time.size(); ++i)
            shortest = std::min(shortest, time[i] - time[i - 1]);
          longest = std::max(longest, time.back() - time.front());
        }
      if (!std::isfinite(shortest) || !(longest > 0.))
        return settings;
      return relaxation_time_window(base, settings, 1e-2 * shortest, 1e2 * longest);
    }

    /// @p values with the branches whose modulus and relaxation time are both
    /// free reordered so that their relaxation times increase with the branch
    /// number (branches of equal springs are interchangeable: the same
    /// film); empty if they are in order or cannot be exchanged.
    std::vector<double> branches_in_order(const Scene &base, const std::vector<SceneParameter> &free,
                                          const std::vector<double> &values)
    {
      const auto *film = dynamic_cast<const TwoNetworkGentLaw *>(base.law().get());
      if (!film)
        return {};
      std::vector<std::pair<int, int>> pairs; // (modulus, time) positions in free
      for (unsigned int k = 1; k <= film->n_branches(); ++k)
        {
          std::pair<int, int> at{-1, -1};
          for (std::size_t j = 0; j < free.size(); ++j)
            for (const bool time : {false, true})
              if (free[j].kind == ParameterKind::law_constant && free[j].entry == branch_constant_entry(k, time))
                (time ? at.second : at.first) = int(j);
          if (at.first >= 0 && at.second >= 0 &&
              film->branches()[k - 1].jlim == film->branches().front().jlim)
            pairs.push_back(at);
        }
      std::vector<std::pair<int, int>> sorted = pairs;
      std::sort(sorted.begin(), sorted.end(), [&](const auto &a, const auto &b) {
        return values[std::size_t(a.second)] < values[std::size_t(b.second)];
      });
      if (sorted == pairs)
        return {};
      std::vector<double> out = values;
      for (std::size_t i = 0; i < pairs.size(); ++i)
        {
          out[std::size_t(pairs[i].first)]  = values[std::size_t(sorted[i].first)];
          out[std::size_t(pairs[i].second)] = values[std::size_t(sorted[i].second)];
        }
      return out;
    }

    /// sum w r^2 of a fit in the observations' unit.
    double cost(const FitResult &r, const FitObservations &o)
    {
      if (!r.started || r.residuals.size() != o.measured.size())
        return std::numeric_limits<double>::quiet_NaN();
      return (o.weight.array() * (r.residuals.array() / o.unit).square()).sum();
    }
  } // namespace

  MaterialFitResult fit_material_tests(
    const Scene &base, const std::vector<MaterialTestData> &tests,
    const MaterialFitSettings                                                    &settings,
    const std::function<void(unsigned int, double, const std::vector<double> &)> &progress)
  {
    if (!settings.test_weights.empty() && settings.test_weights.size() != tests.size())
      throw std::invalid_argument("fit_material_tests: one weight per test");
    const FitSettings       bounded = windowed(base, tests, settings.fit);
    const MaterialTestModel model(base, tests, settings.fit.free, settings.point);
    const FitObservations   data = observations(tests, settings.test_weights);
    const FitFunction       function = [&model](const std::vector<double> &v, Eigen::VectorXd &s,
                                          Eigen::MatrixXd *J, std::string *message) {
      return model.evaluate(v, s, J, message);
    };
    MaterialFitResult out;
    if (settings.starts == 0)
      {
        std::vector<double> own;
        for (const SceneParameter &p : settings.fit.free)
          own.push_back(parameter_value(base, p));
        out.starts.push_back(own);
      }
    else
      out.starts = material_test_starts(base, tests, settings.fit.free, settings.starts);
    // Screening: every start for a few iterations, the best one on.
    FitSettings screening = bounded;
    if (out.starts.size() > 1)
      screening.max_iterations = std::min(bounded.max_iterations, settings.screening_iterations);
    double best = HUGE_VAL;
    for (std::size_t s = 0; s < out.starts.size(); ++s)
      {
        FitResult r = fit_observations(scene_with(base, settings.fit.free, out.starts[s]), data,
                                       screening, function, progress);
        out.evaluations += r.evaluations;
        out.costs.push_back(cost(r, data));
        if (s == 0 || out.costs[s] < best)
          {
            best     = std::isnan(out.costs[s]) ? HUGE_VAL : out.costs[s];
            out.best = s;
            out.fit  = std::move(r);
          }
      }
    if (out.fit.started && !out.fit.converged && screening.max_iterations < bounded.max_iterations)
      {
        const unsigned int screened = out.fit.iterations;
        out.fit = fit_observations(scene_with(base, settings.fit.free, out.fit.values), data, bounded,
                                   function, progress);
        out.evaluations += out.fit.evaluations;
        out.fit.iterations += screened;
        out.fit.initial = out.starts[out.best];
        best            = cost(out.fit, data);
      }
    // The same film with its branches in the order of their relaxation
    // times: one more fit from there (converged at once) gives its errors.
    if (const auto ordered = branches_in_order(base, settings.fit.free, out.fit.values);
        out.fit.started && !ordered.empty())
      {
        FitResult r = fit_observations(scene_with(base, settings.fit.free, ordered), data, bounded,
                                       function, progress);
        out.evaluations += r.evaluations;
        if (cost(r, data) <= best * (1. + 1e-9))
          out.fit = std::move(r);
      }
    if (out.fit.fitted.size() == Eigen::Index(model.size()))
      out.tests = test_measures(model, out.fit.fitted);
    return out;
  }
} // namespace cdea

namespace cdea
{
  namespace
  {
    /// The outcome of the tests of @p model for its stresses @p stress (Pa,
    /// the tests' samples one after the other); @p tests are the caller's
    /// data the model was made from (it holds copies).
    void add_outcomes(const MaterialTestModel &model, const Eigen::VectorXd &stress,
                      const MaterialTestData *tests, const std::vector<double> &weights,
                      const bool fitted, std::vector<MaterialTestOutcome> &out)
    {
      const std::vector<TestMeasures> measures = test_measures(model, stress);
      for (std::size_t k = 0; k < model.tests().size(); ++k)
        {
          MaterialTestOutcome o;
          o.data     = &tests[k];
          o.weight   = weights.empty() ? 1. : weights[k];
          o.fitted   = fitted;
          o.measures = measures[k];
          const double *first = stress.data() + model.offset(k);
          o.model.assign(first, first + o.data->size());
          out.push_back(std::move(o));
        }
    }
  } // namespace

  std::vector<MaterialTestOutcome> material_test_outcomes(
    const Scene &base, const std::vector<SceneParameter> &free, const MaterialFitResult &r,
    const std::vector<MaterialTestData> &fitted, const std::vector<double> &weights,
    const std::vector<MaterialTestData> &predicted, std::vector<std::string> &warnings)
  {
    std::vector<MaterialTestOutcome> out;
    const MaterialTestModel          fitted_model(base, fitted, free);
    Eigen::VectorXd                  stress = r.fit.fitted;
    if (stress.size() != Eigen::Index(fitted_model.size()) &&
        !fitted_model.evaluate(r.fit.values, stress, nullptr))
      stress = Eigen::VectorXd::Constant(Eigen::Index(fitted_model.size()),
                                         std::numeric_limits<double>::quiet_NaN());
    add_outcomes(fitted_model, stress, fitted.data(), weights, true, out);
    // Each predicted file alone: one the model cannot follow spoils no other.
    for (const MaterialTestData &t : predicted)
      {
        const MaterialTestModel model(base, {t}, free);
        Eigen::VectorXd         predicted_stress;
        std::string             why;
        if (!model.evaluate(r.fit.values, predicted_stress, nullptr, &why))
          {
            warnings.push_back("--predict " + t.name + ": " + why);
            predicted_stress = Eigen::VectorXd::Constant(Eigen::Index(t.size()),
                                               std::numeric_limits<double>::quiet_NaN());
          }
        add_outcomes(model, predicted_stress, &t, {}, false, out);
      }
    return out;
  }
} // namespace cdea
