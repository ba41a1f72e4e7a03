#include <cdea/fe/error_estimate.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/model_access.h>
#include <cdea/base/format.h>
#include <cdea/model/load_state.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// The highest degree the input allows (Discretization/Polynomial degree).
    constexpr unsigned int highest_degree = 8;

    KeyOutputs key_outputs(const MembraneModel &model)
    {
      return {model.displacement(), model.enclosed_volume(), model.hoop_stresses().s2_min};
    }

    KeyOutputs absolute_change(const KeyOutputs &from, const KeyOutputs &to)
    {
      return {std::abs(to.displacement - from.displacement), std::abs(to.volume - from.volume),
              std::abs(to.s2_min - from.s2_min)};
    }

    /// The unknowns of @p coarse's current state interpolated at the
    /// support points of @p fine's dofs: exact where every coarse cell is a
    /// union of fine cells and the fine degree is at least the coarse one.
    std::vector<double> embedded_unknowns(const MembraneModel &coarse, const MembraneModel &fine)
    {
      const auto                support = fine.dof_support();
      std::vector<unsigned int> order(support.size());
      std::iota(order.begin(), order.end(), 0u);
      // Sorted by radius, so that profile_at() walks the cells once.
      std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
        return support[a].first < support[b].first;
      });
      std::vector<double> R(order.size()), r, z;
      for (std::size_t k = 0; k < order.size(); ++k)
        R[k] = support[order[k]].first;
      coarse.profile_at(R, r, z);
      std::vector<double> x(support.size());
      for (std::size_t k = 0; k < order.size(); ++k)
        x[order[k]] = support[order[k]].second == 0 ? r[k] : z[k];
      return x;
    }
  } // namespace

  FeDiscretization enriched_discretization(const FeDiscretization &coarse)
  {
    FeDiscretization richer = coarse;
    if (coarse.degree < highest_degree)
      ++richer.degree;
    else
      ++richer.refinements;
    return richer;
  }

  HierarchicalEstimate::HierarchicalEstimate(std::unique_ptr<MembraneModel> coarse_model,
                                             std::unique_ptr<MembraneModel> enriched_model)
    : coarse(std::move(coarse_model))
    , enriched(std::move(enriched_model))
  {}

  HierarchicalEstimate::~HierarchicalEstimate() = default;

  const Discretization &HierarchicalEstimate::enriched_discretization() const
  {
    return enriched->discretization();
  }

  SolveReport HierarchicalEstimate::solve_enriched(const ModelState &state)
  {
    coarse->set_state(state);
    enriched->set_state({state.load, embedded_unknowns(*coarse, *enriched), enriched->state().internal});
    return enriched->solve(state.load);
  }

  StateComparison HierarchicalEstimate::compare(const ModelState &state)
  {
    StateComparison out;
    coarse->set_state(state);
    out.coarse = key_outputs(*coarse);

    // Newton's correction of the coarse iterate: du = K^-1 r, x - du.
    ModelAccess &access = coarse->access();
    if (access.state_tangent())
      {
        Eigen::VectorXd du;
        access.solve_tangent(access.system().residual, du);
        std::vector<double> corrected = state.unknowns;
        for (std::size_t i = 0; i < corrected.size(); ++i)
          corrected[i] -= du[i];
        coarse->set_solution(corrected);
        out.newton = absolute_change(out.coarse, key_outputs(*coarse));
        coarse->set_state(state);
      }

    const SolveReport solved = solve_enriched(state);
    out.converged            = solved.converged;
    out.iterations           = solved.iterations;
    if (solved.converged)
      out.enriched = key_outputs(*enriched);
    return out;
  }

  OnsetComparison HierarchicalEstimate::onset(const ModelState                       &state,
                                              const std::function<LoadState(double)> &path,
                                              const double                            dt)
  {
    OnsetComparison out;
    const double    t = state.load.load_factor;
    coarse->set_state(state);
    const double coarse_margin = coarse->hoop_stresses().s2_min;
    if (!solve_enriched(state).converged)
      return out;
    const double margin = enriched->hoop_stresses().s2_min;
    if (!enriched->solve(path(t + dt)).converged)
      return out;
    const double slope = (enriched->hoop_stresses().s2_min - margin) / dt;
    out.coarse_root    = t - coarse_margin / slope;
    out.enriched_root  = t - margin / slope;
    out.converged      = std::isfinite(slope) && slope != 0.;
    return out;
  }

  namespace
  {
    using Output = double KeyOutputs::*;

    /// An output of one state: the richer solution's change, Newton's part.
    ErrorParts state_part(const StateComparison &c, const Output q)
    {
      ErrorParts e;
      if (c.converged)
        e.discretization = std::abs(c.enriched.*q - c.coarse.*q);
      e.newton = c.newton.*q;
      return e;
    }

    /// A change of an output from state @p from to state @p to (the stroke,
    /// the volume change): the difference of their richer changes.
    ErrorParts change_part(const StateComparison &to, const StateComparison &from, const Output q)
    {
      ErrorParts e;
      if (to.converged && from.converged)
        e.discretization =
          std::abs((to.enriched.*q - to.coarse.*q) - (from.enriched.*q - from.coarse.*q));
      e.newton = to.newton.*q + from.newton.*q;
      return e;
    }

    std::string method_text(const FeDiscretization &coarse, const FeDiscretization &richer)
    {
      std::ostringstream o;
      o << "the converged states solved again with degree " << richer.degree;
      if (richer.refinements != coarse.refinements)
        o << " and every element bisected";
      else
        o << " on the same mesh";
      o << " (the change is the discretization part), Newton's remaining residual "
           "|Q(x - K^-1 r) - Q(x)|, and the onset search's bracket";
      return o.str();
    }
  } // namespace

  RunErrorEstimate::RunErrorEstimate(const Scene &scene, const FeDiscretization &discretization,
                                     const double onset_tolerance, ModelFactory make)
    : scene(scene)
    , discretization(discretization)
    , onset_tolerance(onset_tolerance)
    , make(std::move(make))
  {}

  void RunErrorEstimate::step(const StepSummary &summary, const EquilibriumModel &model)
  {
    last = model.state();
    if (summary.stage == Stage::prestretch)
      load_end.reset();
    if (summary.stage == Stage::dead_load && summary.load_factor == 1.)
      load_end = last;
  }

  void RunErrorEstimate::onset(const EquilibriumModel &model) { onset_state = model.state(); }

  OutputErrors RunErrorEstimate::estimate() const
  {
    const FeDiscretization &coarse = discretization;
    const FeDiscretization  richer = enriched_discretization(coarse);
    OutputErrors           e;
    e.method = method_text(coarse, richer);
    if (!last)
      return e;
    HierarchicalEstimate h(make(coarse), make(richer));
    const StateComparison final_state = h.compare(*last);
    e.displacement = state_part(final_state, &KeyOutputs::displacement);
    e.s2_min       = state_part(final_state, &KeyOutputs::s2_min);
    if (load_end)
      {
        const StateComparison loaded = h.compare(*load_end);
        e.stroke        = change_part(final_state, loaded, &KeyOutputs::displacement);
        e.volume_change = change_part(final_state, loaded, &KeyOutputs::volume);
      }
    if (!onset_state || onset_state->load.stage != Stage::voltage)
      return e;
    // The richer margin's slope from a state 1 V before the onset (on the
    // side where the path has come from); the search's bracket in t.
    const double t    = onset_state->load.load_factor;
    const double rate = scene.path.max_rate(t);
    if (!(rate > 0.))
      return e;
    const auto path = [&](const double s) { return full_load(scene, scene.path.voltages(s), s); };
    const OnsetComparison o       = h.onset(*onset_state, path, -1. / rate);
    const double          bracket = onset_tolerance / rate;
    const auto v_t = scene.path.voltages(t), v_bracket = scene.path.voltages(t + bracket);
    const auto v_coarse = scene.path.voltages(o.coarse_root),
               v_richer = scene.path.voltages(o.enriched_root);
    e.onset_voltages.resize(scene.n_rings());
    for (unsigned int k = 0; k < scene.n_rings(); ++k)
      {
        ErrorParts &v = e.onset_voltages[k];
        if (o.converged)
          v.discretization = std::abs(v_richer[k] - v_coarse[k]);
        v.search = std::abs(v_bracket[k] - v_t[k]);
      }
    return e;
  }

  std::string describe_errors(const OutputErrors &errors, const StepSummary &last,
                              const std::vector<double> &onset_voltages, const double shear_modulus)
  {
    using namespace summary_attribute;
    std::ostringstream o;
    // "name value unit (estimated error e unit)", both in the error row's unit.
    const auto line = [&](const std::string &name, const double value, const double error,
                          const Quantity &row) {
      o << "  " << name << ' ' << format_number(row.in_file_units(value), 7) << ' '
        << row.unit.name << " (estimated error " << format_number(row.in_file_units(error), 2)
        << ' ' << row.unit.name << ")\n";
    };
    line("displacement", last.displacement, errors.displacement.total(), displacement_error);
    line("stroke", last.stroke, errors.stroke.total(), stroke_error);
    line("volume change", last.columns.get(summary_column::volume_change),
         errors.volume_change.total(), volume_change_error);
    o << "  smallest hoop stress s2_min/mu " << format_number(last.s2_min / shear_modulus, 7)
      << " (estimated error " << format_number(errors.s2_min.total() / shear_modulus, 2) << ")\n";
    for (std::size_t k = 0; k < errors.onset_voltages.size() && k < onset_voltages.size(); ++k)
      line("onset voltage of ring " + std::to_string(k + 1), onset_voltages[k],
           errors.onset_voltages[k].total(), onset_voltage_error);
    return o.str();
  }
} // namespace cdea
