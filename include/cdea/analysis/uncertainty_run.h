#pragma once
// The uncertainty of the answers of a quasi-static FE run (`cdea run` with
// Uncertainty/Mode, doc/uncertainty.md): the final displacement, stroke and
// volume change and the onset voltages of wrinkling, each with one standard
// deviation as /summary attributes (model/quantities_uncertainty.h).
//
// Linear: the exact gradients of each answer at the states where the run
// takes it (StateSensitivity): the end of the dead-load stage (the stroke's
// and the volume change's zero), the onset, the final state. At the onset
// s2(x(p), t, p) = 0 at the point where it first vanishes, so along the path
// t -> V(t)
//   dt*/dp = -(ds2/dp) / sum_k (ds2/dV_k) V_k'(t*),   dV_onset/dp = V'(t*) dt*/dp.
// At a limit point (fold) of the path R(x, t, p) = 0 with K phi = 0 (K
// symmetric), so to first order
//   dt*/dp = -(phi^T dR/dp) / (phi^T dR/dt),     dV_fold/dp = V'(t*) dt*/dp,
// phi from the solve K u = -dR/dt with the nearly singular tangent of the
// located fold (one step of inverse iteration: u is phi to the accuracy of
// the location).
// Monte-Carlo: the run again with sampled constants, each a full run.

#include <cdea/analysis/run_input.h>
#include <cdea/analysis/uncertainty.h>
#include <cdea/model/equilibrium_model.h>
#include <cdea/model/product.h>
#include <cdea/model/records.h>
#include <cdea/solver/load_stepper.h>

#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  class MembraneModel;

  /// What the uncertainty is about: a quasi-static run's answers.
  struct RunAnswers
  {
    bool                completed = false;
    double              displacement = 0., stroke = 0., volume_change = 0.; ///< m, m, m^3
    bool                onset = false;
    std::vector<double> onset_voltages; ///< V per ring
  };

  /// The answers of a run that ended with @p final_step and @p result.
  RunAnswers run_answers(const StepSummary &final_step, const RunResult &result);

  /// The linear propagation along a run: told of the run's states as they
  /// come, it keeps the gradients of the answers.
  class LinearRunUncertainty
  {
  public:
    LinearRunUncertainty(const UncertainConstants &constants, const Scene &scene);

    /// Follows the reports of @p stepper on @p model (reference(), onset(),
    /// limit_point()) before the callbacks it has so far.
    void follow(LoadStepper &stepper, MembraneModel &model);
    /// The model's state is the end of the dead-load stage.
    void reference(MembraneModel &model);
    /// The model's state is the onset @p onset.
    void onset(MembraneModel &model, const OnsetRecord &onset);
    /// The model's state is the limit point @p limit.
    void limit_point(MembraneModel &model, const LimitPoint &limit);
    /// The model's state is the final one: the _std rows of every answer taken.
    ProductGroup finish(MembraneModel &model) const;

  private:
    const UncertainConstants     &constants;
    const Scene                  &scene;
    Eigen::VectorXd               reference_displacement, reference_volume;
    std::vector<Eigen::VectorXd> onset_gradients; ///< per ring; empty: no onset
    std::vector<Eigen::VectorXd> limit_gradients; ///< dt*/dp of each limit point
    std::vector<std::vector<double>> limit_rates;  ///< V'(t*) of each

    /// The constants, then the voltage of each ring.
    std::vector<SceneParameter> with_voltages() const;
  };

  /// A run of @p input's parameters on @p scene without output (as `cdea
  /// run` solves it), and with @p linear_rows the linear propagation of
  /// input.uncertainty along it into them. A run that throws is not completed.
  RunAnswers quiet_run(const RunInput &input, const Scene &scene,
                       ProductGroup *linear_rows = nullptr);

  /// Monte-Carlo: constants.samples runs of @p input with sampled constants
  /// (round-robin over the MPI ranks when launched by mpirun, gathered on
  /// every rank), stopped early by a stop request; the rows of
  /// model/quantities_uncertainty.h.
  ProductGroup monte_carlo_run(const RunInput &input, const UncertainConstants &constants,
                               bool show_progress);

  /// The lines `cdea run` prints of @p rows (after the final state).
  std::string uncertainty_report(const UncertainConstants &constants, const ProductGroup &rows);
} // namespace cdea
