#pragma once
// Checks shared by the tests of the law library (test_*_law.cc): a law built
// by its registered name from plain settings, its energy, stresses and
// tangent against Sacado's second-order AD of an energy written
// independently in the test, and against central differences; its parameter
// derivatives against central differences of laws rebuilt with a perturbed
// constant; the tension-field relaxation's natural width.

#include <Sacado.hpp>

#include <cdea/material/law_factory.h>
#include <cdea/material/tension_field.h>

#include "check.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace cdea_test
{
  using Fad  = Sacado::Fad::DFad<double>;
  using Fad2 = Sacado::Fad::DFad<Fad>;

  /// The paper's film (SI): mu = 25.1 kPa, Jlim = 270, eps, H = 1 mm.
  inline cdea::MaterialConstants paper_film() { return {25.1e3, 270., 3.98e-11, 1e-3}; }

  /// Settings of the registered law @p model with @p film and @p constants
  /// (the entries in the file's units); every other law's entries at values
  /// that do not matter to it.
  inline cdea::LawSettings law_settings(const std::string &model,
                                        const cdea::MaterialConstants &film,
                                        const std::map<std::string, double> &constants)
  {
    cdea::LawSettings s;
    s.model     = model;
    s.material  = film;
    s.constants = constants;
    return s;
  }

  inline std::shared_ptr<const cdea::MembraneLaw> law_named(
    const std::string &model, const cdea::MaterialConstants &film,
    const std::map<std::string, double> &constants = {})
  {
    return cdea::make_membrane_law(law_settings(model, film, constants));
  }

  /// Every quantity of evaluate() at (l1, l2, voltage); false outside the range.
  inline bool respond(const cdea::MembraneLaw &law, const double l1, const double l2,
                      const double voltage, cdea::LawResponse &r)
  {
    return law.evaluate({l1, l2, voltage}, {}, cdea::law_energy | cdea::law_stress |
                                                 cdea::law_tangent, r);
  }

  /// The stretches and voltages the tests run over: from the flat film to the
  /// disk edge at high voltage (l1 up to 4, l2 from 1.5 to 3.5, 0 to 6 kV).
  struct Grid
  {
    std::vector<double> l1{1.2, 2.5, 4.0}, l2{1.5, 2.5, 3.5}, voltage{0., 3e3, 6e3};
  };

  /// Energy, stresses and tangent of @p law against Sacado's derivatives of
  /// @p energy(l1, l2, voltage) (a generic lambda), relative to |value| + mu
  /// (tolerance @p ad_tol), and against central differences of the law's own
  /// energy and stresses (@p fd_tol).
  template <typename Energy>
  void check_against_ad(const cdea::MembraneLaw &law, const Energy &energy, const double mu,
                        const std::string &name, const double ad_tol = 1e-12,
                        const double fd_tol = 1e-7, const Grid &grid = Grid())
  {
    double worst_ad = 0., worst_fd = 0., worst_w = 0.;
    bool   all_in   = true;
    for (const double phi : grid.voltage)
      for (const double l1 : grid.l1)
        for (const double l2 : grid.l2)
          {
            cdea::LawResponse r;
            if (!respond(law, l1, l2, phi, r))
              {
                all_in = false;
                continue;
              }
            Fad2       a1(2, 0, Fad(2, 0, l1)), a2(2, 1, Fad(2, 1, l2));
            const Fad2 w   = energy(a1, a2, phi);
            const auto rel = [&](const double a, const double b) {
              return std::abs(a - b) / (std::abs(b) + mu);
            };
            worst_w  = std::max(worst_w, rel(r.energy, w.val().val()));
            worst_ad = std::max({worst_ad, rel(r.stress.s1, w.dx(0).val()),
                                 rel(r.stress.s2, w.dx(1).val()), rel(r.tangent.s11, w.dx(0).dx(0)),
                                 rel(r.tangent.s12, w.dx(0).dx(1)),
                                 rel(r.tangent.s12, w.dx(1).dx(0)),
                                 rel(r.tangent.s22, w.dx(1).dx(1))});
            const double h  = 1e-5;
            const auto   at = [&](const double a, const double b) {
              cdea::LawResponse x;
              respond(law, a, b, phi, x);
              return x;
            };
            const auto p1 = at(l1 + h, l2), m1 = at(l1 - h, l2);
            const auto p2 = at(l1, l2 + h), m2 = at(l1, l2 - h);
            const double scale = 10. * mu;
            for (const double e :
                 {r.stress.s1 - (p1.energy - m1.energy) / (2 * h),
                  r.stress.s2 - (p2.energy - m2.energy) / (2 * h),
                  r.tangent.s11 - (p1.stress.s1 - m1.stress.s1) / (2 * h),
                  r.tangent.s12 - (p2.stress.s1 - m2.stress.s1) / (2 * h),
                  r.tangent.s12 - (p1.stress.s2 - m1.stress.s2) / (2 * h),
                  r.tangent.s22 - (p2.stress.s2 - m2.stress.s2) / (2 * h)})
              worst_fd = std::max(worst_fd, std::abs(e) / scale);
          }
    check(all_in, name + ": every point of the grid inside the law's range");
    check_close(worst_w, 0., ad_tol, name + ": energy vs the test's energy (rel.)");
    check_close(worst_ad, 0., ad_tol, name + ": stresses and tangent vs Sacado AD (rel.)");
    check_close(worst_fd, 0., fd_tol, name + ": stresses and tangent vs central differences");
  }

  /// The parameter derivatives of the law built by @p make(value) for
  /// parameter @p p at value @p value, against central differences of its
  /// energy and stresses (relative step 1e-6), on the grid.
  inline void check_parameter_derivative(
    const std::function<std::shared_ptr<const cdea::MembraneLaw>(double)> &make,
    const cdea::LawParameter p, const double value, const std::string &what,
    const double tol = 1e-6, const Grid &grid = Grid())
  {
    const auto   law = make(value);
    const double h   = 1e-6 * std::max(std::abs(value), 1e-3);
    const auto plus = make(value + h), minus = make(value - h);
    double     worst = 0.;
    bool       given = true;
    for (const double phi : grid.voltage)
      for (const double l1 : grid.l1)
        for (const double l2 : grid.l2)
          {
            double              dW = 0.;
            cdea::NominalStress ds{0., 0.};
            given = law->parameter_derivative({l1, l2, phi}, {}, p, dW, ds) && given;
            cdea::LawResponse a, b;
            respond(*plus, l1, l2, phi, a);
            respond(*minus, l1, l2, phi, b);
            const double fW = (a.energy - b.energy) / (2 * h);
            const double f1 = (a.stress.s1 - b.stress.s1) / (2 * h);
            const double f2 = (a.stress.s2 - b.stress.s2) / (2 * h);
            const double scale =
              std::max({std::abs(fW), std::abs(f1), std::abs(f2), 1e-30}) + 1e-9;
            worst = std::max({worst, std::abs(dW - fW) / scale, std::abs(ds.s1 - f1) / scale,
                              std::abs(ds.s2 - f2) / scale});
          }
    check(given, what + ": parameter_derivative() given at every point");
    check_close(worst, 0., tol, what + ": parameter derivative vs central differences (rel.)");
  }

  /// The tension-field relaxation of @p law where the plain hoop stress is
  /// negative: the natural width w* > l2 is found with s2(l1, w*) = 0 and
  /// the relaxed s1 is the law's s1 there.
  inline void check_natural_width(const std::shared_ptr<const cdea::MembraneLaw> &law,
                                  const double l1, const double l2, const double voltage,
                                  const std::string &name)
  {
    const cdea::TensionField relaxed(law);
    const cdea::LawResponse  r = relaxed.relax({l1, l2, voltage});
    cdea::LawResponse        plain, at_w;
    respond(*law, l1, l2, voltage, plain);
    if (!check(plain.stress.s2 < 0. && r.tension == cdea::TensionState::wrinkled &&
                 r.natural_width > l2,
               name + ": wrinkled at l1 = " + std::to_string(l1) + ", l2 = " +
                 std::to_string(l2) + ", natural width " + std::to_string(r.natural_width)))
      return;
    respond(*law, l1, r.natural_width, voltage, at_w);
    check_close(at_w.stress.s2 / std::abs(plain.stress.s2), 0., 1e-12,
                name + ": s2 at the natural width (over |s2| at l2)");
    check_close(r.stress.s1 / at_w.stress.s1, 1., 1e-15, name + ": relaxed s1 = s1 at w*");
  }
} // namespace cdea_test
