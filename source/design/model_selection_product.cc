// The product of a model selection (model_selection.h,
// model/quantities_model_selection.h): the verdict, one row per candidate,
// the files and every model's constants, in SI.

#include <cdea/design/model_selection.h>
#include <cdea/model/quantities_material_fit.h>
#include <cdea/model/quantities_model_selection.h>

namespace cdea
{
  namespace
  {
    /// Per model and file (model-major) the measures of @p which.
    template <typename Measure>
    std::vector<double> per_model_and_file(const ModelSelection &s, const Measure &which)
    {
      std::vector<double> out;
      for (const ModelAssessment &m : s.models)
        for (std::size_t i = 0; i < m.held_out.size(); ++i)
          out.push_back(which(m, i));
      return out;
    }

    /// Measures of file @p i in the fit on every file (NaN if it did not start).
    const TestMeasures *all_files(const ModelAssessment &m, std::size_t i)
    {
      return i < m.fit.tests.size() ? &m.fit.tests[i] : nullptr;
    }

    /// /tests: each file's name, kind and samples.
    void set_files(ProductGroup &group, const std::vector<MaterialTestData> &tests)
    {
      std::vector<std::string> files, kinds;
      std::vector<double>      samples;
      for (const MaterialTestData &t : tests)
        {
          files.push_back(t.name);
          kinds.push_back(test_kind_name(t.history.kind));
          samples.push_back(double(t.size()));
        }
      group.set(material_fit_quantity::file, files)
        .set(material_fit_quantity::kind, kinds)
        .set(material_fit_quantity::samples, samples);
    }
  } // namespace

  Product model_selection_product(const ModelSelection                &s,
                                  const std::vector<MaterialTestData> &tests)
  {
    namespace q = model_selection_quantity;
    Product product;
    product.root()
      .set(q::recommended, s.models.empty() ? "" : s.models[s.recommended].setup.candidate.name())
      .set(q::decided, s.decided ? 1 : 0)
      .set(q::verdict, s.verdict)
      .set(q::spread, s.spread);
    std::vector<std::string> names, laws, constant_names;
    std::vector<double> branches, constants, samples, converged, rss, aic, bic, held_out;
    std::vector<double> constant_model, value, error;
    for (std::size_t k = 0; k < s.models.size(); ++k)
      {
        const ModelAssessment &m = s.models[k];
        names.push_back(m.setup.candidate.name());
        laws.push_back(m.setup.candidate.law);
        branches.push_back(m.setup.candidate.branches);
        constants.push_back(double(m.setup.fit.free.size()));
        samples.push_back(double(m.samples));
        converged.push_back(m.fit.fit.converged ? 1. : 0.);
        rss.push_back(m.rss);
        aic.push_back(m.aic);
        bic.push_back(m.bic);
        held_out.push_back(m.held_out_error);
        for (std::size_t j = 0; j < m.setup.fit.free.size(); ++j)
          {
            constant_model.push_back(double(k));
            constant_names.push_back(label(m.setup.fit.free[j]));
            const bool fitted = j < m.fit.fit.standard_errors.size();
            value.push_back(j < m.fit.fit.values.size() ? m.fit.fit.values[j] : NAN);
            error.push_back(fitted ? m.fit.fit.standard_errors[j] : NAN);
          }
      }
    const std::vector<std::size_t> by_file{s.models.size(), tests.size()};
    const auto measure = [&](auto field) {
      return per_model_and_file(s, [&](const ModelAssessment &m, std::size_t i) {
        const TestMeasures *t = all_files(m, i);
        return t ? field(*t) : NAN;
      });
    };
    product.group("/models")
      .set(q::model, names)
      .set(q::law, laws)
      .set(q::branches, branches)
      .set(q::constants, constants)
      .set(q::samples, samples)
      .set(q::converged, converged)
      .set(q::rss, rss)
      .set(q::aic, aic)
      .set(q::bic, bic)
      .set(q::held_out_error, held_out)
      .set(q::rms, measure([](const TestMeasures &t) { return t.rms; }), by_file)
      .set(q::relative_rms, measure([](const TestMeasures &t) { return t.relative; }), by_file)
      .set(q::held_out_rms,
           per_model_and_file(s, [](const ModelAssessment &m, std::size_t i) {
             return m.held_out[i].rms;
           }),
           by_file)
      .set(q::held_out_relative_rms,
           per_model_and_file(s, [](const ModelAssessment &m, std::size_t i) {
             return m.held_out[i].relative;
           }),
           by_file);
    set_files(product.group("/tests"), tests);
    product.group("/constants")
      .set(q::constant_model, constant_model)
      .set(q::constant_name, constant_names)
      .set(q::value, value)
      .set(q::standard_error, error);
    return product;
  }
} // namespace cdea
