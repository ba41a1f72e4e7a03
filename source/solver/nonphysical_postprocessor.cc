// The /summary column `nonphysical` of the runs (postprocessors.h): the
// NonPhysical bits of the state's meridian (state_check.h).

#include <cdea/model/output_fields.h>
#include <cdea/solver/postprocessors.h>
#include <cdea/solver/state_check.h>

namespace cdea
{
  class NonPhysicalCheck final : public Postprocessor
  {
  public:
    static constexpr int position = 60;

    explicit NonPhysicalCheck(const PostprocessorSetup &setup)
      : frame_radius(setup.frame_radius)
    {}

    void evaluate(StepContext &context, StepSummary &summary) override
    {
      summary.columns.set(summary_column::nonphysical,
                          double(nonphysical_flags(context.fields(), frame_radius)));
    }

  private:
    double frame_radius; ///< m
  };

  CDEA_REGISTER_PLUGIN(Postprocessors, NonPhysicalCheck, "nonphysical", on_runs,
                       "whether the meridian leaves the frame or crosses itself or the disk")
} // namespace cdea
