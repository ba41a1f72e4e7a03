// The stability check (numerics/band_eigenvalue.h): the inertia of its
// factorizations against the sign of the eigenvalue the check computed
// before (LAPACK dsbevx on the band, a dense solver for the water's rank-one
// term: numerics/eigenvalue_reference.h), and its smallest eigenvalue by
// Lanczos against that eigenvalue,
//  - on random symmetric band matrices: sizes 1 to 150, bandwidths 0 to 15,
//    definite, with one or many negative eigenvalues, nearly singular on
//    either side, with and without excluded dofs and a rank-one term;
//  - along a family whose two lowest modes cross, one check object carrying
//    its last eigenvector from one matrix to the next;
//  - at every step of the fold scenes (prm/fold-full.prm, prm/fold-rv1.7.prm,
//    and the arc length through the full-electrode fold of test_stability)
//    and of the pump (the water's rank-one coupling): the stable column
//    changes only at the located limit points, which stay where they were.

#include <cdea/analysis/run_setup.h>
#include <cdea/base/mpi_session.h>
#include <cdea/fe/cell_kernel.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/input/solver_settings.h>
#include <cdea/model/output_fields.h>
#include <cdea/numerics/band_eigenvalue.h>
#include <cdea/numerics/eigenvalue_reference.h>
#include <cdea/solver/postprocessors.h>

#include "check.h"
#include "scenes.h"

#include <Eigen/Eigenvalues>

