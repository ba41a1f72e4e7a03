#pragma once
// The numerical error of a converged FE state's key outputs, estimated
// after the fact (doc/accuracy.md):
//  - discretization: the state embedded in the richer space of degree p + 1
//    on the same mesh (exactly: a polynomial of degree p is one of degree
//    p + 1), solved there by Newton from it, and the change of each output
//    taken as the error of the coarse one (the hierarchical estimate; it
//    holds while the richer solution is much closer to the exact one than
//    the coarse solution is);
//  - Newton's remaining residual: |Q(x - K^-1 r) - Q(x)| at the coarse
//    iterate x with its residual r and tangent K;
//  - for the wrinkling onset, where the richer margin s2_min crosses zero
//    (a secant from the onset state), against where the coarse one does.
// Both models are copies set up as the run's (the run's own is left as it
// is), so the run's results do not depend on the estimate.

#include <cdea/fe/discretization.h>
#include <cdea/model/equilibrium_model.h>
#include <cdea/model/quantities_error.h>
#include <cdea/model/records.h>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace cdea
{
  class MembraneModel;

  /// The key outputs of one state (SI).
  struct KeyOutputs
  {
    double displacement = std::numeric_limits<double>::quiet_NaN(); ///< m
    double volume       = std::numeric_limits<double>::quiet_NaN(); ///< enclosed, m^3
    double s2_min       = std::numeric_limits<double>::quiet_NaN(); ///< Pa
  };

  /// One state's outputs on the coarse and the richer model, and how much
  /// one further Newton step on the coarse one would change them.
  struct StateComparison
  {
    KeyOutputs   coarse, enriched;
    KeyOutputs   newton; ///< |change| by the Newton correction -K^-1 r
    bool         converged  = false; ///< the richer solve converged
    unsigned int iterations = 0;     ///< its Newton iterations
  };

  /// Where the richer model's onset margin crosses zero, against the coarse.
  struct OnsetComparison
  {
    /// Path parameter of the coarse margin's root and of the richer one's
    /// (linear from the onset state: the margins and their slope there).
    double coarse_root   = std::numeric_limits<double>::quiet_NaN();
    double enriched_root = std::numeric_limits<double>::quiet_NaN();
    bool   converged     = false;
  };

  /// The richer discretization of @p coarse: degree p + 1 on the same mesh;
  /// at degree 8, the highest the input allows, every element bisected.
  FeDiscretization enriched_discretization(const FeDiscretization &coarse);

  class HierarchicalEstimate
  {
  public:
    /// @p coarse: a model set up as the run's (the same scene, law, load
    /// terms and discretization); @p enriched: the same on
    /// enriched_discretization(). Neither is the run's own model.
    HierarchicalEstimate(std::unique_ptr<MembraneModel> coarse,
                         std::unique_ptr<MembraneModel> enriched);
    ~HierarchicalEstimate();

    /// The outputs of the coarse converged @p state and of its richer
    /// solution at the same load.
    StateComparison compare(const ModelState &state);

    /// The roots of s2_min = 0 near the coarse onset @p state at path
    /// parameter t on @p path: both margins at t, the richer one also at
    /// t + @p dt for the slope.
    OnsetComparison onset(const ModelState &state, const std::function<LoadState(double)> &path,
                          double dt);

    /// The richer model's discretization.
    const Discretization &enriched_discretization() const;

  private:
    std::unique_ptr<MembraneModel> coarse, enriched;

    /// The richer model put at @p state's load with the coarse unknowns
    /// embedded, then solved.
    SolveReport solve_enriched(const ModelState &state);
  };

  /// The estimate of a quasi-static run's key outputs (Discretization/Error
  /// estimate): the states it needs are kept as the run passes them (the end
  /// of the dead-load stage, the onset, the last step), and after the run
  /// each is compared with its richer solution on models of its own.
  class RunErrorEstimate
  {
  public:
    /// A model of the run's set-up on a discretization.
    using ModelFactory = std::function<std::unique_ptr<MembraneModel>(const FeDiscretization &)>;

    /// For a run of @p scene on @p discretization whose onset search stops
    /// at a bracket of @p onset_tolerance (V); @p make sets models up as the run's.
    RunErrorEstimate(const Scene &scene, const FeDiscretization &discretization,
                     double onset_tolerance, ModelFactory make);

    /// After each converged step, with @p model in that state.
    void step(const StepSummary &summary, const EquilibriumModel &model);
    /// When the onset is located, with @p model in that state.
    void onset(const EquilibriumModel &model);

    /// The estimate at the last step (NaN parts where a richer solve
    /// failed; no onset errors without an onset in the voltage stage).
    OutputErrors estimate() const;

  private:
    const Scene              &scene;
    const FeDiscretization    discretization;
    const double              onset_tolerance;
    const ModelFactory        make;
    std::optional<ModelState> load_end, onset_state, last;
  };

  /// The final state's outputs with their estimated errors, a line each
  /// ("  displacement 23.79359 mm (estimated error 3.1e-09 mm)").
  std::string describe_errors(const OutputErrors &errors, const StepSummary &last,
                              const std::vector<double> &onset_voltages, double shear_modulus);
} // namespace cdea
