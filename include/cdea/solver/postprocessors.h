#pragma once
// Summary quantities of a converged state as small postprocessors, registered
// once with the load stepper and called after every converged step (and at
// the states its crossing searches visit), in the manner of ASPECT's
// postprocessors. Each fills its part of the StepSummary; quantities beyond
// StepSummary's typed ones go into StepSummary::columns by their rows of the
// table of output fields (model/output_fields.h, namespace summary_column)
// and become /summary columns of the results file.
//
// The fields along the meridian are computed at most once per state
// (StepContext::fields()) and shared by every postprocessor and the writer.

#include <cdea/model/equilibrium_model.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cdea
{
  /// A converged state as the postprocessors see it.
  class StepContext
  {
  public:
    StepContext(EquilibriumModel &model, Stage stage, double load_factor)
      : model(model)
      , stage(stage)
      , load_factor(load_factor)
    {}

    EquilibriumModel &model;
    const Stage       stage;
    const double      load_factor;

    /// The model's fields of this state, computed on first use.
    const StepFields &fields()
    {
      if (!cached_fields)
        cached_fields = std::make_shared<const StepFields>(model.fields());
      return *cached_fields;
    }
    /// The fields if they were computed (else null).
    std::shared_ptr<const StepFields> computed_fields() const { return cached_fields; }

  private:
    std::shared_ptr<const StepFields> cached_fields;
  };

  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;
    /// Its quantities of the state of @p context into @p summary.
    virtual void evaluate(StepContext &context, StepSummary &summary) = 0;
  };

  /// Load, displacement, hoop stresses (with the wrinkled zone and the
  /// validity limit), and wrinkled = s2_min < 0 after the pre-stretch stage.
  class ModelQuantities final : public Postprocessor
  {
  public:
    explicit ModelQuantities(double prestretch)
      : prestretch(prestretch)
    {}
    void evaluate(StepContext &context, StepSummary &summary) override;

  private:
    double prestretch;
  };

  /// Stroke: the displacement minus its value at the end of the dead-load stage.
  class Stroke final : public Postprocessor
  {
  public:
    void evaluate(StepContext &context, StepSummary &summary) override;

  private:
    std::optional<double> reference;
  };

  /// Smallest eigenvalue of the tangent with loads held (NaN when off, and
  /// with near_folds where it was not computed) and whether the state is
  /// stable. With near_folds the first evaluation forgets the reference
  /// (near_folds_first) and computes the eigenvalue unless the state is
  /// singular to round-off, so a run's column does not depend on what the
  /// model computed before it.
  class Stability final : public Postprocessor
  {
  public:
    explicit Stability(bool enabled, StabilityEigenvalue eigenvalue = StabilityEigenvalue::every_step)
      : enabled(enabled)
      , eigenvalue(eigenvalue)
    {}
    void evaluate(StepContext &context, StepSummary &summary) override;

  private:
    bool                enabled;
    StabilityEigenvalue eigenvalue;
    bool                first = true;
  };

  /// Largest true electric field and where (NaN when off).
  class MaxField final : public Postprocessor
  {
  public:
    explicit MaxField(bool enabled)
      : enabled(enabled)
    {}
    void evaluate(StepContext &context, StepSummary &summary) override;

  private:
    bool enabled;
  };

  /// Enclosed volume, its change from the end of the dead-load stage and the
  /// pump's level drop in a tube of cross-section @p tube_area.
  class EnclosedVolume final : public Postprocessor
  {
  public:
    explicit EnclosedVolume(double tube_area)
      : tube_area(tube_area)
    {}
    void evaluate(StepContext &context, StepSummary &summary) override;

    double volume        = 0.; ///< m^3, of the last evaluation
    double volume_change = std::numeric_limits<double>::quiet_NaN(); ///< m^3
    double level_drop    = std::numeric_limits<double>::quiet_NaN(); ///< m

  private:
    double                tube_area;
    std::optional<double> reference;
  };

  /// The postprocessors every run has, in order: model quantities, stroke,
  /// stability (if @p stability_check, its eigenvalue where @p eigenvalue
  /// says), field.
  std::vector<std::unique_ptr<Postprocessor>>
  standard_postprocessors(double prestretch, bool stability_check, StabilityEigenvalue eigenvalue,
                          bool field_check);
} // namespace cdea
