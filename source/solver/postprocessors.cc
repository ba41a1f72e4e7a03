#include <cdea/model/output_fields.h>
#include <cdea/solver/postprocessors.h>

#include <cmath>
#include <limits>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  }

  // The model's own quantities, shared by summary() and the postprocessor.
  StepSummary EquilibriumModel::summary() const
  {
    StepSummary        s;
    const LoadState   &l = load();
    const HoopStresses h = hoop_stresses();
    s.stage               = l.stage;
    s.load_factor         = l.load_factor;
    s.voltages            = l.voltages;
    s.mass                = l.mass;
    s.displacement        = displacement();
    s.s2_min              = h.s2_min;
    s.s2_min_radius       = h.s2_min_radius;
    s.s2_ring_inner       = h.s2_ring_inner;
    s.wrinkled_zone_inner = h.wrinkled_zone_inner;
    s.wrinkled_zone_outer = h.wrinkled_zone_outer;
    s.validity_limit      = h.validity_limit;
    return s;
  }

  void ModelQuantities::evaluate(StepContext &context, StepSummary &summary)
  {
    ColumnValues columns = std::move(summary.columns);
    summary             = context.model.summary();
    summary.columns     = std::move(columns);
    summary.stage       = context.stage;
    summary.load_factor = context.load_factor;
    summary.wrinkled    = context.stage != Stage::prestretch && summary.s2_min < 0.;
    summary.columns.set(summary_column::wrinkled_zone_inner,
                        prestretch * summary.wrinkled_zone_inner);
    summary.columns.set(summary_column::wrinkled_zone_outer,
                        prestretch * summary.wrinkled_zone_outer);
  }

  void Stroke::evaluate(StepContext &context, StepSummary &summary)
  {
    if (context.stage == Stage::prestretch)
      reference.reset();
    if (context.stage == Stage::dead_load && context.load_factor == 1.)
      reference = summary.displacement;
    summary.stroke = reference ? summary.displacement - *reference : nan;
  }

  void Stability::evaluate(StepContext &context, StepSummary &summary)
  {
    StabilityEigenvalue where = eigenvalue;
    if (first && where == StabilityEigenvalue::near_folds)
      where = StabilityEigenvalue::near_folds_first;
    first                  = false;
    const StateStability s = enabled ? context.model.stability(where) : StateStability();
    summary.min_eigenvalue = s.min_eigenvalue;
    summary.columns.set(summary_column::min_eigenvalue, s.min_eigenvalue);
    summary.columns.set(summary_column::stable, s.stable);
  }

  void MaxField::evaluate(StepContext &context, StepSummary &summary)
  {
    summary.max_field = summary.max_field_radius = nan;
    if (enabled)
      {
        const StepFields &f = context.fields();
        summary.max_field   = 0.;
        for (std::size_t i = 0; i < f.E.size(); ++i)
          if (f.E[i] > summary.max_field)
            {
              summary.max_field        = f.E[i];
              summary.max_field_radius = f.R[i];
            }
      }
    summary.columns.set(summary_column::max_field, summary.max_field);
  }

  void EnclosedVolume::evaluate(StepContext &context, StepSummary &summary)
  {
    volume = context.model.enclosed_volume();
    if (context.stage == Stage::prestretch)
      reference.reset();
    if (context.stage == Stage::dead_load && context.load_factor == 1.)
      reference = volume;
    volume_change = reference ? volume - *reference : nan;
    level_drop    = volume_change / tube_area;
    summary.columns.set(summary_column::volume, volume);
    summary.columns.set(summary_column::volume_change, volume_change);
    summary.columns.set(summary_column::level_drop, level_drop);
  }

  std::vector<std::unique_ptr<Postprocessor>>
  standard_postprocessors(const double prestretch, const bool stability_check,
                          const StabilityEigenvalue eigenvalue, const bool field_check)
  {
    std::vector<std::unique_ptr<Postprocessor>> list;
    list.push_back(std::make_unique<ModelQuantities>(prestretch));
    list.push_back(std::make_unique<Stroke>());
    list.push_back(std::make_unique<Stability>(stability_check, eigenvalue));
    list.push_back(std::make_unique<MaxField>(field_check));
    return list;
  }
} // namespace cdea
