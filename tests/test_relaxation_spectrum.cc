// The relaxation spectrum of the viscoelastic law (two_network_gent.h,
// doc/materials.md "The relaxation spectrum"): network B as parallel branches.
//  - one branch given by the lists Branch shear moduli (kPa) etc. is the
//    Network B entries' law: the same FE time run of a homogeneous film
//    (20 backward Euler steps of s(t) = 2.5 + 0.3 sin(pi t) at 3 kV) to 1e-12;
//  - a branch split into two identical halves (mu / 2 each, the same tau):
//    the same run to 1e-12;
//  - all branches relaxed: the FE solution with dt = infinity is the elastic
//    (network A) one to 1e-12, and a material point held 1e4 s at fixed
//    stretches creeps to network A's stress;
//  - the DMA chart of a 3-branch film against the Prony series
//    E' = E_A + sum_k E_k x_k^2 / (1 + x_k^2), E'' = sum_k E_k x_k / (1 + x_k^2),
//    E = 3 mu, x_k = 2 pi f tau_k, to 1e-10;
//  - stress and consistent tangent of 3-branch laws (Gent, Mooney-Rivlin and
//    Ogden springs) against central differences of the incremental potential
//    and of the stress, both schemes;
//  - the entries' checks name the entry and what is allowed.

#include <cdea/base/text.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/material/gent_law.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/material_chart.h>
#include <cdea/material/two_network_gent.h>

#include "check.h"
#include "fe_checks.h"

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_close;
using cdea_test::check_rel;

namespace
{
  const double voltage = 3e3;

  double stretch(const double t) { return 2.5 + 0.3 * std::sin(M_PI * t); }

  LoadState load(const double t) { return cdea_test::film_load(t, stretch(t), voltage); }

  /// The viscoelastic law of @p texts (list entries) over the Network B
  /// entries 45 kPa, Jlim 60, 2 s.
  std::shared_ptr<const MembraneLaw> spectrum(const MaterialConstants &film,
                                              const std::map<std::string, std::string> &texts)
  {
    LawSettings s;
    s.model     = "viscoelastic";
    s.material  = film;
    s.constants = {{"Network B shear modulus (kPa)", 45.},
                   {"Network B Jlim", 60.},
                   {"Relaxation time (s)", 2.},
                   {"Mooney-Rivlin C2 (kPa)", 3.},
                   {"Ogden alpha 1", 1.3},
                   {"Ogden mu 2 (kPa)", 0.5},
                   {"Ogden alpha 2", 5.},
                   {"Ogden mu 3 (kPa)", -0.1},
                   {"Ogden alpha 3", -2.}};
    s.texts     = texts;
    return make_membrane_law(s);
  }

  struct FilmState
  {
    double              s1 = 0.;
    std::vector<double> xi1; ///< of each branch
  };

  /// The homogeneous film after 20 backward Euler steps of 0.1 s from the relaxed state.
  FilmState film_run(const Scene &scene, const std::shared_ptr<const MembraneLaw> &law)
  {
    MembraneModel model(scene, cdea_test::discretization(2, 2), NewtonSettings());
    model.set_material_law(law);
    model.set_time_step(std::numeric_limits<double>::infinity(), TimeScheme::backward_euler);
    check(model.solve(load(0.)).converged, "relaxed start");
    model.relax_internal_variables();
    for (unsigned int k = 0; k < 20; ++k)
      {
        model.set_time_step(0.1, TimeScheme::backward_euler);
        if (!check(model.solve(load((k + 1) * 0.1)).converged, "time step converges"))
          return {};
        model.accept_time_step();
      }
    model.set_time_step(0., TimeScheme::backward_euler);
    const StepFields f = model.fields();
    FilmState        s{f.s1[0], {}};
    for (const InternalField &v : f.internal)
      if (v.name.rfind("xi1", 0) == 0)
        s.xi1.push_back(v.values[0]);
    return s;
  }

  void check_runs(const Scene &scene)
  {
    const FilmState old_entries = film_run(scene, spectrum(scene.material, {}));
    const FilmState one_listed  = film_run(
      scene, spectrum(scene.material, {{"Branch shear moduli (kPa)", "45"},
                                       {"Branch relaxation times (s)", "2"},
                                       {"Branch Jlim", "60"}}));
    const FilmState halves = film_run(
      scene, spectrum(scene.material, {{"Branch shear moduli (kPa)", "22.5, 22.5"},
                                       {"Branch relaxation times (s)", "2, 2"}}));
    check(std::abs(old_entries.xi1.at(0) - stretch(2.)) > 1e-2,
          "the viscous stretch lags (the comparison is not trivial)");
    check_rel(one_listed.s1, old_entries.s1, 1e-12, "one listed branch: s1 of the Network B run");
    check_rel(one_listed.xi1.at(0), old_entries.xi1.at(0), 1e-12, "one listed branch: xi1");
    check(halves.xi1.size() == 2, "two halves: xi1 and xi1_b2 written");
    check_rel(halves.s1, old_entries.s1, 1e-12, "two halves: s1 of the one branch");
    check_rel(halves.xi1.at(0), old_entries.xi1.at(0), 1e-12, "two halves: xi1 of branch 1");
    check_rel(halves.xi1.at(1), old_entries.xi1.at(0), 1e-12, "two halves: xi1 of branch 2");
  }

