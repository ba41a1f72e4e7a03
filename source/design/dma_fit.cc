// The free parameters of the fits of the viscoelastic film and the DMA fit:
// the small-strain Prony moduli in closed form with exact derivatives.

#include <cdea/base/format.h>
#include <cdea/base/units.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/input/parameters.h>
#include <cdea/material/material_chart.h>
#include <cdea/material/two_network_gent.h>

#include <algorithm>
#include <cmath>

namespace cdea
{
  namespace
  {
    bool is_branch_constant(const SceneParameter &p)
    {
      return p.kind == ParameterKind::law_constant && p.entry.compare(0, 7, "Branch ") == 0;
    }

    /// Branch k (from 0) and whether @p p is its relaxation time.
    std::pair<unsigned int, bool> branch_of(const SceneParameter &p)
    {
      for (unsigned int k = 1; k <= max_viscous_branches; ++k)
        for (const bool is_time : {false, true})
          if (p.entry == branch_constant_entry(k, is_time))
            return {k - 1, is_time};
      throw std::invalid_argument("branch_of: '" + p.entry + "' is no branch constant");
    }

    const TwoNetworkGentLaw &film_of(const MembraneLaw &law)
    {
      const auto *film = dynamic_cast<const TwoNetworkGentLaw *>(&law);
      if (!film)
        throw InputError("a DMA fit needs the viscoelastic film (Material/Model = viscoelastic)");
      return *film;
    }

    std::string allowed(const MembraneLaw &law, const bool creep)
    {
      std::string list = creep ? "shear modulus, Jlim, permittivity" : "shear modulus";
      for (const LawConstant &c : law.own_constants())
        if (c.entry.compare(0, 7, "Branch ") == 0)
          list += ", " + c.entry;
      return list;
    }
  } // namespace

  FitSettings viscous_fit_settings(const Parameters &p, const FitDataKind kind)
  {
    const bool  creep = kind == FitDataKind::creep;
    const auto  law   = p.scene().law();
    FitSettings s     = free_parameter_settings(p);
    if (!creep)
      film_of(*law);
    if (creep && (!p.time.enabled || p.time.inertia))
      throw InputError("a creep fit runs the quasi-static time model: it needs Time/Enabled = "
                       "true and Time/Inertia = false");
    for (const SceneParameter &f : s.free)
      {
        const bool ok = f.kind == ParameterKind::shear_modulus || is_branch_constant(f) ||
                        (creep && (f.kind == ParameterKind::jlim ||
                                   f.kind == ParameterKind::permittivity));
        if (!ok)
          throw InputError("Calibration/Free parameters: '" + label(f) + "': " +
                           (creep ? "a creep fit frees the film's law constants only" :
                                    "the small-strain DMA moduli do not depend on it") +
                           " (any of " + allowed(*law, creep) + ")");
      }
    return s;
  }

  LawParameter law_parameter_of(const Scene &scene, const SceneParameter &p)
  {
    switch (p.kind)
      {
        case ParameterKind::shear_modulus:
          return LawParameter::shear_modulus;
        case ParameterKind::jlim:
          return LawParameter::jlim;
        case ParameterKind::permittivity:
          return LawParameter::permittivity;
        case ParameterKind::law_constant:
          {
            const auto own = scene.law()->own_constants();
            for (unsigned int k = 0; k < own.size(); ++k)
              if (own[k].entry == p.entry)
                return own_constant(k);
            break;
          }
        default:
          break;
      }
    throw std::invalid_argument("law_parameter_of: " + p.name() + " is no law parameter");
  }

  double law_parameter_value(const Parameters &p, const LawParameter q)
  {
    switch (q)
      {
        case LawParameter::shear_modulus:
          return units::kPa.in_si(p.material.shear_modulus_kPa);
        case LawParameter::jlim:
          return p.material.jlim;
        case LawParameter::permittivity:
          return p.material.permittivity;
        default:
          break;
      }
    const auto own = p.scene().law()->own_constants();
    const int  k   = own_constant_index(q);
    if (k < 0 || std::size_t(k) >= own.size())
      throw std::invalid_argument("law_parameter_value: no such parameter");
    const auto it = p.material_law.constants.find(own[std::size_t(k)].entry);
    return it != p.material_law.constants.end() ? it->second : own[std::size_t(k)].value;
  }

  void set_law_parameter(Parameters &p, const LawParameter q, const double value)
  {
    switch (q)
      {
        case LawParameter::shear_modulus:
          p.material.shear_modulus_kPa = units::kPa.from_si(value);
          return;
        case LawParameter::jlim:
          p.material.jlim = value;
          return;
        case LawParameter::permittivity:
          p.material.permittivity = value;
          return;
        default:
          break;
      }
    const auto own = p.scene().law()->own_constants();
    const int  k   = own_constant_index(q);
    if (k < 0 || std::size_t(k) >= own.size())
      throw std::invalid_argument("set_law_parameter: no such parameter");
    p.material_law.constants[own[std::size_t(k)].entry] = value;
  }