#include <cstdlib>
#include <memory>
#include <random>
#include <sstream>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// How the test matrix is shifted: its smallest eigenvalue (without the
  /// excluded dofs) relative to the spread of the spectrum.
  enum class Kind
  {
    definite,
    one_negative,
    many_negative,
    nearly_singular_above,
    nearly_singular_below
  };

  struct Tally
  {
    unsigned int matrices = 0, sign_checked = 0, sign_wrong = 0, value_wrong = 0;
    unsigned int count_checked = 0, count_wrong = 0;
    double       worst_value = 0.; ///< |new - old| / (|old| + 1e-6 spectrum)
  };

  /// A random band matrix shifted as @p kind says, with the rank-one term if
  /// @p rank_one; then the check against the reference and the dense inertia.
  void random_case(std::mt19937 &random, const unsigned int n, const unsigned int kd,
                   const Kind kind, const bool rank_one, const bool exclude, Tally &tally)
  {
    std::uniform_real_distribution<double> u(-1., 1.);
    BandMatrix                             K;
    K.reinit(n, kd);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i > kd ? i - kd : 0; j <= std::min(n - 1, i + kd); ++j)
        K(i, j) = u(random) * (i == j ? 3. : 1.); // unsymmetric: the check takes (K + K^T)/2
    std::vector<unsigned int> excluded;
    if (exclude && n > 3)
      excluded = {0, n / 2, n - 1};
    SymmetricBand S;
    S.assign(K, excluded);
    std::vector<unsigned int> kept;
    for (unsigned int i = 0; i < n; ++i)
      if (!S.excluded(i))
        kept.push_back(i);
    Eigen::MatrixXd dense(kept.size(), kept.size());
    for (std::size_t a = 0; a < kept.size(); ++a)
      for (std::size_t b = 0; b < kept.size(); ++b)
        dense(a, b) = S.entry(kept[a], kept[b]);
    const Eigen::VectorXd ev =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense, Eigen::EigenvaluesOnly).eigenvalues();
    const double spread = ev.cwiseAbs().maxCoeff() + 1.;
    double       shift  = 0.;
    switch (kind)
      {
        case Kind::definite:
          shift = ev[0] - spread * (0.01 + 0.3 * std::abs(u(random)));
          break;
        case Kind::one_negative:
          shift = ev.size() > 1 ? 0.5 * (ev[0] + ev[1]) : ev[0] + 0.1;
          break;
        case Kind::many_negative:
          shift = ev[ev.size() / 2] + 1e-3 * spread;
          break;
        case Kind::nearly_singular_above:
          shift = ev[0] - 1e-9 * spread;
          break;
        case Kind::nearly_singular_below:
          shift = ev[0] + 1e-9 * spread;
          break;
      }
    for (unsigned int i = 0; i < n; ++i)
      K(i, i) -= shift;

    Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
    double          k = 0.;
    if (rank_one)
      {
        k = spread * std::abs(u(random));
        for (const unsigned int i : kept)
          g[i] = u(random);
      }
    const double reference = rank_one ? reference::smallest_symmetric_eigenvalue(K, k, g, excluded) :
                                        reference::smallest_symmetric_eigenvalue(K, excluded);
    StabilityCheck         check;
    const TangentStability t = check.compute(K, excluded, k, g, true);
    ++tally.matrices;
    // The reference is exact to round-off of the spectrum's size; a sign at
    // that level is no answer.
    if (std::abs(reference) > 1e-10 * spread)
      {
        ++tally.sign_checked;
        tally.sign_wrong += t.positive_definite != (reference > 0.);
      }
    const double error =
      std::abs(t.smallest_eigenvalue - reference) / (std::abs(reference) + 1e-6 * spread);
    tally.worst_value = std::max(tally.worst_value, error);
    tally.value_wrong += !(std::abs(t.smallest_eigenvalue - reference) <=
                           1e-10 * std::abs(reference) + 1e-13 * spread);

    // The LDL^T's count of negative pivots against the dense inertia (away
    // from zero, where the count has an answer).
    if (!rank_one && (ev.array() - shift).abs().minCoeff() > 1e-8 * spread)
      {
        SymmetricBand shifted;
        shifted.assign(K, excluded);
        unsigned int negative = 0;
        for (Eigen::Index i = 0; i < ev.size(); ++i)
          negative += ev[i] - shift < 0.;
        ++tally.count_checked;
        tally.count_wrong += band_inertia(shifted, 0.).negative != negative;
      }
  }

  void random_matrices()
  {
    std::cout << "Random symmetric band matrices against dsbevx and the dense solver\n";
    std::mt19937 random(2024);
    Tally        tally;
    const Kind   kinds[] = {Kind::definite, Kind::one_negative, Kind::many_negative,
                            Kind::nearly_singular_above, Kind::nearly_singular_below};
    for (const unsigned int n : {1u, 2u, 5u, 17u, 40u, 91u, 150u})
      for (const unsigned int kd : {0u, 1u, 4u, 9u, 15u})
        for (const Kind kind : kinds)
          for (int variant = 0; variant < 4; ++variant)
            random_case(random, n, std::min(kd, n - 1), kind, variant % 2 == 1, variant >= 2,
                        tally);
    std::ostringstream m;
    m << tally.matrices << " matrices: positive definite exactly when the eigenvalue is "
      << "positive (" << tally.sign_checked << " signs away from round-off, " << tally.sign_wrong
      << " wrong)";
    check(tally.sign_wrong == 0, m.str());
    check(tally.value_wrong == 0,
          "smallest eigenvalue within 1e-10 of the reference plus 1e-13 of the spectrum (" +
            std::to_string(tally.value_wrong) + " outside; worst relative " +
            std::to_string(tally.worst_value) + ")");
    check(tally.count_checked > 100 && tally.count_wrong == 0,
          "LDL^T negative pivots = negative eigenvalues (" + std::to_string(tally.count_checked) +
            " matrices)");
  }

  void crossing_modes()
  {
    std::cout << "Two lowest modes crossing, one check object along the family\n";
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> u(-1., 1.);
    unsigned int                           wrong = 0, steps = 0, calls = 0;
    for (int family = 0; family < 40; ++family)
      {
        const unsigned int n = 20 + family * 3, kd = 1 + family % 9;
        BandMatrix         A, B;
        A.reinit(n, kd);
        B.reinit(n, kd);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i > kd ? i - kd : 0; j <= i; ++j)
            {
              A(i, j) = A(j, i) = i == j ? 5. + 3. * u(random) : 0.3 * u(random);
              B(i, j) = B(j, i) = i == j ? 4. * u(random) : 0.05 * u(random);
            }
        const std::vector<unsigned int> excluded{0, n - 1};
        const double                    k = family % 2 ? 3. : 0.;
        Eigen::VectorXd                 g(n);
        for (unsigned int i = 0; i < n; ++i)
          g[i] = i == 0 || i == n - 1 ? 0. : u(random);
        StabilityCheck check;
        for (int s = 0; s <= 60; ++s)
          {
            BandMatrix K = A;
            K.add(-1.5 + 3. * s / 60., B);
            const double reference = k != 0. ? reference::smallest_symmetric_eigenvalue(K, k, g, excluded) :
                                               reference::smallest_symmetric_eigenvalue(K, excluded);
            const TangentStability t = check.compute(K, excluded, k, g, true);
            steps += check.lanczos_steps();
            ++calls;
            wrong += !(std::abs(t.smallest_eigenvalue - reference) <=
                       1e-10 * std::abs(reference) + 1e-12) ||
                     (std::abs(reference) > 1e-10 && t.positive_definite != (reference > 0.));
          }
      }
    check(wrong == 0, std::to_string(calls) + " matrices: the smallest eigenvalue and its sign "
                                              "follow every crossing (" +
                        std::to_string(wrong) + " wrong; " +
                        std::to_string(double(steps) / calls) + " Lanczos steps per matrix)");
  }

  /// What AgainstReference found over a run.
  struct ReferenceTally
  {
    unsigned int rows = 0, signs = 0, sign_wrong = 0, value_wrong = 0;
    double       worst_to_scale = 0., worst_away_from_zero = 0.;
  };

  /// After the standard postprocessors: the stable column and the eigenvalue
  /// of every state the run evaluates (its steps and the states of its
  /// crossing searches) against the reference on the model's tangent.
  class AgainstReference final : public Postprocessor
  {
  public:
    AgainstReference(MembraneModel &model, std::shared_ptr<ReferenceTally> tally)
      : model(model)
      , tally(std::move(tally))
    {}

    void evaluate(StepContext &, StepSummary &summary) override
    {
      AssembledSystem system;
      model.assemble(assemble_residual | assemble_tangent, system);
      const std::vector<unsigned int> &constrained = model.discretization().constrained;
      Eigen::VectorXd                  g           = system.volume_gradient;
      for (const unsigned int i : constrained)
        if (g.size() > 0)
          g[i] = 0.;
      const double reference =
        system.rank_one_coupling != 0. ?
          reference::smallest_symmetric_eigenvalue(system.tangent, system.rank_one_coupling, g,
                                                   constrained) :
          reference::smallest_symmetric_eigenvalue(system.tangent, constrained);
      double scale = 0.;
      for (unsigned int i = 0; i < system.tangent.size(); ++i)
        scale = std::max(scale, std::abs(system.tangent.entry(i, i)));
      const double    lambda = summary.min_eigenvalue;
      ReferenceTally &t      = *tally;
      ++t.rows;
      if (std::abs(reference) > 1e-12 * scale)
        {
          ++t.signs;
          t.sign_wrong += summary.columns.get(summary_column::stable) != double(reference > 0.);
        }
      t.worst_to_scale = std::max(t.worst_to_scale, std::abs(lambda - reference) / scale);
      t.value_wrong +=
        !(std::abs(lambda - reference) <= 1e-10 * std::abs(reference) + 1e-13 * scale);
      if (std::abs(reference) > 1e-6 * scale)
        t.worst_away_from_zero =
          std::max(t.worst_away_from_zero, std::abs(lambda - reference) / std::abs(reference));
    }

  private:
    MembraneModel                  &model;
    std::shared_ptr<ReferenceTally> tally;
  };

  /// The rows of a run with the check against the reference at every step.
  struct CheckedRun
  {
    RunResult                       result;
    std::vector<StepSummary>        steps;
    std::shared_ptr<ReferenceTally> tally = std::make_shared<ReferenceTally>();
  };

  CheckedRun checked_run(MembraneModel &model, const Scene &scene, const SteppingSettings &settings)
  {
    CheckedRun  run;
    LoadStepper stepper(scene, model, settings);
    stepper.add_postprocessor(std::make_unique<AgainstReference>(model, run.tally));
    stepper.on_step = [&](const StepSummary &s) { run.steps.push_back(s); };
    run.result      = stepper.run();
    return run;
  }

  /// The assertions on a run: signs and values against the reference, and
  /// (arc length) the stable column changing only next to a limit point.
  void assert_run(const std::string &name, const CheckedRun &run)
  {
    const ReferenceTally &a = *run.tally;
    check(run.result.completed, name + ": the run completes (" + run.result.end + ")");
    check(a.sign_wrong == 0, name + ": stable = the sign of the dsbevx eigenvalue at " +
                               std::to_string(a.signs) + " of " + std::to_string(a.rows) +
                               " states (the others at round-off of the tangent)");
    std::ostringstream m;
    m << name << ": min_eigenvalue within 1e-10 of dsbevx plus 1e-13 of the tangent's diagonal "
      << "(worst " << a.worst_away_from_zero << " relative where |lambda| > 1e-6 of it, "
      << a.worst_to_scale << " of it anywhere)";
    check(a.value_wrong == 0, m.str());
    // Along an arc-length path the inertia changes at folds only.
    const auto stable = [](const StepSummary &s) { return s.columns.get(summary_column::stable); };
    unsigned int changes_off_folds = 0, changes = 0;
    const auto   at_fold = [&](const StepSummary &s) {
      for (const LimitPoint &lp : run.result.limit_points)
        if (std::abs(s.load_factor - lp.load_factor) < 1e-12 &&
            std::abs(s.displacement - lp.displacement) < 1e-12)
          return true;
      return false;
    };
    for (std::size_t i = 1; i < run.steps.size(); ++i)
      if (stable(run.steps[i]) != stable(run.steps[i - 1]) && run.steps[i].stage == Stage::voltage)
        {
          ++changes;
          changes_off_folds += !at_fold(run.steps[i]) && !at_fold(run.steps[i - 1]);
        }
    if (!run.result.limit_points.empty())
      check(changes >= 1 && changes_off_folds == 0,
            name + ": the stable column changes " + std::to_string(changes) +
              " times in the voltage stage, each at a limit point");
  }

  std::string source_file(const std::string &relative)
  {
    const char *dir = std::getenv("CDEA_SOURCE_DIR");
    return std::string(dir ? dir : ".") + "/" + relative;
  }

  void prm_scene(const std::string &file, const std::vector<double> &fold_kV)
  {
    const Parameters p     = read_parameters(source_file(file));
    const Scene      scene = p.scene();
    const auto       model = make_fe_model(p, scene);
    SteppingSettings settings = stepping_settings(p);
    settings.stability_check  = true;
    const CheckedRun run      = checked_run(*model, scene, settings);
    assert_run(file, run);
    check(run.result.limit_points.size() == fold_kV.size(),
          file + ": " + std::to_string(fold_kV.size()) + " limit points");
    for (std::size_t i = 0; i < std::min(fold_kV.size(), run.result.limit_points.size()); ++i)
      check_rel(run.result.limit_points[i].voltages.back() * 1e-3, fold_kV[i], 1e-9,
                file + ": limit point " + std::to_string(i + 1) + " (kV) where it was");
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  random_matrices();
  crossing_modes();

  std::cout << "Fold scenes: every step against the dsbevx eigenvalue\n";
  // The limit points as the check before the factorization located them
  // (`cdea run` of the files; the eigenvalue takes no part in locating them).
  prm_scene("prm/fold-full.prm", {6.630906395817, 5.759381704698});
  prm_scene("prm/fold-rv1.7.prm", {7.565902475856, 5.9605761976});
  {
    const Scene      scene = paper_scene({1., 3.}, {{8.}});
    SteppingSettings arc;
    arc.arc_length       = true;
    arc.max_displacement = 0.040;
    arc.stability_check  = true;
    FeDiscretization disc;
    disc.elements_per_ring = 16;
    MembraneModel fe(scene, disc, NewtonSettings());
    assert_run("test_stability's arc length (p = 4, 16 elements)", checked_run(fe, scene, arc));
  }
  std::cout << "The pump: the water's rank-one coupling\n";
  {
    const Parameters p     = read_parameters(source_file("prm/pump.prm"));
    const Scene      scene = p.scene();
    const auto       model = make_fe_model(p, scene);
    SteppingSettings settings = stepping_settings(p);
    settings.stability_check  = true;
    assert_run("prm/pump.prm", checked_run(*model, scene, settings));
  }
  return finish();
}