  const std::map<std::string, std::string> three = {
    {"Branch shear moduli (kPa)", "30, 10, 5"},
    {"Branch relaxation times (s)", "0.1, 1, 10"},
    {"Branch Jlim", "60, 100, 270"}};

  void check_relaxed(const Scene &scene)
  {
    const auto law = spectrum(scene.material, three);
    double     s1[2];
    int        k = 0;
    for (const auto &l : {law, std::shared_ptr<const MembraneLaw>(
                                 std::make_shared<GentDielectricLaw>(scene.material))})
      {
        MembraneModel model(scene, cdea_test::discretization(2, 2), NewtonSettings());
        model.set_material_law(l);
        model.set_time_step(std::numeric_limits<double>::infinity(), TimeScheme::backward_euler);
        check(model.solve(load(0.5)).converged, "relaxed solve");
        s1[k++] = model.fields().s1[0];
      }
    check_rel(s1[0], s1[1], 1e-12, "3 branches relaxed (dt = infinity): the elastic s1");

    // A point held at (2.7, 2.2, 3 kV) from xi = 1 for 1e4 s in growing steps.
    const unsigned int  n = law->n_internal_variables();
    std::vector<double> old(n, 0.), current(n, 0.);
    law->relaxed_internal_variables({1., 1., 0.}, old.data());
    const LawInput in{2.7, 2.2, voltage};
    LawResponse    r;
    for (double t = 0., dt = 1e-3; t < 1e4; t += dt, dt *= 1.2)
      {
        if (!law->evaluate(in, {old.data(), current.data(), dt, TimeScheme::backward_euler},
                           law_stress, r))
          {
            check(false, "the held point evaluates");
            return;
          }
        old = current;
      }
    const NominalStress a = GentDielectric(scene.material, voltage).stress(in.l1, in.l2);
    check_rel(r.stress.s1, a.s1, 1e-9, "held 1e4 s: s1 creeps to network A's");
    check_rel(r.stress.s2, a.s2, 1e-9, "held 1e4 s: s2 creeps to network A's");
  }

  void check_dma(const MaterialConstants &film)
  {
    const auto     law = spectrum(film, three);
    const DmaChart d   = dma_chart(*law, ChartSettings());
    const double   mu[3] = {30e3, 10e3, 5e3}, tau[3] = {0.1, 1., 10.};
    check_rel(d.moduli.relaxed, 3. * film.shear_modulus, 1e-12, "DMA: relaxed modulus 3 mu_A");
    check_rel(d.moduli.instantaneous, 3. * (film.shear_modulus + 45e3), 1e-12,
              "DMA: instantaneous modulus 3 (mu_A + sum mu_k)");
    check(d.moduli.relaxation_time == 0., "DMA: a spectrum has no single relaxation time");
    double worst = 0.;
    for (std::size_t k = 0; k < d.frequency.size(); ++k)
      {
        double storage = 3. * film.shear_modulus, loss = 0.;
        for (int b = 0; b < 3; ++b)
          {
            const double x = 2. * M_PI * d.frequency[k] * tau[b];
            storage += 3. * mu[b] * x * x / (1. + x * x);
            loss += 3. * mu[b] * x / (1. + x * x);
          }
        worst = std::max({worst, std::abs(d.storage[k] - storage) / storage,
                          std::abs(d.loss[k] - loss) / loss,
                          std::abs(d.loss_factor[k] - loss / storage) / (loss / storage)});
      }
    check(d.frequency.size() == 61, "DMA: 61 frequencies");
    check_close(worst, 0., 1e-10, "DMA of 3 branches: E', E'', tan delta vs the Prony series");
  }

