// Solver/Stability eigenvalue = near folds (StabilityCheck::compute_near_folds):
// stable or not from one factorization, the smallest eigenvalue only where
// the state is not positive definite or near a fold. Against the eigenvalue
// at every step,
//  - along the arc length through the full-electrode fold (as test_stability):
//    the same states and limit points, the same stable column at every step,
//    the eigenvalue where near folds reports one equal to every step's to
//    1e-10 relative, NaN elsewhere, and reported next to the fold;
//  - the pump (the water's rank-one coupling k g g^T, k > 0): the same;
//  - random symmetric band matrices, one check object along a family each:
//    the sign-only path (eigenvalue NaN) says positive definite only where
//    the dense eigenvalue is positive and above the fraction of the last
//    one computed; where it computes, the value equals compute()'s;
//  - a tangent singular to round-off: not positive definite, the eigenvalue
//    not computed (zero to round-off); one slightly indefinite: computed.

#include <cdea/base/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/input/solver_settings.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/model/output_fields.h>
#include <cdea/numerics/band_eigenvalue.h>

#include "check.h"
#include "scenes.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdlib>
#include <random>
#include <sstream>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// The two modes on fresh models of the same scene, step by step.
  void compare_modes(const std::string &name, const std::function<std::unique_ptr<EquilibriumModel>()> &make,
                     const Scene &scene, SteppingSettings settings, const bool expect_fold)
  {
    settings.stability_check      = true;
    settings.stability_eigenvalue = StabilityEigenvalue::every_step;
    const auto  every_model       = make();
    const RunTrace every          = trace_run(*every_model, scene, settings);
    settings.stability_eigenvalue = StabilityEigenvalue::near_folds;
    const auto  near_model        = make();
    const RunTrace near           = trace_run(*near_model, scene, settings);

    check(every.result.completed && near.result.completed &&
            every.steps.size() == near.steps.size(),
          name + ": both runs complete with the same number of steps (" +
            std::to_string(near.steps.size()) + ")");
    bool         same_states = every.result.limit_points.size() == near.result.limit_points.size();
    unsigned int stable_wrong = 0, value_wrong = 0, reported = 0, nan_where_every_finite = 0;
    double       worst = 0.;
    for (std::size_t i = 0; i < std::min(every.steps.size(), near.steps.size()); ++i)
      {
        const StepSummary &a = every.steps[i], &b = near.steps[i];
        same_states = same_states && a.displacement == b.displacement &&
                      a.load_factor == b.load_factor && a.voltages == b.voltages;
        stable_wrong += a.columns.get(summary_column::stable) != b.columns.get(summary_column::stable);
        const double la = a.columns.get(summary_column::min_eigenvalue);
        const double lb = b.columns.get(summary_column::min_eigenvalue);
        if (std::isnan(lb))
          nan_where_every_finite += !std::isnan(la);
        else
          {
            ++reported;
            const double error = std::abs(lb - la) / std::abs(la);
            worst              = std::max(worst, error);
            value_wrong += !(error <= 1e-10);
          }
      }
    for (std::size_t k = 0; same_states && k < every.result.limit_points.size(); ++k)
      same_states = every.result.limit_points[k].displacement ==
                    near.result.limit_points[k].displacement;
    check(same_states, name + ": the same states, bit for bit, and the same limit points");
    check(stable_wrong == 0, name + ": the same stable column at every step (" +
                               std::to_string(stable_wrong) + " differ)");
    std::ostringstream m;
    m << name << ": the eigenvalue at " << reported << " of " << near.steps.size()
      << " steps, equal to every step's to 1e-10 (worst " << worst << ")";
    check(value_wrong == 0 && reported >= 1, m.str());
    check(nan_where_every_finite > 0 && reported + nan_where_every_finite == near.steps.size(),
          name + ": NaN at the other " + std::to_string(nan_where_every_finite) + " steps");
    if (expect_fold)
      {
        // The steps next to the limit point (where the stable column flips)
        // report their eigenvalue, or are unstable with an eigenvalue zero
        // to round-off (every step's: below zero, above -1e-8; the flat start).
        const auto reported_or_zero = [&](const std::size_t i) {
          const double lb = near.steps[i].columns.get(summary_column::min_eigenvalue);
          const double la = every.steps[i].columns.get(summary_column::min_eigenvalue);
          return !std::isnan(lb) ||
                 (near.steps[i].columns.get(summary_column::stable) == 0. && la <= 0. &&
                  la > -1e-8);
        };
        unsigned int flips = 0, flips_reported = 0;
        for (std::size_t i = 1; i < near.steps.size(); ++i)
          if (near.steps[i].columns.get(summary_column::stable) !=
              near.steps[i - 1].columns.get(summary_column::stable))
            {
              ++flips;
              flips_reported += reported_or_zero(i) && reported_or_zero(i - 1);
            }
        check(flips >= 1 && flips_reported == flips,
              name + ": the eigenvalue reported on both sides of each of the " +
                std::to_string(flips) + " changes of the stable column");
      }
  }

  /// Random symmetric band matrices A + t B along t, one check object per
  /// family, compute_near_folds() against the dense eigenvalue and against
  /// compute() on the same matrices.
  void random_families()
  {
    std::mt19937                           random(11);
    std::uniform_real_distribution<double> u(-1., 1.);
    unsigned int calls = 0, sign_only = 0, sign_wrong = 0, below_fraction = 0, value_wrong = 0;
    unsigned int rank_one_sign_only = 0;
    for (int family = 0; family < 12; ++family)
      {
        const unsigned int n = 12 + 5 * family, kd = 1 + family % 7;
        BandMatrix         A, B;
        A.reinit(n, kd);
        B.reinit(n, kd);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i > kd ? i - kd : 0; j <= i; ++j)
            {
              A(i, j) = A(j, i) = i == j ? 6. + u(random) : 0.3 * u(random);
              B(i, j) = B(j, i) = i == j ? 1. + 0.5 * u(random) : 0.05 * u(random);
            }
        const std::vector<unsigned int> excluded{0, n - 1};
        const double                    k = family % 2 ? 2. : 0.;
        Eigen::VectorXd                 g(n);
        for (unsigned int i = 0; i < n; ++i)
          g[i] = i == 0 || i == n - 1 ? 0. : u(random);
        StabilityCheck near, every;
        double         last_computed = std::numeric_limits<double>::quiet_NaN();
        // From positive definite down through singular to indefinite.
        for (int s = 0; s <= 40; ++s)
          {
            BandMatrix K = A;
            K.add(-9. * s / 40., B);
            SymmetricBand S;
            S.assign(K, excluded);
            Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n - 2, n - 2);
            for (unsigned int i = 1; i + 1 < n; ++i)
              for (unsigned int j = 1; j + 1 < n; ++j)
                dense(i - 1, j - 1) = S.entry(i, j) + k * g[i] * g[j];
            const double lambda =
              Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense, Eigen::EigenvaluesOnly)
                .eigenvalues()[0];
            const TangentStability a = near.compute_near_folds(K, excluded, k, g);
            const TangentStability b = every.compute(K, excluded, k, g, true);
            ++calls;
            if (std::abs(lambda) > 1e-10)
              sign_wrong += a.positive_definite != (lambda > 0.);
            if (std::isnan(a.smallest_eigenvalue))
              {
                ++sign_only;
                rank_one_sign_only += k > 0.;
                // Skipped only where every eigenvalue is above the fraction
                // of the last one computed.
                below_fraction +=
                  !(lambda > StabilityCheck::near_fold_fraction * last_computed * (1. - 1e-12));
              }
            else
              {
                last_computed = a.smallest_eigenvalue;
                value_wrong += !(std::abs(a.smallest_eigenvalue - b.smallest_eigenvalue) <=
                                 1e-10 * std::abs(b.smallest_eigenvalue) + 1e-12);
              }
          }
      }
    std::ostringstream m;
    m << calls << " matrices along 12 families: positive definite exactly when the dense "
      << "eigenvalue is positive (" << sign_wrong << " wrong), the eigenvalue skipped at "
      << sign_only << " (" << rank_one_sign_only << " with k g g^T), each above "
      << StabilityCheck::near_fold_fraction << " of the last one computed (" << below_fraction
      << " not)";
    check(sign_wrong == 0 && below_fraction == 0 && sign_only > 40 && rank_one_sign_only > 20,
          m.str());
    check(value_wrong == 0, "where computed, the eigenvalue equals compute()'s to 1e-10 (" +
                              std::to_string(value_wrong) + " not)");
  }

  /// A tangent singular to round-off (the chain Laplacian, free ends: its
  /// null vector is constant) is reported not positive definite without its
  /// eigenvalue near folds; one slightly indefinite gets it.
  void singular_to_round_off()
  {
    const unsigned int n = 30;
    BandMatrix         L;
    L.reinit(n, 1);
    for (unsigned int i = 0; i + 1 < n; ++i)
      {
        L(i, i) += 1.;
        L(i + 1, i + 1) += 1.;
        L(i, i + 1) = L(i + 1, i) = -1.;
      }
    StabilityCheck         near, every;
    const TangentStability a = near.compute_near_folds(L, {}, 0., Eigen::VectorXd());
    const double           lambda = every.compute(L, {}, 0., Eigen::VectorXd(), true).smallest_eigenvalue;
    std::ostringstream     m;
    m << "singular to round-off (every step's eigenvalue " << lambda
      << "): not positive definite, the eigenvalue NaN";
    check(a.known && !a.positive_definite && std::isnan(a.smallest_eigenvalue) &&
            std::abs(lambda) < 1e-12,
          m.str());
    BandMatrix K = L;
    for (unsigned int i = 0; i < n; ++i)
      K(i, i) -= 1e-6;
    const TangentStability b = near.compute_near_folds(K, {}, 0., Eigen::VectorXd());
    check(!b.positive_definite && std::abs(b.smallest_eigenvalue + 1e-6) < 1e-12,
          "an eigenvalue of -1e-6 is computed near folds (" + std::to_string(b.smallest_eigenvalue) +
            ")");
  }

  std::string source_file(const std::string &relative)
  {
    const char *dir = std::getenv("CDEA_SOURCE_DIR");
    return std::string(dir ? dir : ".") + "/" + relative;
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  std::cout << "Random symmetric band matrices, with and without k g g^T\n";
  random_families();
  singular_to_round_off();

  std::cout << "Arc length through the full-electrode fold (p = 4, 16 elements)\n";
  {
    const Scene      scene = paper_scene({1., 3.}, {{8.}});
    SteppingSettings arc;
    arc.arc_length       = true;
    arc.max_displacement = 0.040;
    FeDiscretization disc;
    disc.elements_per_ring = 16;
    compare_modes(
      "arc length",
      [&] { return std::make_unique<MembraneModel>(scene, disc, NewtonSettings()); }, scene, arc,
      true);
  }
  std::cout << "The pump: the water's rank-one coupling (k > 0)\n";
  {
    const Parameters p     = read_parameters(source_file("prm/pump.prm"));
    const Scene      scene = p.scene();
    compare_modes(
      "prm/pump.prm", [&] { return make_fe_model(p, scene); }, scene, stepping_settings(p),
      false);
  }
  return finish();
}
