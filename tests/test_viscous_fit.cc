// The fits of the viscoelastic film (design/viscous_fit.h): the branch
// constants' convention, the DMA model's closed form against the DMA chart and
// its derivatives against finite differences, the recovery of the constants
// from noisy synthetic DMA data (fixed seeds), and the data files' messages.

#include <cdea/design/viscous_fit.h>
#include <cdea/material/material_chart.h>
#include <cdea/material/two_network_gent.h>

#include "check.h"

#include <random>
#include <sstream>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// The 3-branch film of prm/fit-dma.prm at the true constants.
  Scene film()
  {
    Scene s                                        = paper_scene({1., 3.}, {{1.}});
    s.material_model                               = "viscoelastic";
    s.law_texts["Branch shear moduli (kPa)"]       = "25, 15, 5";
    s.law_texts["Branch relaxation times (s)"]     = "0.2, 2, 20";
    s.law_constants["Network B Jlim"]              = 270.;
    s.law_constants["Network B shear modulus (kPa)"] = 45.;
    s.law_constants["Relaxation time (s)"]         = 2.;
    return s;
  }

  std::vector<SceneParameter> all_free()
  {
    std::vector<SceneParameter> free{{ParameterKind::shear_modulus, 0}};
    for (unsigned int k = 1; k <= 3; ++k)
      for (const bool t : {false, true})
        free.push_back({ParameterKind::law_constant, 0, branch_constant_entry(k, t)});
    return free;
  }

  void check_convention()
  {
    const Scene s   = film();
    const auto  own = s.law()->own_constants();
    check(own.size() == 6, "6 own constants for 3 branches");
    check(own[0].entry == "Branch 1 shear modulus (Pa)" && own[0].value == 25e3 &&
            own[3].entry == "Branch 2 relaxation time (s)" && own[3].value == 2.,
          "own_constant(2(k-1)) = mu_k (Pa), own_constant(2(k-1)+1) = tau_k (s)");
    Scene changed = with_parameter(s, {ParameterKind::law_constant, 0, own[5].entry}, 7.);
    const auto *law = dynamic_cast<const TwoNetworkGentLaw *>(changed.law().get());
    check(law && law->branches()[2].relaxation_time == 7.,
          "a branch constant set in the scene reaches the law");
    check(parameter_value(s, {ParameterKind::law_constant, 0, own[2].entry}) == 15e3,
          "parameter_value of a branch modulus from the law");
  }

  /// Only the free relaxation times get the window; an elastic film none.
  void check_time_window()
  {
    FitSettings settings;
    settings.free = all_free();
    const FitSettings w = relaxation_time_window(film(), settings, 0.01, 8000.);
    bool          ok    = w.window.size() == 7;
    for (std::size_t j = 0; ok && j < 7; ++j)
      ok = (j >= 1 && j % 2 == 0) ? (w.window[j].first == 0.01 && w.window[j].second == 8000.) :
                                    (w.window[j].first == 0. && std::isinf(w.window[j].second));
    check(ok, "the window holds tau_1..tau_3 in [0.01, 8000] s and leaves mu_A and the moduli");
    FitSettings elastic;
    elastic.free = {{ParameterKind::shear_modulus, 0}};
    check(relaxation_time_window(paper_scene({1., 3.}, {{1.}}), elastic, 0.01, 8000.).window.empty(),
          "no window for an elastic film");
  }

  void check_dma_model()
  {
    const Scene               s = film();
    const std::vector<double> f{1e-3, 0.05, 0.8, 10., 300.};
    const auto                free = all_free();
    const DmaModel            model(s, f, free); // refuses a model the chart disagrees with
    std::vector<double>       v;
    for (const auto &p : free)
      v.push_back(parameter_value(s, p));
    Eigen::VectorXd E;
    Eigen::MatrixXd J;
    check(model.evaluate(v, E, &J), "DMA model evaluates");
    const auto law = s.law();
    for (std::size_t i = 0; i < f.size(); ++i)
      check_close(E[Eigen::Index(2 * i)], complex_modulus(*law, f[i]).real(), 1e-9 * E[0],
                  "storage against the DMA chart");
    double worst = 0.;
    for (std::size_t j = 0; j < free.size(); ++j)
      {
        const double        h = 1e-6 * v[j];
        std::vector<double> up = v, down = v;
        up[j] += h;
        down[j] -= h;
        Eigen::VectorXd Eu, Ed;
        model.evaluate(up, Eu, nullptr);
        model.evaluate(down, Ed, nullptr);
        const Eigen::VectorXd fd = (Eu - Ed) / (2. * h);
        worst = std::max(worst, (fd - J.col(Eigen::Index(j))).norm() / (J.col(Eigen::Index(j)).norm() + 1e-30));
      }
    std::ostringstream text;
    text << "exact DMA derivatives against central differences: largest relative "
            "difference of a column "
         << worst;
    check(worst < 1e-6, text.str());
  }

  void check_recovery(const unsigned int seed)
  {
    const Scene         truth = film();
    std::vector<double> f;
    for (int k = 0; k <= 40; ++k)
      f.push_back(std::pow(10., -3. + 4. * k / 40.));
    const auto          free = all_free();
    std::vector<double> v;
    for (const auto &p : free)
      v.push_back(parameter_value(truth, p));
    Eigen::VectorXd E;
    DmaModel(truth, f, free).evaluate(v, E, nullptr);
    std::mt19937                     rng(seed);
    std::normal_distribution<double> noise(0., 300.); // Pa
    DmaData                          data;
    for (std::size_t i = 0; i < f.size(); ++i)
      {
        data.frequency.push_back(f[i]);
        data.storage.push_back(E[Eigen::Index(2 * i)] + noise(rng));
        data.loss.push_back(E[Eigen::Index(2 * i + 1)] + noise(rng));
        data.weight.push_back(1.);
      }
    // Start 20 to 50 % off, as prm/fit-dma.prm.
    const std::vector<double> start{20e3, 30e3, 0.3, 10e3, 1.5, 8e3, 30.};
    const Scene               base = scene_with(truth, free, start);
    FitSettings               settings;
    settings.free            = free;
    const FitResult r        = fit_dma(base, data, settings);
    bool            inside   = r.converged;
    for (std::size_t j = 0; j < free.size(); ++j)
      inside = inside && std::abs(r.values[j] - v[j]) < 2. * r.standard_errors[j];
    check(inside, "seed " + std::to_string(seed) + ": every constant within 2 standard errors");
  }

  void check_messages()
  {
    std::istringstream bad("frequency_Hz, storage_kPa, loss_kPa\n1, 80, 2\n2, 81, -1\n");
    std::string        message;
    try
      {
        read_dma_data(bad, "dma.csv");
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    check(message.find("dma.csv, line 3, column loss_kPa") != std::string::npos,
          "a bad loss modulus is named by file, line and column: " + message);
    std::istringstream creep("time_s, V1_kV, displacement_mm\n0, 0, 1\n0, 1, 2\n");
    message.clear();
    try
      {
        read_creep_data(creep, "creep.csv", 1, 1e4);
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    check(message.find("creep.csv, line 3, column time_s") != std::string::npos,
          "a time that does not increase is named: " + message);
  }
} // namespace

CDEA_TEST_MAIN()
{
  check_convention();
  check_time_window();
  check_dma_model();
  for (const unsigned int seed : {1u, 2u, 4u})
    check_recovery(seed);
  check_messages();
  return finish();
}
