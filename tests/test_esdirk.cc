// The ESDIRK time integration (numerics/esdirk.h, solver/esdirk_step.h):
//  - the tableaus: the order conditions of their order and of the embedded
//    order, stage order 2 (sum_j a_ij c_j = c_i^2 / 2) and L-stability
//    (R(z) -> 0 for z -> -infinity, main and embedded);
//  - a smooth case, the viscoelastic film on a ramp-hold (steps landing on
//    the ramp's end, no inertia): the displacement at the end of fixed steps
//    converges to a reference (ESDIRK4 at relative tolerance 1e-11) with
//    order about 3 (ESDIRK3) and 4 (ESDIRK4);
//  - error control (steps of up to 1 s), ESDIRK3 and 4 at relative
//    tolerances 1e-9..1e-5: the estimated global error (the sum of the local
//    estimates of the embedded, lower order) bounds the true error, and
//    the error (above the reference's 1e-13 m) and the estimate grow and the steps taken
//    fall as the tolerance loosens; halving it (and 5e-9 -> 1e-9) moves the
//    answer by less than the estimate;
//  - the limit of the old fixed-step scheme: the trapezoidal rule's steps,
//    Richardson-extrapolated from 5 and 2.5 ms, give the same displacement
//    as ESDIRK4 at tight tolerance to 1e-7 relative;
//  - with the disk's inertia (a lightly damped oscillator): error control at
//    1e-8 agrees with Newmark's fixed steps extrapolated to zero step.

#include <cdea/fe/membrane_model.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/numerics/esdirk.h>
#include <cdea/solver/time_stepper.h>

#include "check.h"
#include "fe_checks.h"
#include "scenes.h"

#include <Eigen/Dense>

#include <cmath>
#include <iostream>
#include <memory>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_close;

namespace
{
  const Scene scene = cdea::paper_scene({1., 3.}, {{5.}});

  /// b . phi for the tableau's stage vector phi.
  double dot(const std::vector<double> &b, const Eigen::VectorXd &phi)
  {
    double s = 0.;
    for (std::size_t j = 0; j < b.size(); ++j)
      s += b[j] * phi[j];
    return s;
  }

  /// The order conditions up to order 4 (those of the order @p p) with the
  /// weights @p b; the largest defect.
  double order_defect(const EsdirkTableau &T, const std::vector<double> &b, const unsigned int p)
  {
    const unsigned int s = T.stages();
    Eigen::MatrixXd    A = Eigen::MatrixXd::Zero(s, s);
    Eigen::VectorXd    c(s), one = Eigen::VectorXd::Ones(s);
    for (unsigned int i = 0; i < s; ++i)
      {
        c[i] = T.c[i];
        for (unsigned int j = 0; j <= i && j < T.a[i].size(); ++j)
          A(i, j) = T.a[i][j];
      }
    const Eigen::VectorXd c2 = c.cwiseProduct(c), Ac = A * c;
    std::vector<std::pair<Eigen::VectorXd, double>> trees = {{one, 1.}};
    if (p >= 2)
      trees.push_back({c, 1. / 2});
    if (p >= 3)
      {
        trees.push_back({c2, 1. / 3});
        trees.push_back({Ac, 1. / 6});
      }
    if (p >= 4)
      {
        trees.push_back({c2.cwiseProduct(c), 1. / 4});
        trees.push_back({c.cwiseProduct(Ac), 1. / 8});
        trees.push_back({A * c2, 1. / 12});
        trees.push_back({A * Ac, 1. / 24});
      }
    double worst = 0.;
    for (const auto &[phi, value] : trees)
      worst = std::max(worst, std::abs(dot(b, phi) - value));
    return worst;
  }

  /// |R(z)| at z = -1e8 for the weights @p b: R = 1 + z b^T (I - z A)^-1 1.
  double stiff_limit(const EsdirkTableau &T, const std::vector<double> &b)
  {
    const unsigned int s = T.stages();
    const double       z = -1e8;
    Eigen::MatrixXd    M = Eigen::MatrixXd::Identity(s, s);
    for (unsigned int i = 0; i < s; ++i)
      for (unsigned int j = 0; j <= i && j < T.a[i].size(); ++j)
        M(i, j) -= z * T.a[i][j];
    const Eigen::VectorXd k = M.lu().solve(Eigen::VectorXd::Ones(s));
    return std::abs(1. + z * dot(b, k));
  }

