// The shear-thinning viscosity of network B's dashpots (viscosity.h,
// doc/materials.md "The relaxation spectrum"):
//  - K1 = 0 and K2 = 0 (or eta_inf = eta_0 and K1 = 0) is the Newtonian
//    branch: the FE time run of a homogeneous film to 1e-12;
//  - the local update solves the stage residual: at the law's answer the
//    residual, written here from the Gent spring and the viscosity's formula,
//    is zero (both schemes), and branch_residual()'s Jacobian agrees with
//    central differences of its residual;
//  - linearize() (rates and stress against the internal variables and the
//    stretches) against central differences of evaluate() with dt = 0;
//  - a material point stretched at a constant rate, integrated by the law's
//    trapezoidal rule, against a Runge-Kutta integration of the same ODE
//    written here; the error falls as dt^2;
//  - the FE film converges with the inexact tangent, and its answer
//    converges in the step size (backward Euler: first order);
//  - the entries' checks name the entry and what is allowed.

#include <cdea/base/text.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/material/viscosity.h>

#include "check.h"
#include "fe_checks.h"

#include <Eigen/Dense>

#include <cmath>
#include <iostream>
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
  const double mu_b = 45e3, jlim_b = 60., tau = 2.;

  /// The VHB 4910 constants of Kumar and Lopez-Pamies, K2 in 1/kPa^2.
  std::map<std::string, double> vhb(const double k2_kPa = 1e-6)
  {
    return {{"Shear thinning eta_inf/eta_0", 0.1 / 7014.},
            {"Shear thinning K1/eta_0", 0.5},
            {"Shear thinning beta1", 1.852},
            {"Shear thinning K2 (1/kPa^2)", k2_kPa},
            {"Shear thinning beta2", 0.26}};
  }

  /// The viscoelastic law of one branch (45 kPa, Jlim 60, 2 s) with the
  /// shear-thinning @p constants (none: Newtonian).
  std::shared_ptr<const MembraneLaw> law_of(const MaterialConstants             &film,
                                            const std::map<std::string, double> &constants,
                                            const std::string &viscosity = "shear thinning")
  {
    LawSettings s;
    s.model     = "viscoelastic";
    s.material  = film;
    s.constants = {{"Network B shear modulus (kPa)", mu_b * 1e-3},
                   {"Network B Jlim", jlim_b},
                   {"Relaxation time (s)", tau}};
    for (const auto &[name, value] : constants)
      s.constants[name] = value;
    if (!constants.empty())
      s.texts["Viscosity"] = viscosity;
    return make_membrane_law(s);
  }

  /// The film's load at time @p t, with a dead load of @p mass (kg) on the disk.
  LoadState load(const double t, const double mass)
  {
    return cdea_test::film_load(t, 2.5 + 0.3 * std::sin(M_PI * t), voltage, mass);
  }

  struct FilmRun
  {
    double       s1 = 0., xi1 = 0.;
    unsigned int newton = 0; ///< iterations over the run
    bool         converged = true;
  };

  /// The homogeneous film from the relaxed state over 1 s in steps of @p dt.
  FilmRun film_run(const Scene &scene, const std::shared_ptr<const MembraneLaw> &law,
                   const double dt, const TimeScheme scheme = TimeScheme::backward_euler,
                   const double mass = 0.)
  {
    MembraneModel model(scene, cdea_test::discretization(2, 2), NewtonSettings());
    model.set_material_law(law);
    model.set_time_step(std::numeric_limits<double>::infinity(), scheme);
    FilmRun run;
    run.converged = model.solve(load(0., mass)).converged;
    model.relax_internal_variables();
    const unsigned int n = static_cast<unsigned int>(std::lround(1. / dt));
    for (unsigned int k = 0; k < n && run.converged; ++k)
      {
        model.set_time_step(dt, scheme);
        const SolveReport r = model.solve(load((k + 1) * dt, mass));
        run.converged       = r.converged;
        run.newton += r.iterations;
        model.accept_time_step();
      }
    model.set_time_step(0., scheme);
    const StepFields f = model.fields();
    run.s1             = f.s1[0];
    for (const InternalField &v : f.internal)
      if (v.name == "xi1")
        run.xi1 = v.values[0];
    return run;
  }

  void check_newtonian_limit(const Scene &scene)
  {
    const auto newtonian = law_of(scene.material, {});
    auto       no_k      = vhb(0.);
    no_k["Shear thinning K1/eta_0"] = 0.;
    auto equal_etas                         = vhb();
    equal_etas["Shear thinning eta_inf/eta_0"] = 1.;
    equal_etas["Shear thinning K1/eta_0"]      = 0.;
    for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::trapezoidal})
      {
        const std::string name = scheme == TimeScheme::trapezoidal ? " (trapezoidal)" : "";
        const FilmRun     a    = film_run(scene, newtonian, 0.1, scheme);
        const FilmRun     b    = film_run(scene, law_of(scene.material, no_k), 0.1, scheme);
        const FilmRun     c    = film_run(scene, law_of(scene.material, equal_etas), 0.1, scheme);
        check(a.converged && b.converged && c.converged, "Newtonian-limit runs converge" + name);
        check_rel(b.s1, a.s1, 1e-12, "K1 = K2 = 0: s1 of the Newtonian run" + name);
        check_rel(b.xi1, a.xi1, 1e-12, "K1 = K2 = 0: xi1 of the Newtonian run" + name);
        check_rel(c.s1, a.s1, 1e-12, "eta_inf = eta_0, K1 = 0: s1 of the Newtonian run" + name);
        check_rel(c.xi1, a.xi1, 1e-12, "eta_inf = eta_0, K1 = 0: xi1 of the Newtonian run" + name);
      }
  }

  // The law written out here, independently of the library: Gent spring B
  // at a = l / xi, s_i = (mu / g) (a_i^2 - (a1 a2)^-2), g = 1 - (I1 - 3) / Jlim,
  // the viscosity of the paper and the rate de/dt = M s, M = [[2, -1], [-1, 2]] / (6 eta).
  struct Reference
  {
    double r, k1, beta1, k2, beta2; // k2 in 1/Pa^2

    Eigen::Vector2d stress(const double l1, const double l2, const Eigen::Vector2d &e) const
    {
      const double a1 = l1 * std::exp(-e[0]), a2 = l2 * std::exp(-e[1]);
      const double p  = 1. / (a1 * a1 * a2 * a2);
      const double g  = 1. - (a1 * a1 + a2 * a2 + p - 3.) / jlim_b;
      return Eigen::Vector2d(a1 * a1 - p, a2 * a2 - p) * mu_b / g;
    }
    double eta(const Eigen::Vector2d &e, const Eigen::Vector2d &s) const
    {
      const double eta0 = mu_b * tau;
      const double i1v  = std::exp(2. * e[0]) + std::exp(2. * e[1]) + std::exp(-2. * (e[0] + e[1]));
      const double j2   = (s[0] * s[0] + s[1] * s[1] - s[0] * s[1]) / 3.;
      return r * eta0 + (eta0 * (1. - r) + k1 * eta0 * (std::pow(i1v, beta1) - std::pow(3., beta1))) /
                          (1. + std::pow(k2 * j2, beta2));
    }
    Eigen::Vector2d rate(const double l1, const double l2, const Eigen::Vector2d &e) const
    {
      const Eigen::Vector2d s = stress(l1, l2, e);
      return Eigen::Vector2d(2. * s[0] - s[1], 2. * s[1] - s[0]) / (6. * eta(e, s));
    }
  };

  const Reference vhb_reference{0.1 / 7014., 0.5, 1.852, 1e-12, 0.26};

  void check_residual(const MaterialConstants &film)
  {
    const auto          law = law_of(film, vhb());
    const Eigen::Vector2d e0(std::log(1.7), std::log(2.3));
    const double        l1 = 2.9, l2 = 2.2;
    double              worst = 0., worst_rate = 0., worst_work = 0.;
    for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::trapezoidal})
      for (const double dt : {0.01, 0.5, 20.})
        {
          const Eigen::Vector2d q0 = vhb_reference.rate(2.5, 2.4, e0);
          double old[4] = {std::exp(e0[0]), std::exp(e0[1]), q0[0], q0[1]}, current[4] = {};
          LawResponse r;
          if (!check(law->evaluate({l1, l2, voltage}, {old, current, dt, scheme}, law_stress, r),
                     "the point updates"))
            return;
          const Eigen::Vector2d e(std::log(current[0]), std::log(current[1]));
          const Eigen::Vector2d q = vhb_reference.rate(l1, l2, e);
          // Backward Euler: e - e0 = dt q(e); trapezoidal: e - e0 = dt (q0 + q(e)) / 2.
          const Eigen::Vector2d R = scheme == TimeScheme::trapezoidal ?
                                      Eigen::Vector2d(e - e0 - 0.5 * dt * (q0 + q)) :
                                      Eigen::Vector2d(e - e0 - dt * q);
          worst      = std::max(worst, R.lpNorm<Eigen::Infinity>());
          worst_rate = std::max(worst_rate, std::max(std::abs(current[2] - q[0]),
                                                     std::abs(current[3] - q[1])) /
                                              q.lpNorm<Eigen::Infinity>());
          // The dashpot's work over the step: dt s . q (backward Euler), the
          // mean of the end powers times dt (trapezoidal).
          const double power = vhb_reference.stress(l1, l2, e).dot(q);
          const double work  = scheme == TimeScheme::trapezoidal ?
                                 0.5 * dt * (power + vhb_reference.stress(2.5, 2.4, e0).dot(q0)) :
                                 dt * power;
          worst_work = std::max(worst_work, std::abs(law->dissipation({old, current, dt, scheme}) - work) / work);
        }
    check_close(worst, 0., 1e-12, "stage residual at the update (in ln xi; both schemes, dt 0.01 to 20 s)");
    check_close(worst_rate, 0., 1e-12, "stored rate q = M(eta) s at the update");
    check_close(worst_work, 0., 1e-10, "dissipation over the step (relative)");

    // branch_residual()'s Jacobian against central differences, with a
    // neo-Hooke spring: W_e = -mu (a_i^2 - p), W_ee = mu (2 a_i^2 delta_ij + 2 p).
    const ShearThinning t{true, 0.1 / 7014., 0.5, 1.852, 1e-9, 0.26};
    const auto          residual = [&](const Eigen::Vector2d &e, const double c, const Eigen::Vector2d &q0) {
      const double a1 = l1 * std::exp(-e[0]), a2 = l2 * std::exp(-e[1]), p = 1. / (a1 * a1 * a2 * a2);
      Eigen::Matrix2d W_ee;
      W_ee << 2. * a1 * a1 + 2. * p, 2. * p, 2. * p, 2. * a2 * a2 + 2. * p;
      return branch_residual(t, mu_b * tau, c, e, e0, q0, -mu_b * Eigen::Vector2d(a1 * a1 - p, a2 * a2 - p),
                             mu_b * W_ee);
    };
    double worst_jacobian = 0., asymmetry = 0.;
    for (const auto &[c, q0] : {std::pair{2., Eigen::Vector2d(0., 0.)}, std::pair{40., Eigen::Vector2d(0.3, -0.1)}})
      for (const Eigen::Vector2d &e : {Eigen::Vector2d(0.9, 0.7), Eigen::Vector2d(0.6, 0.95)})
        {
          const BranchResidual b = residual(e, c, q0);
          asymmetry              = std::max(asymmetry, std::abs(b.jacobian(0, 1) - b.jacobian(1, 0)) / b.jacobian.norm());
          for (int j = 0; j < 2; ++j)
            {
              const double   h = 1e-6;
              Eigen::Vector2d d = Eigen::Vector2d::Zero();
              d[j]              = h;
              const Eigen::Vector2d fd = (residual(e + d, c, q0).G - residual(e - d, c, q0).G) / (2. * h);
              worst_jacobian = std::max(worst_jacobian, (fd - b.jacobian.col(j)).norm() / b.jacobian.norm());
            }
        }
    check_close(worst_jacobian, 0., 1e-8, "local Jacobian dG/de against central differences");
    check(asymmetry > 1e-3, "the local Jacobian is unsymmetric (" + std::to_string(asymmetry) + ")");
  }

  /// linearize() against central differences of the rate and stress that
  /// evaluate() stores and returns with dt = 0 (xi held).
  void check_linearize(const MaterialConstants &film)
  {
    const auto  law = law_of(film, vhb(1e-3));
    const auto  at  = [&](const double l1, const double l2, const double xi1, const double xi2,
                        Eigen::Vector2d &q, Eigen::Vector2d &s) {
      double      old[4] = {xi1, xi2, 0., 0.}, current[4] = {};
      LawResponse r;
      law->evaluate({l1, l2, voltage}, {old, current, 0., TimeScheme::backward_euler}, law_stress, r);
      q = Eigen::Vector2d(current[2], current[3]);
      s = Eigen::Vector2d(r.stress.s1, r.stress.s2);
    };
    const double          l[2] = {2.8, 2.3}, xi[2] = {2.1, 1.9};
    const double          stored[4] = {xi[0], xi[1], 0., 0.};
    InternalLinearization lin;
    if (!check(law->linearize({l[0], l[1], voltage}, stored, lin), "linearize at a stressed point"))
      return;
    double worst_rate = 0., worst_stress = 0.;
    Eigen::Vector2d q0, s0;
    at(l[0], l[1], xi[0], xi[1], q0, s0);
    for (int j = 0; j < 2; ++j)
      {
        const double    h = 1e-6;
        Eigen::Vector2d qp, qm, sp, sm;
        // Against y_j = ln xi_j.
        at(l[0], l[1], xi[0] * (j == 0 ? std::exp(h) : 1.), xi[1] * (j == 1 ? std::exp(h) : 1.), qp, sp);
        at(l[0], l[1], xi[0] * (j == 0 ? std::exp(-h) : 1.), xi[1] * (j == 1 ? std::exp(-h) : 1.), qm, sm);
        for (int i = 0; i < 2; ++i)
          {
            worst_rate = std::max(worst_rate, std::abs((qp[i] - qm[i]) / (2. * h) - lin.rate_y[i * 2 + j]) /
                                                q0.norm());
            worst_stress = std::max(worst_stress, std::abs((sp[i] - sm[i]) / (2. * h) - lin.stress_y[i * 2 + j]) /
                                                    s0.norm());
          }
        // Against l_j.
        at(l[0] + (j == 0 ? h : 0.), l[1] + (j == 1 ? h : 0.), xi[0], xi[1], qp, sp);
        at(l[0] - (j == 0 ? h : 0.), l[1] - (j == 1 ? h : 0.), xi[0], xi[1], qm, sm);
        for (int i = 0; i < 2; ++i)
          worst_rate = std::max(worst_rate, std::abs((qp[i] - qm[i]) / (2. * h) - lin.rate_l[i * 2 + j]) /
                                              q0.norm());
      }
    check_close(worst_rate, 0., 1e-7, "linearize: rate_y and rate_l against central differences");
    check_close(worst_stress, 0., 1e-7, "linearize: stress_y against central differences");
    // The power of the dashpot, s . q with the branch's stress written here.
    const Reference       strong{0.1 / 7014., 0.5, 1.852, 1e-9, 0.26};
    const Eigen::Vector2d e(std::log(xi[0]), std::log(xi[1]));
    check_rel(q0.norm(), strong.rate(l[0], l[1], e).norm(), 1e-12, "the stored rate at dt = 0");
    const double stored_q[4] = {xi[0], xi[1], q0[0], q0[1]};
    check_rel(law->dissipation_rate(stored_q), strong.stress(l[0], l[1], e).dot(q0), 1e-10,
              "dissipation rate from the stored rate: s . q");
  }

  /// xi1, xi2 after 2 s of l = (1 + t, 1 + 0.4 t) from the relaxed state,
  /// by the law's trapezoidal rule in @p n steps.
  Eigen::Vector2d creep_by_law(const MembraneLaw &law, const unsigned int n)
  {
    double       old[4] = {1., 1., 0., 0.}, current[4] = {};
    const double dt     = 2. / n;
    for (unsigned int k = 1; k <= n; ++k)
      {
        LawResponse r;
        if (!law.evaluate({1. + k * dt, 1. + 0.4 * k * dt, 0.}, {old, current, dt, TimeScheme::trapezoidal},
                          law_stress, r))
          return Eigen::Vector2d::Constant(std::nan(""));
        std::copy(current, current + 4, old);
      }
    return Eigen::Vector2d(old[0], old[1]);
  }

  /// The same by the classical Runge-Kutta method on de/dt = M(eta) s.
  Eigen::Vector2d creep_by_runge_kutta(const Reference &ref, const unsigned int n)
  {
    Eigen::Vector2d e = Eigen::Vector2d::Zero();
    const double    h = 2. / n;
    const auto      f = [&](const double t, const Eigen::Vector2d &y) {
      return ref.rate(1. + t, 1. + 0.4 * t, y);
    };
    for (unsigned int k = 0; k < n; ++k)
      {
        const double          t  = k * h;
        const Eigen::Vector2d k1 = f(t, e), k2 = f(t + h / 2, e + h / 2 * k1),
                              k3 = f(t + h / 2, e + h / 2 * k2), k4 = f(t + h, e + h * k3);
        e += h / 6. * (k1 + 2. * k2 + 2. * k3 + k4);
      }
    return Eigen::Vector2d(std::exp(e[0]), std::exp(e[1]));
  }

  void check_creep(const MaterialConstants &film)
  {
    // tau = 2 s and K2 = 1e-3 / kPa^2: the viscosity thins to about a
    // fifth as the branch's stress grows.
    const auto            law   = law_of(film, vhb(1e-3));
    const Reference       ref{0.1 / 7014., 0.5, 1.852, 1e-9, 0.26};
    const Eigen::Vector2d exact = creep_by_runge_kutta(ref, 20000);
    check_rel(exact[0], creep_by_runge_kutta(ref, 10000)[0], 1e-13, "Runge-Kutta converged");
    const Eigen::Vector2d coarse = creep_by_law(*law, 500), fine = creep_by_law(*law, 1000);
    const double e_coarse = (coarse - exact).lpNorm<Eigen::Infinity>(),
                 e_fine   = (fine - exact).lpNorm<Eigen::Infinity>();
    const Eigen::Vector2d newtonian = creep_by_law(*law_of(film, {}), 1000);
    check((newtonian - fine).lpNorm<Eigen::Infinity>() > 1e-2,
          "the thinning changes the creep (xi1 " + std::to_string(fine[0]) + " against Newtonian " +
            std::to_string(newtonian[0]) + ")");
    check_close(e_fine, 0., 1e-7, "creep at a constant stretch rate: xi after 2 s, 1000 trapezoidal steps against Runge-Kutta");
    check_close(e_coarse / e_fine, 4., 0.2, "the error falls as dt^2");
  }

  /// The cone under the mass (not homogeneous: Newton iterates).
  void check_film(const Scene &scene)
  {
    const auto    law = law_of(scene.material, vhb(1e-3));
    const TimeScheme euler = TimeScheme::backward_euler;
    const double     mass  = 0.05;
    const FilmRun    a = film_run(scene, law, 0.1, euler, mass), b = film_run(scene, law, 0.05, euler, mass),
                  c = film_run(scene, law, 0.025, euler, mass);
    const FilmRun newtonian = film_run(scene, law_of(scene.material, {}), 0.05, euler, mass);
    check(a.converged && b.converged && c.converged, "the film converges with the inexact tangent");
    std::cout << "  Newton iterations over 20 steps of 0.05 s: " << b.newton << " (Newtonian "
              << newtonian.newton << ")\n";
    check(b.newton <= 3 * newtonian.newton, "at most three times the Newtonian run's iterations");
    check(std::abs(b.xi1 - newtonian.xi1) > 1e-3, "the thinning changes the film's creep");
    // Halving dt from 0.1 s: the differences of xi1 and s1 shrink by 2 to 4
    // each time (backward Euler is first order; at these steps the second
    // order term still shows: the ratios fall towards 2, 3.6, 3.3, 2.9).
    const FilmRun d     = film_run(scene, law, 0.0125, euler, mass);
    const double  x[4] = {a.xi1, b.xi1, c.xi1, d.xi1}, s[4] = {a.s1, b.s1, c.s1, d.s1};
    bool          shrinks = true;
    std::string   ratios;
    for (int k = 0; k + 2 < 4; ++k)
      for (const double *v : {x, s})
        {
          const double ratio = std::abs(v[k] - v[k + 1]) / std::abs(v[k + 1] - v[k + 2]);
          shrinks            = shrinks && ratio > 1.8 && ratio < 4.2;
          ratios += " " + std::to_string(ratio);
        }
    check(shrinks, "xi1 and s1 converge in the step size: difference ratios" + ratios);
    check_close(std::abs(c.s1 - d.s1) / std::abs(d.s1), 0., 1e-6, "s1 at dt = 0.025 against 0.0125 s");
  }

  std::string message_of(const MaterialConstants &film, const std::map<std::string, double> &constants,
                         const std::string &viscosity = "shear thinning")
  {
    try
      {
        law_of(film, constants, viscosity);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  void check_messages(const MaterialConstants &film)
  {
    const auto has = [&](const std::string &entry, const double value, const std::string &part) {
      auto c   = vhb();
      c[entry] = value;
      const std::string m = message_of(film, c);
      check(m.find(part) != std::string::npos, "message '" + m + "' says '" + part + "'");
    };
    has("Shear thinning eta_inf/eta_0", 0., "Material/Shear thinning eta_inf/eta_0 must be above 0 and at most 1, got 0");
    has("Shear thinning eta_inf/eta_0", 2., "Material/Shear thinning eta_inf/eta_0 must be above 0 and at most 1, got 2");
    has("Shear thinning K1/eta_0", -1., "Material/Shear thinning K1/eta_0 must be at least 0 and at most 1e+06, got -1");
    has("Shear thinning beta1", 0., "Material/Shear thinning beta1 must be above 0 and at most 10, got 0");
    has("Shear thinning K2 (1/kPa^2)", -1e-6, "Material/Shear thinning K2 (1/kPa^2) must be at least 0");
    has("Shear thinning beta2", 11., "Material/Shear thinning beta2 must be above 0 and at most 10, got 11");
    const std::string m = message_of(film, vhb(), "thin");
    check(m.find("Material/Viscosity must be 'newtonian' or 'shear thinning', got 'thin'") != std::string::npos,
          "message '" + m + "' names Material/Viscosity");
    check(message_of(film, vhb()).empty(), "the VHB 4910 constants build");
    check(law_of(film, vhb())->tangent_is_exact() == false && law_of(film, {})->tangent_is_exact(),
          "the tangent is inexact only with shear thinning");
  }
} // namespace

CDEA_TEST_MAIN()
{
  Scene scene = cdea::paper_scene({1., 3.}, {{voltage * 1e-3}});
  scene.mass  = 0.;
  check_newtonian_limit(scene);
  check_residual(scene.material);
  check_linearize(scene.material);
  check_creep(scene.material);
  check_film(cdea::paper_scene({1., 3.}, {{voltage * 1e-3}}));
  check_messages(scene.material);
  return cdea_test::finish();
}
