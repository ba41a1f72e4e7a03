// What `cdea fit` returns and writes: the product of each kind of data
// (<Base name>_fit.h5) and the fitted entries of <Base name>_fit.prm.

#include <cdea/base/format.h>
#include <cdea/design/fit.h>
#include <cdea/design/material_fit.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/model/quantities_common.h>
#include <cdea/model/quantities_fit.h>
#include <cdea/model/quantities_material_fit.h>

#ifndef CDEA_VERSION
#  define CDEA_VERSION "unknown"
#endif

namespace cdea
{
  ParameterChange fitted_entry(const SceneParameter &p, const double value)
  {
    switch (p.kind)
      {
        case ParameterKind::shear_modulus:
          return {"Material", "Shear modulus (kPa)", exact_number(units::kPa.from_si(value))};
        case ParameterKind::jlim:
          return {"Material", "Jlim", exact_number(value)};
        case ParameterKind::permittivity:
          return {"Material", "Permittivity (F/m)", exact_number(value)};
        case ParameterKind::mass:
          return {"Loading", "Mass (g)", exact_number(units::g.from_si(value))};
        case ParameterKind::prestretch:
          return {"Geometry", "Prestretch", exact_number(value)};
        case ParameterKind::law_constant:
          return {"Material", p.entry, exact_number(value)};
        default:
          throw std::invalid_argument("fitted_entry: " + p.name() + " is not a fit parameter");
      }
  }

  std::vector<ParameterChange> fitted_entries(const Scene &base,
                                              const std::vector<SceneParameter> &free,
                                              const std::vector<double>         &values)
  {
    std::vector<ParameterChange> changes;
    bool                         branches = false;
    for (std::size_t j = 0; j < free.size(); ++j)
      {
        const bool branch = free[j].kind == ParameterKind::law_constant &&
                            free[j].entry.compare(0, 7, "Branch ") == 0;
        branches = branches || branch;
        if (!branch)
          changes.push_back(fitted_entry(free[j], values[j]));
      }
    if (!branches)
      return changes;
    // The lists hold every branch: the fitted law's moduli (kPa) and times.
    const auto law = scene_with(base, free, values).law();
    const auto *film = dynamic_cast<const TwoNetworkGentLaw *>(law.get());
    if (!film)
      throw std::invalid_argument("fitted_entries: branch constants of a law without branches");
    std::string moduli, times;
    for (const ViscousNetwork &b : film->branches())
      {
        moduli += (moduli.empty() ? "" : ", ") + exact_number(units::kPa.from_si(b.shear_modulus));
        times += (times.empty() ? "" : ", ") + exact_number(b.relaxation_time);
      }
    changes.push_back({"Material", "Branch shear moduli (kPa)", moduli});
    changes.push_back({"Material", "Branch relaxation times (s)", times});
    return changes;
  }

  std::vector<ParameterChange> uncertainty_entries(const std::vector<SceneParameter> &free,
                                                   const FitResult                   &r)
  {
    const Eigen::Index K = Eigen::Index(free.size());
    if (r.covariance.rows() != K || r.covariance.cols() != K)
      return {};
    std::vector<Eigen::Index> known; // the constants the data identify
    std::vector<std::string>  names;
    std::string               deviations, correlations;
    for (Eigen::Index j = 0; j < K; ++j)
      if (std::isfinite(r.covariance(j, j)) && r.covariance(j, j) >= 0.)
        {
          const ParameterChange sd = fitted_entry(free[j], std::sqrt(r.covariance(j, j)));
          known.push_back(j);
          names.push_back(sd.entry);
          deviations += (deviations.empty() ? "" : ", ") + sd.entry + ": " + sd.value;
        }
    for (std::size_t a = 0; a < known.size(); ++a)
      for (std::size_t b = a + 1; b < known.size(); ++b)
        {
          const Eigen::Index i = known[a], j = known[b];
          const double       d = std::sqrt(r.covariance(i, i) * r.covariance(j, j));
          if (d > 0.)
            correlations += (correlations.empty() ? "" : "; ") + names[a] + ", " + names[b] +
                            ": " + exact_number(r.covariance(i, j) / d);
        }
    if (deviations.empty())
      return {};
    return {{"Uncertainty", "Mode", "none"},
            {"Uncertainty", "Covariance file", ""},
            {"Uncertainty", "Standard deviations", deviations},
            {"Uncertainty", "Correlations", correlations}};
  }