  /// Stress against central differences of the energy (the incremental
  /// potential) and tangent against those of the stress, at points off the
  /// relaxed state, for dt = 0.05 and 1 s and both schemes.
  void check_tangent(const MaterialConstants &film, const std::string &spring)
  {
    auto texts          = three;
    texts["Branch law"] = spring;
    const auto          law = spectrum(film, texts);
    const unsigned int  n   = law->n_internal_variables();
    std::vector<double> old(n);
    for (unsigned int b = 0; b < 3; ++b)
      {
        old[4 * b]     = 1.8 + 0.2 * b;
        old[4 * b + 1] = 2.1 - 0.15 * b;
        old[4 * b + 2] = 0.05 * (b + 1);
        old[4 * b + 3] = -0.02 * b;
      }
    const auto respond = [&](const double l1, const double l2, const double dt,
                             const TimeScheme scheme, LawResponse &r) {
      std::vector<double> current(n, 0.);
      return law->evaluate({l1, l2, voltage}, {old.data(), current.data(), dt, scheme},
                           law_energy | law_stress | law_tangent, r);
    };
    double worst_stress = 0., worst_tangent = 0.;
    bool   all          = true;
    for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::trapezoidal})
      for (const double dt : {0.05, 1.})
        for (const auto &[l1, l2] : {std::pair{2.6, 2.3}, std::pair{2.0, 2.5}})
          {
            LawResponse r, p, m;
            all = all && respond(l1, l2, dt, scheme, r);
            const double scale = std::abs(r.stress.s1) + std::abs(r.stress.s2) + film.shear_modulus;
            for (int i = 0; i < 2; ++i)
              {
                const double h = 1e-6;
                all = all && respond(l1 + (i == 0 ? h : 0.), l2 + (i == 1 ? h : 0.), dt, scheme, p) &&
                      respond(l1 - (i == 0 ? h : 0.), l2 - (i == 1 ? h : 0.), dt, scheme, m);
                const double s  = i == 0 ? r.stress.s1 : r.stress.s2;
                const double t1 = i == 0 ? r.tangent.s11 : r.tangent.s12;
                const double t2 = i == 0 ? r.tangent.s12 : r.tangent.s22;
                worst_stress = std::max(worst_stress, std::abs((p.energy - m.energy) / (2. * h) - s) / scale);
                worst_tangent = std::max({worst_tangent,
                                          std::abs((p.stress.s1 - m.stress.s1) / (2. * h) - t1) / scale,
                                          std::abs((p.stress.s2 - m.stress.s2) / (2. * h) - t2) / scale});
              }
          }
    check(all, spring + " springs: every point evaluates");
    check_close(worst_stress, 0., 1e-7, spring + " springs, 3 branches: stress = dPsi/dl");
    check_close(worst_tangent, 0., 1e-7, spring + " springs, 3 branches: tangent = d(stress)/dl");
  }

  /// The message of building the law of @p texts ("" if it builds).
  std::string message_of(const MaterialConstants &film, const std::map<std::string, std::string> &texts)
  {
    try
      {
        spectrum(film, texts);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  void check_messages(const MaterialConstants &film)
  {
    const auto has = [&](const std::map<std::string, std::string> &texts, const std::string &part) {
      const std::string m = message_of(film, texts);
      check(m.find(part) != std::string::npos, "message '" + m + "' says '" + part + "'");
    };
    has({{"Branch shear moduli (kPa)", "30, 10"}, {"Branch relaxation times (s)", "1"}},
        "Material/Branch relaxation times (s) must list as many relaxation times as "
        "Material/Branch shear moduli (kPa) lists moduli (2), got 1");
    has({{"Branch shear moduli (kPa)", "30, -1"}, {"Branch relaxation times (s)", "1, 2"}},
        "Material/Branch shear moduli (kPa) (branch 2) must be between 1e-6 and 1e4 times");
    has({{"Branch shear moduli (kPa)", "30"}, {"Branch relaxation times (s)", "0"}},
        "Material/Branch relaxation times (s) (branch 1) must be between 1e-12 and 1e12 s, got 0");
    has({{"Branch shear moduli (kPa)", "30"}, {"Branch relaxation times (s)", "1"}, {"Branch Jlim", "1, 2"}},
        "Material/Branch Jlim must be empty or list as many values as");
    has({{"Branch relaxation times (s)", "1"}}, "Material/Branch shear moduli (kPa) must list 1 to 20");
    std::string many = "1";
    for (int k = 0; k < 20; ++k)
      many += ", 1";
    has({{"Branch shear moduli (kPa)", many}, {"Branch relaxation times (s)", many}},
        "Material/Branch shear moduli (kPa) must list 1 to 20 shear moduli when "
        "Material/Branch relaxation times (s) or Material/Branch Jlim is set, got 21");
    has({{"Branch law", "viscoelastic"}}, "Material/Branch law must name an elastic law");
    has({{"Branch law", "steel"}}, "got 'steel'");
    has({{"Branch shear moduli (kPa)", "1, x"}, {"Branch relaxation times (s)", "1, 2"}}, "Material/Branch shear moduli (kPa)");
    check(message_of(film, three).empty(), "three branches build");
  }
} // namespace

CDEA_TEST_MAIN()
{
  Scene scene = cdea::paper_scene({1., 3.}, {{voltage * 1e-3}});
  scene.mass  = 0.;
  check_runs(scene);
  check_relaxed(scene);
  check_dma(scene.material);
  for (const std::string spring : {"elastic", "mooney-rivlin", "ogden"})
    check_tangent(scene.material, spring);
  check_messages(scene.material);
  return cdea_test::finish();
}