  void check_tableau(const EsdirkTableau &T)
  {
    std::vector<double> b(T.stages()), b_hat = T.b_hat;
    double              stage_order = 0.;
    for (unsigned int i = 0; i < T.stages(); ++i)
      {
        b[i]       = T.b(i);
        double sum = 0., sum_c = 0.;
        for (unsigned int j = 0; j < T.a[i].size(); ++j)
          {
            sum += T.a[i][j];
            sum_c += T.a[i][j] * T.c[j];
          }
        stage_order = std::max({stage_order, std::abs(sum - T.c[i]),
                                std::abs(sum_c - 0.5 * T.c[i] * T.c[i])});
        if (i > 0)
          stage_order = std::max(stage_order, std::abs(T.a[i][i] - T.gamma));
      }
    std::cout << T.name << ": order defect " << order_defect(T, b, T.order) << ", embedded "
              << order_defect(T, b_hat, T.embedded_order) << ", stage order " << stage_order
              << ", |R(-1e8)| " << stiff_limit(T, b) << ", embedded " << stiff_limit(T, b_hat)
              << '\n';
    check(order_defect(T, b, T.order) < 1e-14, T.name + ": order conditions");
    check(order_defect(T, b_hat, T.embedded_order) < 1e-14, T.name + ": embedded order");
    check(order_defect(T, b_hat, T.order) > 1e-3, T.name + ": the embedded pair differs");
    check(stage_order < 1e-14, T.name + ": row sums c, stage order 2, diagonal gamma");
    check(stiff_limit(T, b) < 1e-6, T.name + ": L-stable");
    // ESDIRK3's embedded weights are bounded at z -> -infinity (|R| 1.006),
    // ESDIRK4's L-stable too.
    check(stiff_limit(T, b_hat) < (T.order == 4 ? 1e-6 : 1.01), T.name + ": embedded bounded");
  }

  struct Outcome
  {
    double       displacement   = 0.; ///< m, at the end
    double       error_estimate = 0.; ///< m
    unsigned int steps = 0, rejected = 0;
  };

  Outcome run(const TimeMethod method, const TimeStepControl control, const double dt,
              const double tolerance, const bool inertia, const double hold = 1.)
  {
    MembraneModel model(scene, cdea_test::discretization(4, 4), NewtonSettings());
    model.set_material_law(
      std::make_shared<TwoNetworkGentLaw>(scene.material, ViscousNetwork{45e3, 270., 2.}));
    TimeSettings s;
    s.waveform               = Waveform::ramp_hold(scene.path.voltages(1.), 1., hold);
    s.max_step               = dt;
    s.method                 = method;
    s.control                = control;
    s.relative_tolerance     = tolerance;
    s.displacement_tolerance = 1e-3 * tolerance; // m: relative to 1 mm
    s.internal_tolerance     = tolerance;
    s.inertia                = inertia;
    TimeStepper stepper(scene, model, SteppingSettings(), s);
    Outcome     o;
    stepper.on_step   = [&](const StepSummary &summary) { o.displacement = summary.displacement; };
    const RunResult r = stepper.run();
    if (!check(r.completed, "time run completes"))
      std::cout << r.message << '\n';
    check_close(stepper.time(), 1. + hold, 1e-12, "ends at the end of the waveform");
    o.error_estimate = r.error_estimate;
    o.steps          = r.time_steps;
    o.rejected       = r.rejected_steps;
    return o;
  }

