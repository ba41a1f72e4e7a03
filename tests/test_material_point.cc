// The material point of a homogeneous test (material/material_point.h)
// against closed forms (doc/materials.md, "The material-test model").
//
// 1. Every elastic law in the three tests, nominal stress s1 = dW/dl1 of
//    the loaded direction (formulas written here, independently of the
//    laws' code; Treloar 1975 for neo-Hooke, Rivlin and Saunders 1951 for
//    the Mooney-Rivlin pure shear, Ogden 1972, Gent 1996, Pucci and
//    Saccomandi 2002):
//      uniaxial     l2 = L^-1/2:  I1 = L^2 + 2/L,       I2 = 2 L + L^-2
//      equibiaxial  l2 = L:       I1 = 2 L^2 + L^-4,    I2 = 2 L^-2 + L^4
//      pure shear   l2 = 1:       I1 = I2 = L^2 + 1 + L^-2
//    neo-Hooke      mu (L - L^-2),  mu (L - L^-5),  mu (L - L^-3)
//    Mooney-Rivlin  (mu + 2 C2 / L)(L - L^-2), (mu + 2 C2 L^2)(L - L^-5), (mu + 2 C2)(L - L^-3)
//    Ogden          sum mu_p (L^(a-1) - L^(-a/2-1)), (L^(a-1) - L^(-2a-1)), (L^(a-1) - L^(-a-1))
//    Gent           the neo-Hooke forms over g = 1 - (I1 - 3) / Jlim
//    Gent-Gent      Gent + C2 terms 2 C2 (L - L^-2) / (L I2), 2 C2 L^2 (L - L^-5) / I2,
//                   2 C2 (L - L^-3) / I2.
// 2. The small-strain relaxation of a Prony series: network A and three
//    branches, a ramp of strain e0 over t_r and a hold. Linear
//    viscoelasticity gives, for t >= t_r,
//      s(t) = c (e0 / t_r) [mu_A t_r + sum_k mu_k tau_k (exp(-(t - t_r)/tau_k) - exp(-t/tau_k))],
//    c = 3 (uniaxial, E = 3 mu), 6 (equibiaxial), 4 (pure shear): each
//    branch's elastic strain relaxes with tau_k in every test.
// 3. The schemes' orders: backward Euler 1, trapezoidal 2, ESDIRK3 3,
//    ESDIRK4 4, on a finite-strain cycle against ESDIRK4 at 1/64 the step.
// 4. The default steps on lab histories against a fine ESDIRK4 run.
// 5. What the point refuses (a stretch beyond the Gent limit, times that do
//    not increase), with the sample named.

#include <cdea/material/material_point.h>
#include <cdea/material/two_network_gent.h>

#include "law_checks.h"

