// The material point's exact derivatives (material/material_point.h) against
// central differences of whole histories with every constant perturbed by a
// relative 1e-6 (the law rebuilt from its settings), for every elastic law,
// the viscoelastic film with three branches (Gent and Mooney-Rivlin
// springs) in every time scheme, and the shear-thinning viscosity's
// constants; in uniaxial tension (l2 from s2 = 0), equibiaxial tension and
// pure shear. The history starts held at stretch 1.2 (the relaxed start is
// differentiated too), loads, holds, unloads and holds again. Measure: the
// largest difference over a column's largest entry.

#include <cdea/material/law_factory.h>
#include <cdea/material/material_point.h>

#include "check.h"

#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_close;

namespace
{
  StretchHistory lab_history(const TestKind kind)
  {
    StretchHistory h;
    h.kind = kind;
    for (unsigned int k = 0; k <= 60; ++k)
      {
        const double t = 0.25 * k;
        // 1.2 held, up to 2.4 in 3 s, held, down to 1.6 in 2 s, held.
        const double L = t < 1. ? 1.2 : t < 4. ? 1.2 + 0.4 * (t - 1.) : t < 8. ? 2.4 :
                         t < 10. ? 2.4 - 0.4 * (t - 8.) : 1.6;
        h.time.push_back(t);
        h.stretch.push_back(L);
      }
    return h;
  }

  /// The law's value of @p p in @p s (own constants by their entry, or the
  /// law's value for a list element).
  double value_of(const LawSettings &s, const MembraneLaw &law, const LawParameter p)
  {
    if (p == LawParameter::shear_modulus)
      return s.material.shear_modulus;
    if (p == LawParameter::jlim)
      return s.material.jlim;
    const LawConstant c = law.own_constants().at(std::size_t(own_constant_index(p)));
    return std::isnan(c.value) ? s.constant(c.entry) : c.value;
  }

  LawSettings with_value(LawSettings s, const MembraneLaw &law, const LawParameter p,
                         const double v)
  {
    if (p == LawParameter::shear_modulus)
      s.material.shear_modulus = v;
    else if (p == LawParameter::jlim)
      s.material.jlim = v;
    else
      s.constants[law.own_constants().at(std::size_t(own_constant_index(p))).entry] = v;
    return s;
  }

  std::vector<double> stresses(const LawSettings &s, const StretchHistory &h,
                               const MaterialPointSettings &point)
  {
    const auto          law = make_membrane_law(s);
    MaterialPoint       m(*law, point);
    MaterialPointResult r;
    std::string         message;
    if (!m.run(h, {}, r, message))
      std::cout << "  run failed: " << message << '\n';
    return r.stress;
  }

  /// Every parameter's column against central differences; the worst
  /// relative difference of the case.
  double check_case(const std::string &name, const LawSettings &s,
                    const std::vector<LawParameter> &parameters, const TestKind kind,
                    const MaterialPointSettings &point)
  {
    const auto           law = make_membrane_law(s);
    const StretchHistory h   = lab_history(kind);
    MaterialPoint        m(*law, point);
    MaterialPointResult  r;
    std::string          message;
    if (!check(m.run(h, parameters, r, message), name + ": runs " + message))
      return 1.;
    double worst = 0.;
    for (std::size_t j = 0; j < parameters.size(); ++j)
      {
        const double v = value_of(s, *law, parameters[j]), d = 1e-6 * (std::abs(v) + 1e-3);
        const auto   up   = stresses(with_value(s, *law, parameters[j], v + d), h, point);
        const auto   down = stresses(with_value(s, *law, parameters[j], v - d), h, point);
        double       largest = 0., difference = 0.;
        for (std::size_t k = 0; k < h.time.size() && up.size() == h.time.size(); ++k)
          {
            const double fd = (up[k] - down[k]) / (2. * d);
            largest         = std::max(largest, std::abs(r.jacobian(Eigen::Index(k), Eigen::Index(j))));
            difference = std::max(difference, std::abs(fd - r.jacobian(Eigen::Index(k), Eigen::Index(j))));
          }
        worst = std::max(worst, largest > 0. ? difference / largest : difference);
      }
    std::cout << "  " << name << ", " << test_kind_name(kind) << ": " << parameters.size()
              << " columns, worst " << worst << '\n';
    return worst;
  }

