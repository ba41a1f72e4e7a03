#include <cdea/model/output_fields.h>
#include <cdea/solver/postprocessors.h>

#include <cmath>
#include <limits>
#include <optional>

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

  namespace
  {
    /// Load, displacement, hoop stresses (with the wrinkled zone and the
    /// validity limit), and wrinkled = s2_min < 0 after the pre-stretch stage.
    class ModelQuantities final : public Postprocessor
    {
    public:
      static constexpr int position = 10;

      explicit ModelQuantities(const PostprocessorSetup &setup)
        : prestretch(setup.prestretch)
      {}

      void evaluate(StepContext &context, StepSummary &summary) override
      {
        ColumnValues columns = std::move(summary.columns);
        summary              = context.model.summary();
        summary.columns      = std::move(columns);
        summary.stage        = context.stage;
        summary.load_factor  = context.load_factor;
        summary.wrinkled     = context.stage != Stage::prestretch && summary.s2_min < 0.;
        summary.columns.set(summary_column::wrinkled_zone_inner,
                            prestretch * summary.wrinkled_zone_inner);
        summary.columns.set(summary_column::wrinkled_zone_outer,
                            prestretch * summary.wrinkled_zone_outer);
      }

    private:
      double prestretch;
    };

    /// Stroke: the displacement minus its value at the end of the dead-load stage.
    class Stroke final : public Postprocessor
    {
    public:
      static constexpr int position = 20;

      explicit Stroke(const PostprocessorSetup &) {}

      void evaluate(StepContext &context, StepSummary &summary) override
      {
        if (context.stage == Stage::prestretch)
          reference.reset();
        if (context.stage == Stage::dead_load && context.load_factor == 1.)
          reference = summary.displacement;
        summary.stroke = reference ? summary.displacement - *reference : nan;
      }

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
      static constexpr int position = 30;

      explicit Stability(const PostprocessorSetup &setup)
        : enabled(setup.stability_check)
        , eigenvalue(setup.eigenvalue)
      {}

      void evaluate(StepContext &context, StepSummary &summary) override
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

    private:
      bool                enabled;
      StabilityEigenvalue eigenvalue;
      bool                first = true;
    };

    /// Largest true electric field and where (NaN when off).
    class MaxField final : public Postprocessor
    {
    public:
      static constexpr int position = 40;

      explicit MaxField(const PostprocessorSetup &setup)
        : enabled(setup.field_check)
      {}

      void evaluate(StepContext &context, StepSummary &summary) override
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

    private:
      bool enabled;
    };
  } // namespace

  std::vector<std::unique_ptr<Postprocessor>> make_postprocessors(const unsigned int        paths,
                                                                  const PostprocessorSetup &setup)
  {
    std::vector<std::unique_ptr<Postprocessor>> list;
    for (const Postprocessors::Plugin &plugin : Postprocessors::plugins())
      if (plugin.flags & paths)
        list.push_back(plugin.create(setup));
    return list;
  }

  CDEA_REGISTER_PLUGIN(Postprocessors, ModelQuantities, "model quantities", on_every_path,
                       "load, displacement, hoop stresses, wrinkled zone, validity limit")
  CDEA_REGISTER_PLUGIN(Postprocessors, Stroke, "stroke", on_every_path,
                       "the displacement from the end of the dead-load stage")
  CDEA_REGISTER_PLUGIN(Postprocessors, Stability, "stability", on_every_path,
                       "the smallest eigenvalue of the tangent and whether the state is stable")
  CDEA_REGISTER_PLUGIN(Postprocessors, MaxField, "max field", on_every_path,
                       "the largest true electric field and where")
} // namespace cdea