#include <cmath>
#include <functional>
#include <iostream>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// s1 of a closed form per test kind.
  using Form = std::function<double(double)>;

  struct ClosedForms
  {
    std::string                        name;
    std::shared_ptr<const MembraneLaw> law;
    Form                               uniaxial, equibiaxial, pure_shear;
  };

  StretchHistory ramp(const TestKind kind, const double top, const unsigned int n)
  {
    StretchHistory h;
    h.kind = kind;
    for (unsigned int k = 0; k <= n; ++k)
      {
        h.time.push_back(double(k));
        h.stretch.push_back(1. + (top - 1.) * double(k) / n);
      }
    return h;
  }

  void check_forms(const ClosedForms &c, const double mu)
  {
    for (const TestKind kind : {TestKind::uniaxial, TestKind::equibiaxial, TestKind::pure_shear})
      {
        const Form    &form = kind == TestKind::uniaxial    ? c.uniaxial :
                              kind == TestKind::equibiaxial ? c.equibiaxial :
                                                              c.pure_shear;
        const double   top  = kind == TestKind::equibiaxial ? 3.5 : 4.5;
        MaterialPoint  point(*c.law);
        MaterialPointResult r;
        std::string         message;
        const StretchHistory h = ramp(kind, top, 40);
        check(point.run(h, {}, r, message), c.name + ", " + test_kind_name(kind) + ": runs " + message);
        double worst = 0., worst_l2 = 0.;
        for (std::size_t k = 0; k < h.time.size() && r.stress.size() == h.time.size(); ++k)
          {
            const double L = h.stretch[k], s = form(L);
            const double l2 = kind == TestKind::uniaxial ? 1. / std::sqrt(L) :
                              kind == TestKind::equibiaxial ? L : 1.;
            worst    = std::max(worst, std::abs(r.stress[k] - s) / (std::abs(s) + mu));
            worst_l2 = std::max(worst_l2, std::abs(r.transverse[k] - l2));
          }
        check_close(worst, 0., 1e-13, c.name + ", " + test_kind_name(kind) +
                                        ": s1 against the closed form, L = 1 to " +
                                        std::to_string(top).substr(0, 3) + " (over |s1| + mu)");
        check_close(worst_l2, 0., 1e-14, c.name + ", " + test_kind_name(kind) + ": l2");
      }
  }

  void elastic_closed_forms()
  {
    const MaterialConstants film = paper_film();
    const double mu = film.shear_modulus, jlim = film.jlim, c2 = 5e3;
    const double a1 = 1.3, m2 = -3e3, a2 = -2., m3 = 0.5e3, a3 = 5.;
    const auto gent = [=](const double I1) { return 1. / (1. - (I1 - 3.) / jlim); };
    const auto I1u  = [](double L) { return L * L + 2. / L; };
    const auto I1e  = [](double L) { return 2. * L * L + std::pow(L, -4); };
    const auto I1p  = [](double L) { return L * L + 1. + 1. / (L * L); };
    const auto I2u  = [](double L) { return 2. * L + 1. / (L * L); };
    const auto I2e  = [](double L) { return 2. / (L * L) + std::pow(L, 4); };
    const auto nu   = [](double L) { return L - 1. / (L * L); };
    const auto ne   = [](double L) { return L - std::pow(L, -5); };
    const auto np   = [](double L) { return L - std::pow(L, -3); };
    const auto og   = [=](double L, double e) {
      double s = 0.;
      for (const auto &[m, a] : {std::pair{mu, a1}, {m2, a2}, {m3, a3}})
        s += m * (std::pow(L, a - 1.) - std::pow(L, -e * a - 1.));
      return s;
    };
    const std::vector<ClosedForms> forms{
      {"neo-hooke", law_named("neo-hooke", film), [=](double L) { return mu * nu(L); },
       [=](double L) { return mu * ne(L); }, [=](double L) { return mu * np(L); }},
      {"mooney-rivlin", law_named("mooney-rivlin", film, {{"Mooney-Rivlin C2 (kPa)", c2 * 1e-3}}),
       [=](double L) { return (mu + 2. * c2 / L) * nu(L); },
       [=](double L) { return (mu + 2. * c2 * L * L) * ne(L); },
       [=](double L) { return (mu + 2. * c2) * np(L); }},
      {"ogden",
       law_named("ogden", film,
                 {{"Ogden alpha 1", a1}, {"Ogden mu 2 (kPa)", m2 * 1e-3}, {"Ogden alpha 2", a2},
                  {"Ogden mu 3 (kPa)", m3 * 1e-3}, {"Ogden alpha 3", a3}}),
       [=](double L) { return og(L, 0.5); }, [=](double L) { return og(L, 2.); },
       [=](double L) { return og(L, 1.); }},
      {"elastic (Gent)", law_named("elastic", film),
       [=](double L) { return mu * nu(L) * gent(I1u(L)); },
       [=](double L) { return mu * ne(L) * gent(I1e(L)); },
       [=](double L) { return mu * np(L) * gent(I1p(L)); }},
      {"gent-gent", law_named("gent-gent", film, {{"Gent-Gent C2 (kPa)", c2 * 1e-3}}),
       [=](double L) { return nu(L) * (mu * gent(I1u(L)) + 2. * c2 / (L * I2u(L))); },
       [=](double L) { return ne(L) * (mu * gent(I1e(L)) + 2. * c2 * L * L / I2e(L)); },
       [=](double L) { return np(L) * (mu * gent(I1p(L)) + 2. * c2 / I1p(L)); }}};
    for (const ClosedForms &c : forms)
      check_forms(c, mu);
  }
} // namespace

namespace
{
  /// Network A (Gent, mu_A = 25.1 kPa) and three Gent branches.
  std::shared_ptr<const MembraneLaw> spectrum(const std::vector<ViscousNetwork> &branches,
                                              const double jlim = 270.)
  {
    MaterialConstants film = paper_film();
    film.jlim              = jlim;
    return std::make_shared<TwoNetworkGentLaw>(film, branches);
  }

  const std::vector<ViscousNetwork> three_branches{{30e3, 270., 0.1}, {10e3, 270., 1.}, {5e3, 270., 10.}};