  LawSettings film(const std::string &model, const std::map<std::string, double> &constants = {},
                   const std::map<std::string, std::string> &texts = {})
  {
    LawSettings s;
    s.model     = model;
    s.material  = {25.1e3, 60., 3.98e-11, 1e-3};
    s.constants = constants;
    s.texts     = texts;
    return s;
  }

  /// Three branches (30, 10, 5 kPa at 0.3, 2, 20 s) of @p spring.
  LawSettings spectrum(const std::string &spring, const bool thinning)
  {
    std::map<std::string, double> c{{"Network B shear modulus (kPa)", 45.},
                                    {"Network B Jlim", 80.},
                                    {"Relaxation time (s)", 2.},
                                    {"Mooney-Rivlin C2 (kPa)", 2.},
                                    {"Shear thinning eta_inf/eta_0", 0.2},
                                    {"Shear thinning K1/eta_0", 0.3},
                                    {"Shear thinning beta1", 1.5},
                                    {"Shear thinning K2 (1/kPa^2)", 0.01},
                                    {"Shear thinning beta2", 0.6}};
    std::map<std::string, std::string> t{{"Branch shear moduli (kPa)", "30, 10, 5"},
                                         {"Branch relaxation times (s)", "0.3, 2, 20"},
                                         {"Branch law", spring},
                                         {"Viscosity", thinning ? "shear thinning" : "newtonian"}};
    return film("viscoelastic", c, t);
  }
} // namespace

CDEA_TEST_MAIN()
{
  const double tolerance = 1e-6;
  const std::vector<TestKind> kinds{TestKind::uniaxial, TestKind::equibiaxial, TestKind::pure_shear};
  const LawParameter mu = LawParameter::shear_modulus, jlim = LawParameter::jlim;
  double       elastic = 0.;
  for (const TestKind kind : kinds)
    {
      elastic = std::max({elastic, check_case("Gent", film("elastic"), {mu, jlim}, kind, {}),
                          check_case("Mooney-Rivlin", film("mooney-rivlin", {{"Mooney-Rivlin C2 (kPa)", 3.}}),
                                     {mu, own_constant(0)}, kind, {}),
                          check_case("Ogden", film("ogden", {{"Ogden alpha 1", 1.6}, {"Ogden mu 2 (kPa)", -2.},
                                                             {"Ogden alpha 2", -1.5}, {"Ogden mu 3 (kPa)", 0.},
                                                             {"Ogden alpha 3", 1.}}),
                                     {mu, own_constant(0), own_constant(1), own_constant(2)}, kind, {}),
                          check_case("Gent-Gent", film("gent-gent", {{"Gent-Gent C2 (kPa)", 4.}}),
                                     {mu, jlim, own_constant(0)}, kind, {})});
    }
  check_close(elastic, 0., tolerance, "elastic laws: exact derivatives against central differences");

  std::vector<LawParameter> branches{mu, jlim};
  for (unsigned int k = 0; k < 6; ++k)
    branches.push_back(own_constant(k));
  const std::vector<std::pair<TimeMethod, std::string>> methods{
    {TimeMethod::backward_euler, "backward Euler"}, {TimeMethod::trapezoidal, "trapezoidal"},
    {TimeMethod::esdirk3, "ESDIRK3"}, {TimeMethod::esdirk4, "ESDIRK4"}};
  for (const auto &[method, name] : methods)
    {
      MaterialPointSettings point;
      point.method = method;
      double worst = 0.;
      for (const TestKind kind : kinds)
        worst = std::max(worst, check_case("3 Gent branches, " + name, spectrum("elastic", false),
                                           branches, kind, point));
      check_close(worst, 0., tolerance, "3 Gent branches, " + name + ": every constant");
    }
  MaterialPointSettings point;
  const double spring = check_case("3 Mooney-Rivlin branches", spectrum("mooney-rivlin", false),
                                   branches, TestKind::uniaxial, point);
  check_close(spring, 0., tolerance, "3 Mooney-Rivlin branches: every constant");

  std::vector<LawParameter> thinning = branches;
  for (unsigned int k = 6; k < 11; ++k)
    thinning.push_back(own_constant(k));
  double worst = 0.;
  for (const TimeMethod method : {TimeMethod::trapezoidal, TimeMethod::esdirk3})
    for (const TestKind kind : kinds)
      {
        point.method = method;
        worst = std::max(worst, check_case("shear thinning", spectrum("elastic", true), thinning,
                                           kind, point));
      }
  check_close(worst, 0., tolerance, "shear-thinning viscosity: its constants and the branches'");
  return cdea_test::finish();
}
