#pragma once
// Summary quantities of a converged state as small postprocessors, in the
// manner of ASPECT's postprocessors: each is a plugin of Postprocessors
// (base/plugin_list.h, as the laws and the load terms), made from the
// PostprocessorSetup of the path that runs it and called after every
// converged step (and at the states the crossing searches visit). Each fills
// its part of the StepSummary; quantities beyond StepSummary's typed ones go
// into StepSummary::columns by their rows of the table of output fields
// (model/output_fields.h, namespace summary_column) and become /summary
// columns of the results file. A postprocessor registers itself at the end of
// its source file, inside namespace cdea,
//
//   CDEA_REGISTER_PLUGIN(Postprocessors, EnclosedVolume, "enclosed volume", on_runs, "...")
//
// with the paths it runs on, and states its place among the others (static
// constexpr int position): each sees what the earlier ones wrote, and the
// results file creates the /summary columns in the order they first appear.
//
// The fields along the meridian are computed at most once per state
// (StepContext::fields()) and shared by every postprocessor and the writer.

#include <cdea/base/plugin_list.h>
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

    /// Its entries of the parameter file; none by default.
    static void declare_parameters(ParameterDeclarations &prm) { (void)prm; }
  };

  /// What a postprocessor is made from: the scene's numbers and the settings
  /// of the path that runs it.
  struct PostprocessorSetup
  {
    double              prestretch      = 1.;
    double              frame_radius    = 0.; ///< m
    double              tube_area       = 1.; ///< m^2, the Reservoir's level tube
    bool                stability_check = false;
    StabilityEigenvalue eigenvalue      = StabilityEigenvalue::every_step;
    bool                field_check     = false; ///< the largest field (Solver/Breakdown field on)
  };

  /// Where a postprocessor runs (the flags of a Postprocessors plugin).
  enum PostprocessorPaths : unsigned int
  {
    on_every_path = 1, ///< every load stepper and time stepper
    on_runs       = 2  ///< the runs of cdea run and shoot (and in time), and their in-process twins
  };

  /// The registered postprocessors, in their order (position, then name).
  using Postprocessors = PluginList<Postprocessor, PostprocessorSetup>;

  /// The registered postprocessors of @p paths (PostprocessorPaths bits), in
  /// order, made from @p setup.
  std::vector<std::unique_ptr<Postprocessor>> make_postprocessors(unsigned int          paths,
                                                                  const PostprocessorSetup &setup);
} // namespace cdea