  DmaModel::DmaModel(const Scene &base_in, const std::vector<double> &frequency_in,
                     const std::vector<SceneParameter> &free_in)
    : base(base_in)
    , frequency(frequency_in)
    , free(free_in)
  {
    // The closed form is the DMA chart's modulus for Gent-type springs; a
    // branch law with another small-strain modulus is refused here.
    const auto      law = base.law();
    Eigen::VectorXd E;
    std::vector<double> start;
    for (const SceneParameter &f : free)
      start.push_back(parameter_value(base, f));
    evaluate(start, E, nullptr);
    for (std::size_t i = 0; i < frequency.size(); ++i)
      {
        const std::complex<double> chart = complex_modulus(*law, frequency[i]);
        if (std::abs(chart.real() - E[2 * i]) > 1e-8 * std::abs(chart) ||
            std::abs(chart.imag() - E[2 * i + 1]) > 1e-8 * std::abs(chart))
          throw InputError("a DMA fit needs branch springs whose small-strain shear modulus is "
                           "their mu_k (the Prony series E_k = 3 mu_k); the chart's modulus at " +
                           format_number(frequency[i]) + " Hz differs");
      }
  }

  bool DmaModel::evaluate(const std::vector<double> &values, Eigen::VectorXd &E,
                          Eigen::MatrixXd *J, std::string *message) const
  {
    const Scene scene = scene_with(base, free, values);
    std::shared_ptr<const MembraneLaw> law;
    try
      {
        law = scene.law();
      }
    catch (const std::exception &e)
      {
        if (message)
          *message = e.what();
        return false;
      }
    const TwoNetworkGentLaw &film = film_of(*law);
    const std::size_t        M = frequency.size(), K = free.size();
    E.setZero(Eigen::Index(2 * M));
    if (J)
      J->setZero(Eigen::Index(2 * M), Eigen::Index(K));
    for (std::size_t i = 0; i < M; ++i)
      {
        const double w = 2. * M_PI * frequency[i];
        E[Eigen::Index(2 * i)] = 3. * film.network_a().shear_modulus;
        for (const ViscousNetwork &b : film.branches())
          {
            const double x = w * b.relaxation_time, n = 1. + x * x;
            E[Eigen::Index(2 * i)] += 3. * b.shear_modulus * x * x / n;
            E[Eigen::Index(2 * i + 1)] += 3. * b.shear_modulus * x / n;
          }
        for (std::size_t j = 0; J && j < K; ++j)
          {
            double &ds = (*J)(Eigen::Index(2 * i), Eigen::Index(j));
            double &dl = (*J)(Eigen::Index(2 * i + 1), Eigen::Index(j));
            if (free[j].kind == ParameterKind::shear_modulus)
              {
                ds = 3.;
                continue;
              }
            const auto [k, is_time]  = branch_of(free[j]);
            const ViscousNetwork &b = film.branches()[k];
            const double x = w * b.relaxation_time, n = 1. + x * x;
            ds = is_time ? 3. * b.shear_modulus * 2. * x / (n * n) * w : 3. * x * x / n;
            dl = is_time ? 3. * b.shear_modulus * (1. - x * x) / (n * n) * w : 3. * x / n;
          }
      }
    return true;
  }

  FitSettings relaxation_time_window(const Scene &scene, FitSettings settings,
                                     const double shortest, const double longest)
  {
    if (scene.law()->n_evolving() == 0)
      return settings;
    settings.window.assign(settings.free.size(), {0., HUGE_VAL});
    for (std::size_t j = 0; j < settings.free.size(); ++j)
      if (is_branch_constant(settings.free[j]) && branch_of(settings.free[j]).second)
        settings.window[j] = {shortest, longest};
    return settings;
  }

  FitResult fit_dma(const Scene &base, const DmaData &data, const FitSettings &settings,
                    const std::function<void(unsigned int, double, const std::vector<double> &)>
                      &progress)
  {
    // Relaxation times from a hundredth of 1 / (2 pi f_max) to a hundred times
    // 1 / (2 pi f_min): the loss peak of a branch lies at 2 pi f tau = 1.
    const auto [f_min, f_max] = std::minmax_element(data.frequency.begin(), data.frequency.end());
    const FitSettings bounded = relaxation_time_window(base, settings, 1e-2 / (2. * M_PI * *f_max),
                                                       1e2 / (2. * M_PI * *f_min));
    const DmaModel  model(base, data.frequency, settings.free);
    FitObservations observations;
    observations.unit = units::kPa.to_si; // residuals in kPa
    observations.measured.resize(Eigen::Index(2 * data.size()));
    observations.weight.resize(Eigen::Index(2 * data.size()));
    for (std::size_t i = 0; i < data.size(); ++i)
      {
        observations.measured[Eigen::Index(2 * i)]     = data.storage[i];
        observations.measured[Eigen::Index(2 * i + 1)] = data.loss[i];
        observations.weight[Eigen::Index(2 * i)]       = data.weight[i];
        observations.weight[Eigen::Index(2 * i + 1)]   = data.weight[i];
      }
    return fit_observations(base, observations, bounded,
                            [&model](const std::vector<double> &v, Eigen::VectorXd &E,
                                     Eigen::MatrixXd *J, std::string *message) {
                              return model.evaluate(v, E, J, message);
                            },
                            progress);
  }
} // namespace cdea