  /// s1 of @p law along a ramp to strain @p e0 over @p t_r and a hold to 50 s.
  std::vector<double> ramp_and_hold(const MembraneLaw &law, const TestKind kind, const double e0,
                                    const double t_r, std::vector<double> &times)
  {
    StretchHistory h;
    h.kind = kind;
    for (unsigned int k = 0; k <= 20; ++k)
      {
        h.time.push_back(t_r * k / 20.);
        h.stretch.push_back(1. + e0 * k / 20.);
      }
    for (unsigned int k = 1; k <= 300; ++k)
      {
        h.time.push_back(t_r * std::pow(50. / t_r, k / 300.));
        h.stretch.push_back(1. + e0);
      }
    MaterialPointSettings settings;
    settings.method   = TimeMethod::esdirk4;
    settings.max_step = 2e-3;
    MaterialPoint       point(law, settings);
    MaterialPointResult r;
    std::string         message;
    check(point.run(h, {}, r, message), "Prony history runs " + message);
    times = h.time;
    return r.stress;
  }

  // The odd part (s(e0) - s(-e0)) / 2 of the response is linear to O(e0^3):
  // the geometric nonlinearity of the nominal stress is of second order.
  // e0 = 1e-4 keeps the branches' local updates (converged to 1e-13 in
  // ln xi) far below the strains.
  void prony_relaxation()
  {
    const auto   law = spectrum(three_branches);
    const double e0 = 1e-4, t_r = 0.05, mu_a = paper_film().shear_modulus;
    for (const TestKind kind : {TestKind::uniaxial, TestKind::equibiaxial, TestKind::pure_shear})
      {
        const double c = kind == TestKind::uniaxial ? 3. : kind == TestKind::equibiaxial ? 6. : 4.;
        std::vector<double>       times;
        const std::vector<double> up = ramp_and_hold(*law, kind, e0, t_r, times),
                                  down = ramp_and_hold(*law, kind, -e0, t_r, times);
        const double              peak = c * e0 * (mu_a + 45e3);
        double                    worst = 0.;
        for (std::size_t k = 20; k < times.size() && up.size() == times.size(); ++k)
          {
            const double t = times[k];
            double       s = mu_a * t_r;
            for (const ViscousNetwork &b : three_branches)
              s += b.shear_modulus * b.relaxation_time *
                   (std::exp(-(t - t_r) / b.relaxation_time) - std::exp(-t / b.relaxation_time));
            s *= c * e0 / t_r;
            worst = std::max(worst, std::abs(0.5 * (up[k] - down[k]) - s) / peak);
          }
        check_close(worst, 0., 1e-6, std::string("small-strain ") + test_kind_name(kind) +
                                       " relaxation against the Prony series (over the peak "
                                       "stress, t = 0.05 to 50 s)");
      }
  }

  /// s1 along a finite-strain uniaxial cycle with @p method and @p max_step.
  std::vector<double> cycle(const TimeMethod method, const double max_step)
  {
    StretchHistory h;
    for (unsigned int k = 0; k <= 40; ++k)
      {
        h.time.push_back(0.25 * k);
        h.stretch.push_back(1. + 1.5 * std::pow(std::sin(M_PI * 0.25 * k / 10.), 2));
      }
    MaterialPointSettings settings;
    settings.method           = method;
    settings.max_step         = max_step;
    settings.max_stretch_step = HUGE_VAL; // equal steps of max_step
    settings.step_growth      = 0.;
    const auto          law = spectrum({{30e3, 60., 1.}, {10e3, 60., 3.}, {5e3, 60., 30.}});
    MaterialPoint       point(*law, settings);
    MaterialPointResult r;
    std::string         message;
    check(point.run(h, {}, r, message), "cycle runs " + message);
    return r.stress;
  }

  void orders()
  {
    const std::vector<double> reference = cycle(TimeMethod::esdirk4, 0.25 / 256.);
    double                    scale     = 0.;
    for (const double s : reference)
      scale = std::max(scale, std::abs(s));
    const std::vector<std::pair<TimeMethod, std::string>> methods{
      {TimeMethod::backward_euler, "backward Euler"},
      {TimeMethod::trapezoidal, "trapezoidal"},
      {TimeMethod::esdirk3, "ESDIRK3"},
      {TimeMethod::esdirk4, "ESDIRK4"}};
    for (std::size_t m = 0; m < methods.size(); ++m)
      {
        std::vector<double> error;
        for (const double h : {0.25, 0.125, 0.0625, 0.03125})
          {
            const std::vector<double> s = cycle(methods[m].first, h);
            double                    e = 0.;
            for (std::size_t k = 0; k < s.size() && s.size() == reference.size(); ++k)
              e = std::max(e, std::abs(s[k] - reference[k]) / scale);
            error.push_back(e);
          }
        std::cout << methods[m].second << ": errors (over the largest stress) at steps 0.25 .. 0.03125 s:";
        for (const double e : error)
          std::cout << ' ' << e;
        const double order = std::log2(error[error.size() - 2] / error.back());
        std::cout << "; last order " << order << '\n';
        check_close(order, double(m + 1), 0.25, methods[m].second + ": observed order");
      }
  }