  namespace
  {
    using namespace fit_quantity;

    /// The root attributes and /correlation of every fit.
    /// The root attributes every fit file has; @p rms_row is the rms
    /// residual's row in the data's unit (mm of displacement, kPa of stress).
    Product fit_attributes(const std::string &parameter_text, const FitSettings &settings,
                           const FitResult &r, const unsigned int solve_count,
                           const Quantity &rms_row = rms_residual)
    {
      const std::size_t        K = settings.free.size();
      std::vector<std::string> names;
      std::string              warning_lines;
      for (const auto &p : settings.free)
        names.push_back(p.name());
      for (const auto &x : r.warnings)
        warning_lines += (warning_lines.empty() ? "" : "\n") + x;
      std::vector<double> c(K * K), cov(K * K);
      const bool          has_covariance = r.covariance.rows() == Eigen::Index(K);
      for (std::size_t i = 0; i < K; ++i)
        for (std::size_t j = 0; j < K; ++j)
          {
            c[i * K + j]   = r.correlation.size() ? r.correlation(i, j) : NAN;
            cov[i * K + j] = has_covariance ? r.covariance(i, j) : NAN;
          }
      Product product;
      product.root()
        .set(common_quantity::parameters, parameter_text)
        .set(common_quantity::code_version, CDEA_VERSION)
        .set(free_parameters, names)
        .set(initial_values, r.initial)
        .set(fitted_values, r.values)
        .set(standard_errors, r.standard_errors)
        .set(rms_row, r.rms)
        .set(condition_number, r.condition)
        .set(converged, r.converged)
        .set(status, r.status)
        .set(warnings, warning_lines)
        .set(iterations, r.iterations)
        .set(evaluations, r.evaluations)
        .set(solves, solve_count)
        .set(correlation, c, {K, K})
        .set(covariance, cov, {K, K});
      return product;
    }

    /// Element @p i of @p v (NaN if @p v is empty: not fitted).
    double at(const Eigen::VectorXd &v, const std::size_t i)
    {
      return v.size() ? v[Eigen::Index(i)] : NAN;
    }

    /// The voltages of data points row by row.
    std::vector<double> rows_of(const std::vector<std::vector<double>> &voltages)
    {
      std::vector<double> all;
      for (const auto &v : voltages)
        all.insert(all.end(), v.begin(), v.end());
      return all;
    }
  } // namespace

  Product fit_product(const std::string &parameter_text, const CalibrationData &data,
                      const FitSettings &settings, const Calibrated &c)
  {
    const FitResult  &r = c.result;
    const std::size_t M = data.size(), N = M ? data.voltages[0].size() : 0;
    Product           product = fit_attributes(parameter_text, settings, r, c.solves);
    std::vector<double> fitted_values, residuals;
    for (std::size_t i = 0; i < M; ++i)
      {
        fitted_values.push_back(at(r.fitted, i));
        residuals.push_back(at(r.residuals, i));
      }
    product.group("/data")
      .set(voltage, rows_of(data.voltages), {M, N})
      .set(displacement, data.displacement)
      .set(weight, data.weight)
      .set(fitted, fitted_values)
      .set(residual, residuals);
    product.group("/curve")
      .set(curve_voltage, rows_of(c.curve_voltages), {c.curve_voltages.size(), N})
      .set(curve_displacement, c.curve_displacement);
    return product;
  }

