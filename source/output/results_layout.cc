#include <cdea/output/results_layout.h>

#include <limits>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  }

  std::vector<double> scaled(const std::vector<double> &values, const double factor)
  {
    std::vector<double> result(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
      result[i] = values[i] * factor;
    return result;
  }

  const std::vector<StandardColumn> &standard_summary_columns()
  {
    static const std::vector<StandardColumn> columns = {
      {"stage", "1", "stage of the run: 0 pre-stretch, 1 dead load, 2 voltage", true, false},
      {"load_factor", "1", "stage parameter (voltage path parameter in stage 2)", false, false},
      {"voltage_kV", "kV", "voltage of each ring (steps x rings)", false, true},
      {"mass_g", "g", "dead-load mass on the disk", false, false},
      {"displacement_mm", "mm", "disk deflection from the frame plane |z(disk) - z(frame)|",
       false, false},
      {"stroke_mm", "mm",
       "displacement minus its zero-voltage value under the same load (NaN before the end of "
       "the load stage)",
       false, false},
      {"s2_min_kPa", "kPa", "smallest nominal hoop stress s2 anywhere", false, false},
      {"s2_ring_inner_kPa", "kPa",
       "nominal hoop stress s2 at the inner edge of each ring (steps x rings)", false, true},
      {"wrinkled", "1", "1 if the hoop stress is negative somewhere (loss of tension)", true,
       false},
      {"newton_iterations", "1", "Newton iterations of the converged step", true, false}};
    return columns;
  }

  std::vector<std::vector<double>> standard_summary_values(const StepSummary &s)
  {
    // In the order of standard_summary_columns().
    return {{double(static_cast<int>(s.stage))},
            {s.load_factor},
            scaled(s.voltages, file_units::kV),
            {s.mass * file_units::g},
            {s.displacement * file_units::mm},
            {s.stroke * file_units::mm},
            {s.s2_min * file_units::kPa},
            scaled(s.s2_ring_inner, file_units::kPa),
            {s.wrinkled ? 1. : 0.},
            {double(s.newton_iterations)}};
  }

  const std::vector<FieldDataset> &field_datasets()
  {
    static const std::vector<FieldDataset> fields = {
      {"R", "mm", "undeformed (reference) radius of the material point", file_units::mm,
       &StepFields::R},
      {"r", "mm", "deformed radius", file_units::mm, &StepFields::r},
      {"z", "mm", "deformed height (same sign convention as the solver)", file_units::mm,
       &StepFields::z},
      {"theta", "rad", "meridian slope angle", 1., &StepFields::theta},
      {"lambda1", "1", "meridian stretch", 1., &StepFields::lambda1},
      {"lambda2", "1", "hoop stretch r/R", 1., &StepFields::lambda2},
      {"s1", "kPa", "nominal meridian stress", file_units::kPa, &StepFields::s1},
      {"s2", "kPa", "nominal hoop stress", file_units::kPa, &StepFields::s2},
      {"E", "MV/m", "true electric field in the thickness direction", file_units::MV_per_m,
       &StepFields::E},
      {"Phi", "kV", "voltage across the film", file_units::kV, &StepFields::Phi},
      {"ring", "1", "index of the electrode ring (0 = innermost)", 1., nullptr}};
    return fields;
  }

  std::vector<SummaryAttribute> onset_attributes(const OnsetRecord &onset,
                                                 const unsigned int n_rings)
  {
    std::vector<SummaryAttribute> a(4);
    a[0] = {"onset_found", {onset.found ? 1. : 0.}, 0, 0, true, true};
    a[1] = {"onset_voltage_kV",
            onset.found ? scaled(onset.voltages, file_units::kV) :
                          std::vector<double>(n_rings, nan)};
    a[2] = {"onset_radius_mm", {onset.found ? onset.radius * file_units::mm : nan}, 0, 0, true};
    a[3] = {"onset_load_factor", {onset.found ? onset.load_factor : nan}, 0, 0, true};
    return a;
  }

  std::vector<SummaryAttribute> limit_point_attributes(const std::vector<LimitPoint> &limits,
                                                       const unsigned int n_rings)
  {
    SummaryAttribute voltages{"limit_point_voltage_kV", {}, unsigned(limits.size()), n_rings};
    SummaryAttribute displacements{"limit_point_displacement_mm", {}};
    for (const LimitPoint &limit : limits)
      {
        for (const double v : limit.voltages)
          voltages.values.push_back(v * file_units::kV);
        displacements.values.push_back(limit.displacement * file_units::mm);
      }
    return {voltages, displacements};
  }

  std::vector<SummaryAttribute> breakdown_attributes(const OnsetRecord &breakdown)
  {
    if (!breakdown.found)
      return {};
    return {{"breakdown_voltage_kV", scaled(breakdown.voltages, file_units::kV)},
            {"breakdown_radius_mm", {breakdown.radius * file_units::mm}}};
  }
} // namespace cdea