  /// The default steps (trapezoidal rule, graded after every change of the
  /// stretch rate) against ESDIRK4 at 1/64 of the sample interval, on lab
  /// histories: uniaxial ramps at 0.05 and 1 /s to stretch 3 held 300 s
  /// (1 Hz), and cycles at 0.05 /s between 1 and 3 (10 Hz), with the fastest
  /// branch at 0.1 or 1 s (others 10 and 100 s).
  void default_steps()
  {
    double worst = 0., worst_one = 0.;
    for (const double tau : {0.1, 1.})
      for (const int history : {0, 1, 2})
        {
          const auto law = spectrum({{30e3, 270., tau}, {10e3, 270., 10.}, {5e3, 270., 100.}});
          const double   dt = history == 2 ? 0.1 : 1., rate = history == 1 ? 1. : 0.05;
          StretchHistory h;
          for (double t = 0.; t <= (history == 2 ? 160. : 2. / rate + 300.) + 1e-9; t += dt)
            {
              const double phase = std::fmod(t, 80.);
              h.time.push_back(t);
              h.stretch.push_back(history == 2 ? 1. + 0.05 * std::min(phase, 80. - phase) :
                                                 1. + rate * std::min(t, 2. / rate));
            }
          MaterialPointSettings fine;
          fine.method           = TimeMethod::esdirk4;
          fine.max_step         = dt / 64.;
          fine.max_stretch_step = HUGE_VAL;
          fine.step_growth      = 0.;
          MaterialPointSettings plain; // one trapezoidal step per sample
          plain.max_stretch_step = HUGE_VAL;
          plain.step_growth      = 0.;
          MaterialPoint       reference(*law, fine), point(*law), one(*law, plain);
          MaterialPointResult a, b, c;
          std::string         message;
          check(reference.run(h, {}, a, message) && point.run(h, {}, b, message) &&
                  one.run(h, {}, c, message),
                "lab history runs " + message);
          double error = 0., error_one = 0., scale = 0.;
          for (std::size_t k = 0; k < a.stress.size() && b.stress.size() == a.stress.size() &&
                                  c.stress.size() == a.stress.size();
               ++k)
            {
              error     = std::max(error, std::abs(a.stress[k] - b.stress[k]));
              error_one = std::max(error_one, std::abs(a.stress[k] - c.stress[k]));
              scale     = std::max(scale, std::abs(a.stress[k]));
            }
          std::cout << "  history " << history << ", tau_1 = " << tau << " s: default " << b.steps
                    << " steps for " << h.time.size() - 1 << " intervals, error "
                    << error / scale << "; one step per interval: " << error_one / scale
                    << " (over the largest stress)\n";
          worst     = std::max(worst, error / scale);
          worst_one = std::max(worst_one, error_one / scale);
        }
    check_close(worst, 0., 3e-4, "default steps on lab histories: largest error (over the largest stress)");
    check(worst_one > 10. * worst, "the graded steps at least ten times as accurate as one step per "
                                   "interval (" + std::to_string(worst_one) + ")");
  }

  void refusals()
  {
    const auto          law = spectrum(three_branches, 10.);
    MaterialPoint       point(*law);
    MaterialPointResult r;
    std::string         message;
    StretchHistory      h = ramp(TestKind::uniaxial, 4., 30);
    check(!point.run(h, {}, r, message), "a stretch beyond the Gent limit (Jlim 10) is refused");
    std::cout << "  message: " << message << '\n';
    check(message.find("sample 27 (t = 26 s, stretch 3.6)") == 0, "the message names the sample");
    h         = ramp(TestKind::uniaxial, 2., 4);
    h.time[3]          = h.time[2];
    const bool refused = !point.run(h, {}, r, message);
    check(refused &&
            message.find("sample 4 (t = 2 s, stretch 1.75): the sample times must increase") == 0,
          "times that do not increase are refused: " + message);
  }
} // namespace

CDEA_TEST_MAIN()
{
  elastic_closed_forms();
  prony_relaxation();
  orders();
  default_steps();
  refusals();
  return finish();
}
