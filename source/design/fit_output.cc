// What `cdea fit` writes: <Base name>_fit.h5 and <Base name>_fit.prm.

#include <cdea/base/format.h>
#include <cdea/design/fit.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/output/hdf5_writer.h>

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
          return {"Material", "Shear modulus (kPa)", exact_number(value * 1e-3)};
        case ParameterKind::jlim:
          return {"Material", "Jlim", exact_number(value)};
        case ParameterKind::permittivity:
          return {"Material", "Permittivity (F/m)", exact_number(value)};
        case ParameterKind::mass:
          return {"Loading", "Mass (g)", exact_number(value * 1e3)};
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
        moduli += (moduli.empty() ? "" : ", ") + exact_number(b.shear_modulus * 1e-3);
        times += (times.empty() ? "" : ", ") + exact_number(b.relaxation_time);
      }
    changes.push_back({"Material", "Branch shear moduli (kPa)", moduli});
    changes.push_back({"Material", "Branch relaxation times (s)", times});
    return changes;
  }

  namespace
  {
    /// The root attributes and /correlation of every fit file.
    void write_fit_attributes(Hdf5Writer &w, const std::string &parameter_text,
                              const FitSettings &settings, const FitResult &r,
                              const unsigned int solves)
    {
      const std::size_t K = settings.free.size();
      std::string       names, warnings;
      for (const auto &p : settings.free)
        names += (names.empty() ? "" : "; ") + p.name();
      for (const auto &x : r.warnings)
        warnings += (warnings.empty() ? "" : "\n") + x;
      w.attribute("/", "parameters", parameter_text);
      w.attribute("/", "code_version", std::string(CDEA_VERSION));
      w.attribute("/", "free_parameters", names);
      w.attribute("/", "initial_values", r.initial);
      w.attribute("/", "fitted_values", r.values);
      w.attribute("/", "standard_errors", r.standard_errors);
      w.attribute("/", "rms_residual_mm", r.rms * 1e3);
      w.attribute("/", "condition_number", r.condition);
      w.attribute("/", "converged", int(r.converged));
      w.attribute("/", "status", r.status);
      w.attribute("/", "warnings", warnings);
      w.attribute("/", "iterations", int(r.iterations));
      w.attribute("/", "evaluations", int(r.evaluations));
      w.attribute("/", "solves", int(solves));
      std::vector<double> c(K * K);
      for (std::size_t i = 0; i < K; ++i)
        for (std::size_t j = 0; j < K; ++j)
          c[i * K + j] = r.correlation.size() ? r.correlation(i, j) : NAN;
      w.dataset("/correlation", {K, K}, c, "1",
                "correlation matrix of the fitted parameters (order of free_parameters)");
    }

    /// Element @p i of @p v times @p factor (NaN if @p v is empty: not fitted).
    double at(const Eigen::VectorXd &v, const std::size_t i, const double factor)
    {
      return v.size() ? v[Eigen::Index(i)] * factor : NAN;
    }
  } // namespace

  void write_fit_file(const std::string &path, const std::string &parameter_text,
                      const CalibrationData &data, const FitSettings &settings,
                      const FitResult &r, const std::vector<std::vector<double>> &curve_kV,
                      const std::vector<double> &curve_mm, const unsigned int solves)
  {
    const std::size_t M = data.size();
    const std::size_t N = M ? data.voltages[0].size() : 0;
    Hdf5Writer        w(path);
    write_fit_attributes(w, parameter_text, settings, r, solves);
    w.group("/data");
    std::vector<double> volts, measured, fitted, residual;
    for (std::size_t i = 0; i < M; ++i)
      {
        for (const double v : data.voltages[i])
          volts.push_back(v * 1e-3);
        measured.push_back(data.displacement[i] * 1e3);
        fitted.push_back(r.fitted.size() ? r.fitted[i] * 1e3 : NAN);
        residual.push_back(r.residuals.size() ? r.residuals[i] * 1e3 : NAN);
      }
    w.dataset("/data/voltage_kV", {M, N}, volts, "kV", "ring voltages of each data point");
    w.dataset("/data/displacement_mm", {M}, measured, "mm", "measured displacement");
    w.dataset("/data/weight", {M}, data.weight, "1", "weight of each point");
    w.dataset("/data/fitted_mm", {M}, fitted, "mm",
              "model displacement at the fitted parameters, each point ramped from zero");
    w.dataset("/data/residual_mm", {M}, residual, "mm", "model minus measured");
    w.group("/curve");
    std::vector<double> curve_volts;
    for (const auto &v : curve_kV)
      curve_volts.insert(curve_volts.end(), v.begin(), v.end());
    w.dataset("/curve/voltage_kV", {curve_kV.size(), N}, curve_volts, "kV",
              "ring voltages along the data in file order (8 steps between points)");
    w.dataset("/curve/displacement_mm", {curve_mm.size()}, curve_mm, "mm",
              "model displacement along the data at the fitted parameters, by continuation");
    w.commit();
  }

  void write_dma_fit_file(const std::string &path, const std::string &parameter_text,
                          const DmaData &data, const FitSettings &settings, const FitResult &r)
  {
    const std::size_t M = data.size();
    Hdf5Writer        w(path);
    // rms_residual_mm of a DMA fit is in MPa (moduli in kPa over 1e3): the
    // rms in kPa is its own attribute.
    write_fit_attributes(w, parameter_text, settings, r, 0);
    w.attribute("/", "rms_residual_kPa", r.rms * 1e-3);
    w.group("/data");
    std::vector<double> storage, loss, fs, fl, rs, rl;
    for (std::size_t i = 0; i < M; ++i)
      {
        storage.push_back(data.storage[i] * 1e-3);
        loss.push_back(data.loss[i] * 1e-3);
        fs.push_back(at(r.fitted, 2 * i, 1e-3));
        fl.push_back(at(r.fitted, 2 * i + 1, 1e-3));
        rs.push_back(at(r.residuals, 2 * i, 1e-3));
        rl.push_back(at(r.residuals, 2 * i + 1, 1e-3));
      }
    w.dataset("/data/frequency_Hz", {M}, data.frequency, "Hz", "frequency of each row");
    w.dataset("/data/storage_kPa", {M}, storage, "kPa", "measured storage modulus E'");
    w.dataset("/data/loss_kPa", {M}, loss, "kPa", "measured loss modulus E''");
    w.dataset("/data/weight", {M}, data.weight, "1", "weight of each row (both moduli)");
    w.dataset("/data/fitted_storage_kPa", {M}, fs, "kPa", "model E' at the fitted parameters");
    w.dataset("/data/fitted_loss_kPa", {M}, fl, "kPa", "model E'' at the fitted parameters");
    w.dataset("/data/residual_storage_kPa", {M}, rs, "kPa", "model minus measured E'");
    w.dataset("/data/residual_loss_kPa", {M}, rl, "kPa", "model minus measured E''");
    w.commit();
  }

  void write_creep_fit_file(const std::string &path, const std::string &parameter_text,
                            const CreepData &data, const FitSettings &settings, const FitResult &r)
  {
    const std::size_t M = data.size(), N = M ? data.voltages[0].size() : 0;
    Hdf5Writer        w(path);
    write_fit_attributes(w, parameter_text, settings, r, 0);
    w.group("/data");
    std::vector<double> volts, measured, fitted, residual;
    for (std::size_t i = 0; i < M; ++i)
      {
        for (const double v : data.voltages[i])
          volts.push_back(v * 1e-3);
        measured.push_back(data.displacement[i] * 1e3);
        fitted.push_back(at(r.fitted, i, 1e3));
        residual.push_back(at(r.residuals, i, 1e3));
      }
    w.dataset("/data/time_s", {M}, data.times, "s", "sample time of each row");
    w.dataset("/data/voltage_kV", {M, N}, volts, "kV", "ring voltages at each sample time");
    w.dataset("/data/displacement_mm", {M}, measured, "mm", "measured displacement");
    w.dataset("/data/weight", {M}, data.weight, "1", "weight of each row");
    w.dataset("/data/fitted_mm", {M}, fitted, "mm",
              "displacement of the quasi-static time run at the fitted parameters");
    w.dataset("/data/residual_mm", {M}, residual, "mm", "model minus measured");
    w.commit();
  }
} // namespace cdea
