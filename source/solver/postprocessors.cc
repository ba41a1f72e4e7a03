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

  std::vector<SummaryColumn> ModelQuantities::columns() const
  {
    return {{"wrinkled_zone_inner_mm", "mm",
             "pre-stretched flat radius lam_pre R where the relaxed law's wrinkled zone starts "
             "(NaN: none, or Wrinkling/Model = check)"},
            {"wrinkled_zone_outer_mm", "mm",
             "pre-stretched flat radius where the wrinkled zone ends"}};
  }

  void ModelQuantities::evaluate(StepContext &context, StepSummary &summary)
  {
    std::vector<std::pair<std::string, double>> columns = std::move(summary.columns);
    summary             = context.model.summary();
    summary.columns     = std::move(columns);
    summary.stage       = context.stage;
    summary.load_factor = context.load_factor;
    summary.wrinkled    = context.stage != Stage::prestretch && summary.s2_min < 0.;
    summary.columns.emplace_back("wrinkled_zone_inner_mm",
                                 prestretch * summary.wrinkled_zone_inner * 1e3);
    summary.columns.emplace_back("wrinkled_zone_outer_mm",
                                 prestretch * summary.wrinkled_zone_outer * 1e3);
  }

  void Stroke::evaluate(StepContext &context, StepSummary &summary)
  {
    if (context.stage == Stage::prestretch)
      reference.reset();
    if (context.stage == Stage::dead_load && context.load_factor == 1.)
      reference = summary.displacement;
    summary.stroke = reference ? summary.displacement - *reference : nan;
  }

  std::vector<SummaryColumn> Stability::columns() const
  {
    return {{"min_eigenvalue", "N/m",
             "smallest eigenvalue of the tangent with dead load and voltages held (NaN: "
             "Solver/Stability check off)"},
            {"stable", "0/1", "min_eigenvalue > 0"}};
  }

  void Stability::evaluate(StepContext &context, StepSummary &summary)
  {
    summary.min_eigenvalue = enabled ? context.model.min_tangent_eigenvalue() : nan;
    summary.columns.emplace_back("min_eigenvalue", summary.min_eigenvalue);
    summary.columns.emplace_back("stable", std::isnan(summary.min_eigenvalue) ?
                                             nan :
                                             double(summary.min_eigenvalue > 0.));
  }

  std::vector<SummaryColumn> MaxField::columns() const
  {
    return {{"max_field_MV_per_m", "MV/m",
             "largest true electric field (NaN: breakdown check off)"}};
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
    summary.columns.emplace_back("max_field_MV_per_m", summary.max_field * 1e-6);
  }

  std::vector<SummaryColumn> EnclosedVolume::columns() const
  {
    return {{"volume_mm3", "mm^3",
             "volume enclosed between the frame plane and the deformed membrane with the disk, "
             "pi int r^2 dz"},
            {"volume_change_mm3", "mm^3",
             "enclosed volume minus its value at the end of the load stage (NaN before)"},
            {"level_drop_mm", "mm", "volume change / cross-section of the Reservoir level tube"}};
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
    summary.columns.emplace_back("volume_mm3", volume * 1e9);
    summary.columns.emplace_back("volume_change_mm3", volume_change * 1e9);
    summary.columns.emplace_back("level_drop_mm", level_drop * 1e3);
  }

  std::vector<std::unique_ptr<Postprocessor>>
  standard_postprocessors(const double prestretch, const bool stability_check,
                          const bool field_check)
  {
    std::vector<std::unique_ptr<Postprocessor>> list;
    list.push_back(std::make_unique<ModelQuantities>(prestretch));
    list.push_back(std::make_unique<Stroke>());
    list.push_back(std::make_unique<Stability>(stability_check));
    list.push_back(std::make_unique<MaxField>(field_check));
    return list;
  }
} // namespace cdea
