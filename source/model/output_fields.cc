#include <cdea/model/output_fields.h>

#include <limits>
#include <stdexcept>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The true stresses sigma_i = l_i s_i (SI).
    std::vector<double> true_stress(const std::vector<double> &stretch,
                                    const std::vector<double> &nominal)
    {
      std::vector<double> sigma(nominal.size());
      for (std::size_t i = 0; i < sigma.size(); ++i)
        sigma[i] = stretch[i] * nominal[i];
      return sigma;
    }
  } // namespace

  std::vector<double> in_unit(const std::vector<double> &values, const Unit &unit)
  {
    std::vector<double> result(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
      result[i] = unit.from_si(values[i]);
    return result;
  }

  double ColumnValues::in_file_units(const Quantity &column) const
  {
    return column.in_file_units(get(column));
  }

  const std::vector<double> &StepFields::internal_values(const std::string &name) const
  {
    for (const InternalField &f : internal)
      if (f.name == name)
        return f.values;
    throw std::out_of_range("StepFields: no internal variable '" + name + "'");
  }

  const std::vector<const Quantity *> &standard_summary_columns()
  {
    using namespace summary_column;
    static const std::vector<const Quantity *> columns = {
      &stage,  &load_factor, &voltage,       &mass,     &displacement,
      &stroke, &s2_min,      &s2_ring_inner, &wrinkled, &newton_iterations};
    return columns;
  }

  const std::vector<const Quantity *> &step_attributes()
  {
    using namespace summary_column;
    static const std::vector<const Quantity *> attributes = {&stage, &load_factor, &voltage,
                                                                &displacement};
    return attributes;
  }

  ProductGroup onset_attributes(const OnsetRecord &onset, const unsigned int n_rings)
  {
    using namespace summary_attribute;
    ProductGroup g("/summary");
    g.set(onset_found, onset.found)
      .set(onset_voltage, onset.found ? onset.voltages : std::vector<double>(n_rings, nan))
      .set(onset_radius, onset.found ? onset.radius : nan)
      .set(onset_load_factor, onset.found ? onset.load_factor : nan);
    return g;
  }

  ProductGroup limit_point_attributes(const std::vector<LimitPoint> &limits,
                                      const unsigned int n_rings)
  {
    using namespace summary_attribute;
    std::vector<double> voltages, displacements;
    for (const LimitPoint &limit : limits)
      {
        voltages.insert(voltages.end(), limit.voltages.begin(), limit.voltages.end());
        displacements.push_back(limit.displacement);
      }
    ProductGroup g("/summary");
    g.set(limit_point_voltage, voltages, {limits.size(), n_rings})
      .set(limit_point_displacement, displacements, {limits.size()});
    return g;
  }

  ProductGroup breakdown_attributes(const OnsetRecord &breakdown)
  {
    using namespace summary_attribute;
    ProductGroup g("/summary");
    if (breakdown.found)
      g.set(breakdown_voltage, breakdown.voltages)
        .set(breakdown_radius, std::vector<double>{breakdown.radius});
    return g;
  }

  ProductGroup time_integration_attributes(const unsigned int steps, const unsigned int rejected,
                                           const double error_estimate)
  {
    using namespace summary_attribute;
    ProductGroup g("/summary");
    g.set(time_steps, std::vector<double>{double(steps)})
      .set(time_steps_rejected, std::vector<double>{double(rejected)})
      .set(time_error_estimate, std::vector<double>{error_estimate});
    return g;
  }

  namespace
  {
    /// A /steps dataset: a value per point along the meridian.
    constexpr Quantity field_row(const char *name, const Unit &unit, const Storage storage,
                                 const char *description)
    {
      Quantity q{name, unit, description, shape::point, storage};
      q.runs = every_run;
      return q;
    }
  } // namespace

  const std::vector<StepField> &step_fields()
  {
    // clang-format off
    // Each row: name, unit, storage, description; the member of StepFields
    // (or the derivation); whether the results file and the ParaView output
    // have it.
    static const std::vector<StepField> fields = {
      {field_row("R", units::mm, Storage::real,
        "undeformed (reference) radius of the material point"),
       &StepFields::R, nullptr, true, true},
      {field_row("r", units::mm, Storage::real,
        "deformed radius"),
       &StepFields::r, nullptr, true, true},
      {field_row("z", units::mm, Storage::real,
        "deformed height (same sign convention as the solver)"),
       &StepFields::z, nullptr, true, true},
      {field_row("theta", units::rad, Storage::real,
        "meridian slope angle"),
       &StepFields::theta, nullptr, true, false},
      {field_row("lambda1", units::one, Storage::real,
        "meridian stretch"),
       &StepFields::lambda1, nullptr, true, true},
      {field_row("lambda2", units::one, Storage::real,
        "hoop stretch r/R"),
       &StepFields::lambda2, nullptr, true, true},
      {field_row("s1", units::kPa, Storage::real,
        "nominal meridian stress"),
       &StepFields::s1, nullptr, true, true},
      {field_row("s2", units::kPa, Storage::real,
        "nominal hoop stress"),
       &StepFields::s2, nullptr, true, true},
      {field_row("sigma1", units::kPa, Storage::real,
        "true meridian stress lambda1 s1"),
       nullptr, [](const StepFields &f) { return true_stress(f.lambda1, f.s1); }, false, true},
      {field_row("sigma2", units::kPa, Storage::real,
        "true hoop stress lambda2 s2"),
       nullptr, [](const StepFields &f) { return true_stress(f.lambda2, f.s2); }, false, true},
      {field_row("E", units::MV_per_m, Storage::real,
        "true electric field in the thickness direction"),
       &StepFields::E, nullptr, true, true},
      {field_row("Phi", units::kV, Storage::real,
        "voltage across the film"),
       &StepFields::Phi, nullptr, true, true},
      {field_row("ring", units::one, Storage::integer,
        "index of the electrode ring (0 = innermost)"),
       nullptr, nullptr, true, true}};
    // clang-format on
    return fields;
  }

  std::vector<double> step_field_values(const StepField &row, const StepFields &fields)
  {
    if (row.values)
      return fields.*row.values;
    if (row.derived)
      return row.derived(fields);
    return std::vector<double>(fields.ring.begin(), fields.ring.end());
  }
} // namespace cdea
