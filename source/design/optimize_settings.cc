// Subsection Optimization checked and turned into OptimizationSettings, and
// the layouts' free variables.

#include <cdea/base/units.h>
#include <cdea/design/optimize.h>
#include <cdea/fe/load_term.h>
#include <cdea/input/parameters.h>
#include <cdea/input/validation.h>
#include <cdea/base/format.h>

#include <cctype>
#include <cmath>
#include <sstream>
#include <tuple>

namespace cdea
{
  namespace
  {
    std::string format(const double x) { return format_number(x, 12); }

    /// @p text without its leading and trailing blanks.
    std::string trimmed(const std::string &text)
    {
      std::size_t begin = 0, end = text.size();
      while (begin < end && std::isspace(static_cast<unsigned char>(text[begin])))
        ++begin;
      while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1])))
        --end;
      return text.substr(begin, end - begin);
    }

    /// Entries separated by ',', each a number or 'free' (NaN).
    std::vector<double> numbers_or_free(const std::string &text, const std::string &name)
    {
      std::vector<double> values;
      for (const std::string &item : split_list(text, ','))
        {
          const std::string token = trimmed(item);
          if (token.empty())
            throw InputError(name + ": empty entry in '" + text +
                             "' (expected numbers or 'free' separated by ',')");
          values.push_back(token == "free" ? OptimizationSettings::free :
                                             parse_number(token, name, text));
        }
      if (values.empty())
        throw InputError(name + ": no value given (expected numbers or 'free')");
      if (trimmed(text).back() == ',') // a ',' at the end closes the last entry only
        throw InputError(name + ": empty entry at the end of '" + text + "'");
      return values;
    }

    /// "lower, upper" with lower < upper.
    std::pair<double, double> bounds(const std::string &text, const std::string &name)
    {
      const auto v = parse_number_list(text, name);
      if (v.size() != 2)
        throw InputError(name + ": expected two numbers 'lower, upper', got '" + text + "'");
      if (!(v[0] < v[1]))
        throw InputError(name + ": the lower bound " + format(v[0]) +
                         " must be below the upper bound " + format(v[1]));
      return {v[0], v[1]};
    }

    double one_number(const std::string &text, const std::string &name)
    {
      const auto v = parse_number_list(text, name);
      if (v.size() != 1)
        throw InputError(name + ": expected one number, got '" + text + "'");
      return v[0];
    }
  } // namespace

  std::vector<SceneParameter> OptimizationSettings::free_parameters() const
  {
    std::vector<SceneParameter> list;
    for (unsigned int k = 0; k < n_rings; ++k)
      if (std::isnan(voltages[k]))
        list.push_back({ParameterKind::voltage, k});
    for (unsigned int k = 1; k < n_rings; ++k)
      if (std::isnan(edges[k]))
        list.push_back({ParameterKind::ring_edge, k});
    return list;
  }

  std::vector<double> Layout::free_values(const std::vector<SceneParameter> &free) const
  {
    std::vector<double> v;
    for (const auto &p : free)
      v.push_back(p.kind == ParameterKind::voltage ? voltages[p.index] : edges[p.index]);
    return v;
  }

  void Layout::set_free_values(const std::vector<SceneParameter> &free,
                               const std::vector<double>         &values)
  {
    for (std::size_t j = 0; j < free.size(); ++j)
      (free[j].kind == ParameterKind::voltage ? voltages[free[j].index] :
                                                edges[free[j].index]) = values[j];
  }

  Scene layout_scene(const Scene &base, const Layout &layout)
  {
    Scene scene             = base;
    scene.ring_edges_over_a = layout.edges;
    scene.path              = VoltagePath(std::vector<std::vector<double>>{layout.voltages});
    return scene;
  }

  namespace
  {
    /// What cdea optimize does not support.
    void require_supported(const Parameters &p)
    {
      require_quasi_static_elastic(p, "optimize");
      if (p.wrinkling.model != WrinklingModel::check)
        throw InputError("Wrinkling/Model = " + to_string(p.wrinkling.model) +
                         " is not supported by cdea optimize: the constraint is on the hoop "
                         "stress of the plain membrane law (use check)");
      require_load_term_support(p, supports_sensitivities, "optimize",
                                "the layouts are designed for the actuator under its dead load");
    }

    /// Fixed voltages (kV): one per ring, or one 'free' for all; in V.
    std::vector<double> fixed_voltages(const parameters::Optimization &o, const unsigned int n_rings,
                                       const double ceiling)
    {
      const std::string name     = "Optimization/Fixed voltages (kV)";
      auto              voltages = numbers_or_free(o.fixed_voltages_text, name);
      if (voltages.size() == 1 && std::isnan(voltages[0]))
        voltages.assign(n_rings, OptimizationSettings::free);
      if (voltages.size() != n_rings)
        throw InputError(name + ": " + std::to_string(voltages.size()) + " entries for " +
                         std::to_string(n_rings) +
                         " rings (Optimization/Rings): give one voltage or 'free' per ring");
      for (double &v : voltages)
        {
          if (v < 0.)
            throw InputError(name + ": voltages must not be negative, got " + format(v));
          if (v > units::kV.from_si(ceiling))
            throw InputError(name + ": " + format(v) + " kV is above the voltage ceiling of " +
                             format(units::kV.from_si(ceiling)) + " kV for this film");
          v *= 1e3;
        }
      return voltages;
    }

    /// All N+1 edges (r/a): 1, the fixed interior ones (NaN: free), b/a.
    std::vector<double> ring_edges(const parameters::Optimization &o, const unsigned int n_rings,
                                   const double b_over_a)
    {
      const std::string name     = "Optimization/Fixed ring edges (r/a)";
      auto              interior = numbers_or_free(o.fixed_edges_text, name);
      if (interior.size() == 1 && std::isnan(interior[0]))
        interior.assign(n_rings - 1, OptimizationSettings::free);
      if (interior.size() != n_rings - 1)
        throw InputError(name + ": " + std::to_string(interior.size()) + " entries for the " +
                         std::to_string(n_rings - 1) + " interior edges of " +
                         std::to_string(n_rings) +
                         " rings: give N-1 numbers or 'free', or one 'free' for all");
      std::vector<double> edges = {1.};
      edges.insert(edges.end(), interior.begin(), interior.end());
      edges.push_back(b_over_a);
      for (unsigned int k = 1; k < n_rings; ++k)
        if (!std::isnan(edges[k]) && !(edges[k] > 1. && edges[k] < b_over_a))
          throw InputError(name + ": " + format(edges[k]) + " is not inside (1, " +
                           format(b_over_a) + ")");
      return edges;
    }

    /// The bounds of the free edges (r/a) and voltages (V).
    void variable_bounds(const parameters::Optimization &o, const double b_over_a,
                         const double ceiling, OptimizationSettings &s)
    {
      const std::string edge_name = "Optimization/Edge bounds (r/a)";
      std::tie(s.edge_lower, s.edge_upper) = bounds(o.edge_bounds_text, edge_name);
      if (s.edge_lower < 1. || s.edge_upper > b_over_a)
        throw InputError(edge_name + ": the bounds must lie inside [1, b/a = " +
                         format(b_over_a) + "], got " + o.edge_bounds_text);
      const std::string voltage_name = "Optimization/Voltage bounds (kV)";
      std::tie(s.voltage_lower, s.voltage_upper) = bounds(o.voltage_bounds_text, voltage_name);
      if (s.voltage_lower < 0.)
        throw InputError(voltage_name + ": the lower bound must not be negative, got " +
                         format(s.voltage_lower));
      if (s.voltage_upper > units::kV.from_si(ceiling))
        throw InputError(voltage_name + ": the upper bound " + format(s.voltage_upper) +
                         " kV is above the voltage ceiling of " + format(units::kV.from_si(ceiling)) +
                         " kV for this film");
      s.voltage_lower *= 1e3;
      s.voltage_upper *= 1e3;
    }

    /// The limits of the constraints: hoop stress (Pa), field (V/m), ring
    /// width (r/a); returns the width in mm as given.
    double constraint_limits(const parameters::Optimization &o, const Scene &scene,
                             OptimizationSettings &s)
    {
      s.min_hoop_stress =
        units::kPa.in_si(
          one_number(o.min_hoop_stress_text, "Optimization/Minimum hoop stress (kPa)"));
      const std::string field_name = "Optimization/Maximum field (MV/m)";
      if (trimmed(o.max_field_text) == "inf")
        s.max_field = std::numeric_limits<double>::infinity();
      else
        {
          s.max_field = units::MV_per_m.in_si(one_number(o.max_field_text, field_name));
          if (!(s.max_field > 0.))
            throw InputError(field_name + " must be positive or 'inf', got " + o.max_field_text);
        }
      const std::string width_name = "Optimization/Minimum ring width (mm)";
      const double      width_mm   = one_number(o.min_ring_width_text, width_name);
      if (width_mm < 0.)
        throw InputError(width_name + " must not be negative, got " + format(width_mm));
      s.min_ring_width = units::mm.in_si(width_mm) / scene.disk_radius;
      return width_mm;
    }

    /// The fixed edges must leave room: every ring at least the minimum
    /// width, between fixed neighbours and the bounds of the free edges.
    void check_room(const parameters::Optimization &o, const OptimizationSettings &s,
                    const double width_mm)
    {
      const std::string width_name = "Optimization/Minimum ring width (mm)";
      double            lowest     = 1.;
      for (unsigned int k = 1; k <= s.n_rings; ++k)
        {
          const bool   fixed = k == s.n_rings || !std::isnan(s.edges[k]);
          const double least = lowest + s.min_ring_width;
          if (fixed)
            {
              if (s.edges[k] < least - 1e-12)
                throw InputError(width_name + ": ring " + std::to_string(k) + " cannot be " +
                                 format(width_mm) +
                                 " mm wide with the fixed edges and Optimization/Edge bounds "
                                 "(r/a)");
              lowest = s.edges[k];
            }
          else
            {
              lowest = std::max(least, s.edge_lower);
              if (lowest > s.edge_upper)
                throw InputError(width_name + ": " + std::to_string(s.n_rings) + " rings of " +
                                 format(width_mm) + " mm do not fit between the edge bounds " +
                                 o.edge_bounds_text);
            }
        }
    }
  } // namespace

  OptimizationSettings optimization_settings(const Parameters &p, const Scene &scene)
  {
    require_supported(p);
    const parameters::Optimization &o = p.optimization;
    OptimizationSettings            s;
    const double                    b_over_a = scene.frame_radius / scene.disk_radius;
    const double                    ceiling  = voltage_ceiling(scene);
    s.n_rings                                = o.rings;
    s.voltages                               = fixed_voltages(o, s.n_rings, ceiling);
    s.edges                                  = ring_edges(o, s.n_rings, b_over_a);
    variable_bounds(o, b_over_a, ceiling, s);
    const double width_mm = constraint_limits(o, scene, s);
    check_room(o, s, width_mm);

    s.objective       = o.objective;
    s.starts          = o.starts;
    s.algorithm       = o.algorithm;
    s.max_evaluations = o.max_evaluations;
    s.tolerance       = o.tolerance;
    if (s.free_parameters().empty())
      throw InputError("Optimization: nothing to optimise: every voltage and every ring edge "
                       "is fixed (set some of Fixed voltages (kV) or Fixed ring edges (r/a) "
                       "to 'free')");
    return s;
  }
} // namespace cdea