  Product dma_fit_product(const std::string &parameter_text, const DmaData &data,
                          const FitSettings &settings, const FitResult &r)
  {
    const std::size_t   M = data.size();
    std::vector<double> fs, fl, rs, rl;
    for (std::size_t i = 0; i < M; ++i)
      {
        fs.push_back(at(r.fitted, 2 * i));
        fl.push_back(at(r.fitted, 2 * i + 1));
        rs.push_back(at(r.residuals, 2 * i));
        rl.push_back(at(r.residuals, 2 * i + 1));
      }
    Product product = fit_attributes(parameter_text, settings, r, 0, rms_residual_kPa);
    product.group("/data")
      .set(dma_frequency, data.frequency)
      .set(dma_storage, data.storage)
      .set(dma_loss, data.loss)
      .set(dma_weight, data.weight)
      .set(dma_fitted_storage, fs)
      .set(dma_fitted_loss, fl)
      .set(dma_residual_storage, rs)
      .set(dma_residual_loss, rl);
    return product;
  }

  Product creep_fit_product(const std::string &parameter_text, const CreepData &data,
                            const FitSettings &settings, const FitResult &r)
  {
    const std::size_t   M = data.size(), N = M ? data.voltages[0].size() : 0;
    std::vector<double> fitted_values, residuals;
    for (std::size_t i = 0; i < M; ++i)
      {
        fitted_values.push_back(at(r.fitted, i));
        residuals.push_back(at(r.residuals, i));
      }
    Product product = fit_attributes(parameter_text, settings, r, 0);
    product.group("/data")
      .set(creep_time, data.times)
      .set(creep_voltage, rows_of(data.voltages), {M, N})
      .set(creep_displacement, data.displacement)
      .set(creep_weight, data.weight)
      .set(creep_fitted, fitted_values)
      .set(creep_residual, residuals);
    return product;
  }

  Product material_fit_product(const std::string &parameter_text, const FitSettings &settings,
                               const MaterialFitResult                &r,
                               const std::vector<MaterialTestOutcome> &outcomes)
  {
    namespace q = material_fit_quantity;
    const FitResult &f = r.fit;
    Product product = fit_attributes(parameter_text, settings, f, 0, q::rms_residual_kPa);
    product.root().set(evaluations, r.evaluations);
    std::vector<std::string> files, kinds;
    std::vector<double> fitted_flags, weights, samples, rms, largest, relative;
    std::vector<double> test, time, stretch, measured, model, residual, sample_weight;
    for (std::size_t k = 0; k < outcomes.size(); ++k)
      {
        const MaterialTestOutcome &o = outcomes[k];
        const MaterialTestData    &d = *o.data;
        files.push_back(d.name);
        kinds.push_back(test_kind_name(d.history.kind));
        fitted_flags.push_back(o.fitted ? 1. : 0.);
        weights.push_back(o.weight);
        samples.push_back(double(d.size()));
        rms.push_back(o.measures.rms);
        largest.push_back(o.measures.largest);
        relative.push_back(o.measures.relative);
        for (std::size_t i = 0; i < d.size(); ++i)
          {
            test.push_back(double(k));
            measured.push_back(d.stress[i]);
            model.push_back(o.model[i]);
            residual.push_back(o.model[i] - d.stress[i]);
          }
        time.insert(time.end(), d.history.time.begin(), d.history.time.end());
        stretch.insert(stretch.end(), d.history.stretch.begin(), d.history.stretch.end());
        sample_weight.insert(sample_weight.end(), d.weight.begin(), d.weight.end());
      }
    product.group("/tests")
      .set(q::file, files)
      .set(q::kind, kinds)
      .set(q::fitted, fitted_flags)
      .set(q::file_weight, weights)
      .set(q::samples, samples)
      .set(q::rms, rms)
      .set(q::largest, largest)
      .set(q::relative_rms, relative);
    product.group("/samples")
      .set(q::test, test)
      .set(q::time, time)
      .set(q::stretch, stretch)
      .set(q::measured, measured)
      .set(q::model, model)
      .set(q::residual, residual)
      .set(q::sample_weight, sample_weight);
    return product;
  }
} // namespace cdea
