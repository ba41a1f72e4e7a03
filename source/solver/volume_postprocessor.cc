// The enclosed volume of the runs (postprocessors.h): the volume between the
// film, the disk and the frame plane, its change from the end of the
// dead-load stage and the pump's level drop in a tube of the Reservoir's
// cross-section.

#include <cdea/model/output_fields.h>
#include <cdea/solver/postprocessors.h>

#include <limits>
#include <optional>

namespace cdea
{
  class EnclosedVolume final : public Postprocessor
  {
  public:
    static constexpr int position = 50;

    explicit EnclosedVolume(const PostprocessorSetup &setup)
      : tube_area(setup.tube_area)
    {}

    void evaluate(StepContext &context, StepSummary &summary) override
    {
      const double volume = context.model.enclosed_volume();
      if (context.stage == Stage::prestretch)
        reference.reset();
      if (context.stage == Stage::dead_load && context.load_factor == 1.)
        reference = volume;
      const double volume_change =
        reference ? volume - *reference : std::numeric_limits<double>::quiet_NaN();
      const double level_drop = volume_change / tube_area;
      summary.columns.set(summary_column::volume, volume);
      summary.columns.set(summary_column::volume_change, volume_change);
      summary.columns.set(summary_column::level_drop, level_drop);
    }

  private:
    double                tube_area; ///< m^2
    std::optional<double> reference; ///< m^3, at the end of the dead-load stage
  };

  CDEA_REGISTER_PLUGIN(Postprocessors, EnclosedVolume, "enclosed volume", on_runs,
                       "the enclosed volume, its change and the level drop in the tube")
} // namespace cdea
