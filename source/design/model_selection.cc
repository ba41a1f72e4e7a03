// Model selection for material tests (model_selection.h): the candidates
// parsed and set up, each fitted on all files and once per file left out,
// and the recommendation.

#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/design/model_selection.h>
#include <cdea/input/parameters.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/two_network_gent.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    const std::string candidate_entry = "Calibration/Candidate models";
    /// The law network B's branches stand beside, and the law with them
    /// (two_network_gent.h: network A is the film's Gent law).
    const std::string network_a_law = "elastic", viscous_law = "viscoelastic";

    std::string allowed_candidates()
    {
      std::string laws;
      for (const std::string &name : MembraneLaws::names())
        if (name != viscous_law)
          laws += (laws.empty() ? "" : ", ") + name;
      return "each item 'LAW N': LAW a Material/Model without internal variables (" + laws +
             "), N the number of viscous branches, 0 to " + std::to_string(max_viscous_branches) +
             ", above 0 with " + network_a_law + " (network A's Gent law) only; e.g. '" +
             network_a_law + " 0, " + network_a_law + " 1, " + network_a_law + " 2'";
    }

    /// One item "LAW N" of the entry.
    CandidateModel candidate_item(const std::string &item)
    {
      const std::vector<std::string> words = split_list(trim_blanks(item), ' ');
      std::vector<std::string>       fields;
      for (const std::string &w : words)
        if (!trim_blanks(w).empty())
          fields.push_back(trim_blanks(w));
      const std::string bad = candidate_entry + ": '" + trim_blanks(item) + "' ";
      if (fields.size() != 2)
        throw InputError(bad + "is not 'LAW N' (" + allowed_candidates() + ")");
      const std::vector<std::string> laws = MembraneLaws::names();
      CandidateModel                 c;
      c.law = fields[0];
      if (std::find(laws.begin(), laws.end(), c.law) == laws.end() || c.law == viscous_law)
        throw InputError(bad + "does not name a law without internal variables (" +
                         allowed_candidates() + ")");
      const std::string &n = fields[1];
      if (n.empty() || n.size() > 3 || !std::all_of(n.begin(), n.end(), ::isdigit) ||
          std::stoul(n) > max_viscous_branches)
        throw InputError(bad + "has no branch count from 0 to " +
                         std::to_string(max_viscous_branches) + " (" + allowed_candidates() + ")");
      c.branches = static_cast<unsigned int>(std::stoul(n));
      if (c.branches > 0 && c.law != network_a_law)
        throw InputError(bad + "puts branches beside " + c.law + ": the viscous branches stand "
                         "beside network A's Gent law only (" + allowed_candidates() + ")");
      return c;
    }

    /// The same value @p value, @p n times: "v, v, v".
    std::string repeated(const std::string &value, const unsigned int n)
    {
      std::string list;
      for (unsigned int k = 0; k < n; ++k)
        list += (k ? ", " : "") + value;
      return list;
    }
  } // namespace

  std::vector<CandidateModel> candidate_models(const std::string &text)
  {
    std::vector<CandidateModel> out;
    if (trim_blanks(text).empty())
      return out;
    for (const std::string &item : split_list(text, ','))
      {
        const CandidateModel c = candidate_item(item);
        for (const CandidateModel &o : out)
          if (o.name() == c.name())
            throw InputError(candidate_entry + ": '" + c.name() + "' is given twice");
        out.push_back(c);
      }
    return out;
  }

  CandidateSetup candidate_setup(const ParameterInput &input, const CandidateModel &candidate)
  {
    try
      {
        ParameterInput elastic = input;
        elastic.overrides.push_back({"Material/Model", candidate.law});
        const Parameters pe  = read_parameters(elastic);
        const auto       law = pe.scene().law();
        // The law's own constants, then every branch's.
        std::string free = "shear modulus";
        if (law->depends_on(LawParameter::jlim))
          free += ", Jlim";
        for (const LawConstant &c : law->own_constants())
          free += ", " + c.entry;
        ParameterInput in = elastic;
        if (candidate.branches > 0)
          {
            // Placeholders: the fit starts from values made from the data.
            const unsigned int n = candidate.branches;
            in.overrides.push_back({"Material/Model", viscous_law});
            in.overrides.push_back({"Time/Enabled", "true"});
            in.overrides.push_back({"Material/Branch shear moduli (kPa)",
                                    repeated(format_number(pe.material.shear_modulus_kPa), n)});
            in.overrides.push_back({"Material/Branch relaxation times (s)", repeated("1", n)});
            in.overrides.push_back({"Material/Branch Jlim", ""});
            for (unsigned int k = 1; k <= n; ++k)
              free += ", " + branch_constant_entry(k, false) + ", " + branch_constant_entry(k, true);
          }
        in.overrides.push_back({"Calibration/Free parameters", free});
        const Parameters p = read_parameters(in);
        return {candidate, p.scene(), free_parameter_settings(p),
                {in.overrides.begin() + std::ptrdiff_t(input.overrides.size()),
                 in.overrides.end()}};
      }
    catch (const InputError &e)
      {
        throw InputError(candidate_entry + ": model '" + candidate.name() + "': " + e.what());
      }
  }

  namespace
  {
    using Progress = std::function<void(const std::string &, const std::string &, const FitResult &)>;

    std::size_t samples_of(const std::vector<MaterialTestData> &tests)
    {
      std::size_t n = 0;
      for (const MaterialTestData &t : tests)
        n += t.size();
      return n;
    }

    /// sum w r^2 (Pa^2) of a fit to @p tests, w the test's weight times the row's.
    double weighted_rss(const FitResult &r, const std::vector<MaterialTestData> &tests,
                        const std::vector<double> &weights)
    {
      if (!r.started || r.residuals.size() != Eigen::Index(samples_of(tests)))
        return nan;
      double       sum = 0.;
      Eigen::Index row = 0;
      for (std::size_t k = 0; k < tests.size(); ++k)
        for (std::size_t i = 0; i < tests[k].size(); ++i, ++row)
          sum += (weights.empty() ? 1. : weights[k]) * tests[k].weight[i] *
                 r.residuals[row] * r.residuals[row];
      return sum;
    }

    /// Measures that could not be computed: the file's name and samples, NaN.
    TestMeasures not_computed(const MaterialTestData &t)
    {
      TestMeasures m;
      m.name    = t.name;
      m.samples = t.size();
      m.rms = m.largest = m.relative = nan;
      return m;
    }

    /// Test @p i predicted by the candidate fitted to the other tests.
    TestMeasures held_out_measures(const CandidateSetup &s, const std::vector<MaterialTestData> &tests,
                                   const std::vector<double> &weights, const std::size_t i,
                                   const MaterialFitSettings &settings, const Progress &progress,
                                   std::vector<std::string> &warnings)
    {
      MaterialFitSettings           fs = settings;
      std::vector<MaterialTestData> others;
      fs.fit = s.fit;
      fs.test_weights.clear();
      for (std::size_t j = 0; j < tests.size(); ++j)
        if (j != i)
          {
            others.push_back(tests[j]);
            fs.test_weights.push_back(weights.empty() ? 1. : weights[j]);
          }
      if (others.empty() || samples_of(others) < s.fit.free.size())
        return not_computed(tests[i]);
      const MaterialFitResult r = fit_material_tests(s.base, others, fs);
      if (progress)
        progress(s.candidate.name(), tests[i].name, r.fit);
      const std::string about = s.candidate.name() + " without " + tests[i].name + ": ";
      if (!r.fit.started)
        {
          warnings.push_back(about + "the fit could not start: " + r.fit.status);
          return not_computed(tests[i]);
        }
      const MaterialTestModel model(s.base, {tests[i]}, s.fit.free, settings.point);
      Eigen::VectorXd         stress;
      std::string             why;
      if (!model.evaluate(r.fit.values, stress, nullptr, &why))
        {
          warnings.push_back(about + why);
          return not_computed(tests[i]);
        }
      return test_measures(model, stress).front();
    }

    ModelAssessment assess(const CandidateSetup &s, const std::vector<MaterialTestData> &tests,
                           const std::vector<double> &weights, const MaterialFitSettings &settings,
                           const Progress &progress, std::vector<std::string> &warnings)
    {
      ModelAssessment m;
      m.setup               = s;
      MaterialFitSettings fs = settings;
      fs.fit                = s.fit;
      fs.test_weights       = weights;
      m.fit                 = fit_material_tests(s.base, tests, fs);
      if (progress)
        progress(s.candidate.name(), "", m.fit.fit);
      if (!m.fit.fit.started)
        warnings.push_back(s.candidate.name() + ": the fit could not start: " + m.fit.fit.status);
      m.samples        = samples_of(tests);
      m.rss            = weighted_rss(m.fit.fit, tests, weights);
      const double n   = double(m.samples), k = double(s.fit.free.size());
      const double fit = n * std::log(units::kPa2.from_si(m.rss) / n);
      m.aic            = fit + 2. * k;
      m.bic            = fit + k * std::log(n);
      double sum       = 0.;
      for (std::size_t i = 0; i < tests.size(); ++i)
        {
          m.held_out.push_back(tests.size() > 1 ?
                                 held_out_measures(s, tests, weights, i, settings, progress, warnings) :
                                 not_computed(tests[i]));
          sum += m.held_out.back().relative;
        }
      m.held_out_error = sum / double(tests.size());
      return m;
    }
  } // namespace

  ModelSelection select_model(const std::vector<CandidateSetup> &setups,
                              const std::vector<MaterialTestData> &tests,
                              const std::vector<double> &weights, const MaterialFitSettings &settings,
                              const Progress &progress)
  {
    ModelSelection out;
    for (const CandidateSetup &s : setups)
      out.models.push_back(assess(s, tests, weights, settings, progress, out.warnings));
    recommend(out);
    return out;
  }

  namespace
  {
    /// The indices of @p models ordered by @p measure, NaN last.
    template <typename Measure>
    std::vector<std::size_t> ranked(const std::vector<ModelAssessment> &models, const Measure &measure)
    {
      std::vector<std::size_t> order(models.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double x = measure(models[a]), y = measure(models[b]);
        return std::isnan(y) ? !std::isnan(x) : x < y;
      });
      return order;
    }

    /// The sampling error of a model's held-out error E = mean_i e_i over
    /// m files: an rms e of n Gaussian residuals varies by e / sqrt(2 n), so
    /// SE(E)^2 = sum_i e_i^2 / (2 n_i) / m^2.
    double sampling_error(const ModelAssessment &a)
    {
      double sum = 0.;
      for (const TestMeasures &t : a.held_out)
        sum += t.relative * t.relative / (2. * double(t.samples));
      return std::sqrt(sum) / double(a.held_out.size());
    }

    /// The spread of two models' held-out errors: the larger of their
    /// sampling errors combined, sqrt(SE_a^2 + SE_b^2), and the standard
    /// error over the files of their paired differences (with two files or more).
    double difference_spread(const ModelAssessment &a, const ModelAssessment &b)
    {
      const std::size_t   m = a.held_out.size();
      std::vector<double> d;
      for (std::size_t i = 0; i < m; ++i)
        d.push_back(b.held_out[i].relative - a.held_out[i].relative);
      const double mean = std::accumulate(d.begin(), d.end(), 0.) / double(m);
      double       sum  = 0.;
      for (const double x : d)
        sum += (x - mean) * (x - mean);
      return std::max(std::hypot(sampling_error(a), sampling_error(b)),
                      m > 1 ? std::sqrt(sum / double(m - 1) / double(m)) : 0.);
    }
  } // namespace

  void recommend(ModelSelection &s)
  {
    const auto error = [](const ModelAssessment &m) { return m.held_out_error; };
    const auto bic   = [](const ModelAssessment &m) { return m.bic; };
    const std::vector<std::size_t> by_error = ranked(s.models, error);
    s.decided = false;
    s.spread  = nan;
    if (by_error.empty())
      return;
    if (std::isnan(s.models[by_error.front()].held_out_error))
      {
        s.recommended = ranked(s.models, bic).front();
        s.verdict     = "the held-out error cannot be computed (" +
                    std::string(s.models.front().held_out.size() == 1 ?
                                  "one file: nothing is left to predict" :
                                  "no model predicted every file left out") +
                    "), so the data cannot decide; the lowest BIC is " +
                    s.models[s.recommended].setup.candidate.name();
        return;
      }
    s.recommended              = by_error.front();
    const ModelAssessment &best = s.models[s.recommended];
    const std::string      held = "held-out error " + format_number(best.held_out_error, 3);
    if (by_error.size() == 1 || std::isnan(s.models[by_error[1]].held_out_error))
      {
        s.verdict = best.setup.candidate.name() + " (" + held +
                    "): the only model with a held-out error, nothing to compare";
        return;
      }
    const ModelAssessment &next = s.models[by_error[1]];
    const double           gap  = next.held_out_error - best.held_out_error;
    s.spread                    = difference_spread(best, next);
    s.decided                   = gap > s.spread;
    // Undecided: the simpler of the two (fewer constants, then fewer
    // branches, then the lower BIC), as a richer model the data cannot
    // support only adds uncertain constants.
    const auto simpler = [&](const ModelAssessment &a, const ModelAssessment &b) {
      return std::make_tuple(a.setup.fit.free.size(), a.setup.candidate.branches, a.bic) <
             std::make_tuple(b.setup.fit.free.size(), b.setup.candidate.branches, b.bic);
    };
    if (!s.decided && simpler(next, best))
      s.recommended = by_error[1];
    const std::string versus    = next.setup.candidate.name() + " (" +
                               format_number(next.held_out_error, 3) + ") by " +
                               format_number(gap, 3) + ", spread " + format_number(s.spread, 2);
    s.verdict = s.decided ? best.setup.candidate.name() + " (" + held + ") is better than " + versus :
                            "the data cannot decide between " + best.setup.candidate.name() + " (" +
                              held + ") and " + versus + " (the difference is within the spread; "
                              "the lowest BIC is " +
                              s.models[ranked(s.models, bic).front()].setup.candidate.name() +
                              "); recommended: the simpler, " +
                              s.models[s.recommended].setup.candidate.name();
  }
} // namespace cdea