  void fixed_step_order(const TimeMethod method, const double reference, const double lowest)
  {
    double previous = 0.;
    for (const double dt : {0.2, 0.1, 0.05})
      {
        const double error = std::abs(
          run(method, TimeStepControl::fixed, dt, 1e-6, false).displacement - reference);
        std::cout << "  " << esdirk_tableau(method)->name << " fixed " << dt << " s: error " << error;
        if (previous > 0.)
          std::cout << ", order " << std::log2(previous / error);
        std::cout << '\n';
        if (previous > 0.)
          check(std::log2(previous / error) > lowest, "order of " + esdirk_tableau(method)->name);
        previous = error;
      }
  }
} // namespace

CDEA_TEST_MAIN()
{
  check_tableau(esdirk3());
  check_tableau(esdirk4());

  // The smooth case: no inertia.
  const double reference =
    run(TimeMethod::esdirk4, TimeStepControl::error, 0.1, 1e-11, false).displacement;
  std::cout << "reference displacement " << reference * 1e3 << " mm\n";
  fixed_step_order(TimeMethod::esdirk3, reference, 2.6);
  fixed_step_order(TimeMethod::esdirk4, reference, 3.5);

  // Error control with steps of up to 1 s: the estimate against the error.
  for (const TimeMethod method : {TimeMethod::esdirk3, TimeMethod::esdirk4})
    {
      Outcome      previous;
      double       previous_error = 0.;
      const double tolerances[]   = {1e-9, 5e-9, 1e-8, 1e-7, 1e-6, 1e-5};
      for (const double tolerance : tolerances)
        {
          const Outcome o     = run(method, TimeStepControl::error, 1., tolerance, false);
          const double  error = std::abs(o.displacement - reference);
          std::cout << "  " << esdirk_tableau(method)->name << " tolerance " << tolerance << ": "
                    << o.steps << " steps, " << o.rejected << " rejected, error " << error
                    << ", estimate " << o.error_estimate << '\n';
          check(error < o.error_estimate, "the estimate bounds the error");
          if (previous.steps > 0)
            {
              check(o.steps < previous.steps, "fewer steps at a looser tolerance");
              // (above the reference's own error, about 1e-13 m)
              if (error > 1e-11)
                check(error > previous_error, "a larger error at a looser tolerance");
              check(o.error_estimate > previous.error_estimate, "a larger estimate");
              if (tolerance == tolerances[1] || tolerance == tolerances[2])
                check(std::abs(o.displacement - previous.displacement) < o.error_estimate,
                      "tightening the tolerance moves the answer by less than the estimate");
            }
          previous       = o;
          previous_error = error;
        }
    }

  // The old fixed-step scheme's limit: the trapezoidal rule, extrapolated.
  {
    const double u1 =
      run(TimeMethod::trapezoidal, TimeStepControl::fixed, 0.005, 1e-6, false).displacement;
    const double u2 =
      run(TimeMethod::trapezoidal, TimeStepControl::fixed, 0.0025, 1e-6, false).displacement;
    const double limit = (4. * u2 - u1) / 3.;
    std::cout << "trapezoidal: " << u1 * 1e3 << ", " << u2 * 1e3 << " mm, extrapolated "
              << limit * 1e3 << " mm\n";
    check_close(limit / reference, 1., 1e-7, "the fixed-step scheme's limit");
  }

  // With inertia: Newmark (second order) extrapolated against error control.
  {
    const double hold = 0.5;
    const double u1 =
      run(TimeMethod::trapezoidal, TimeStepControl::fixed, 0.001, 1e-6, true, hold).displacement;
    const double u2 =
      run(TimeMethod::trapezoidal, TimeStepControl::fixed, 0.0005, 1e-6, true, hold).displacement;
    const double  limit = (4. * u2 - u1) / 3.;
    const Outcome o     = run(TimeMethod::esdirk4, TimeStepControl::error, 0.1, 1e-8, true, hold);
    std::cout << "inertia: Newmark " << u1 * 1e3 << ", " << u2 * 1e3 << " mm, extrapolated "
              << limit * 1e3 << " mm; ESDIRK4 at 1e-8: " << o.displacement * 1e3 << " mm in "
              << o.steps << " steps, " << o.rejected << " rejected\n";
    check_close(o.displacement / limit, 1., 1e-7, "inertia: the fixed-step limit");
  }
  return cdea_test::finish();
}
