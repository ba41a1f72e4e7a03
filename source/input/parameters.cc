#include <deal.II/base/parameter_handler.h>

#include <cdea/base/units.h>
#include <cdea/input/parameters.h>

#include <cmath>
#include <map>
#include <memory>
#include <sstream>

namespace cdea
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;

  namespace
  {
    /// The registered subsections by position, made on first use
    /// (registrations run during static initialisation, in an order the
    /// language leaves open).
    std::map<int, ParameterSubsection> &registry()
    {
      static std::map<int, ParameterSubsection> subsections;
      return subsections;
    }

    /// deal.II's pattern of @p e.
    std::unique_ptr<dealii::Patterns::PatternBase> pattern(const EntryDeclaration &e)
    {
      const EntryRange &r = e.range;
      switch (e.kind)
        {
          case EntryKind::number:
            return std::make_unique<Double>(r.lower.value_or(Double::min_double_value),
                                            r.upper.value_or(Double::max_double_value));
          case EntryKind::integer:
            return std::make_unique<Integer>(r.lower ? int(*r.lower) : Integer::min_int_value,
                                             r.upper ? int(*r.upper) : Integer::max_int_value);
          case EntryKind::flag:
            return std::make_unique<Bool>();
          case EntryKind::selection:
            return std::make_unique<dealii::Patterns::Selection>(e.options);
          case EntryKind::text:
            break;
        }
      return std::make_unique<Anything>();
    }

    /// The value of @p e in @p prm (in its subsection) as its kind reads it.
    EntryValue value_of(ParameterHandler &prm, const EntryDeclaration &e)
    {
      switch (e.kind)
        {
          case EntryKind::number:
            return prm.get_double(e.name);
          case EntryKind::integer:
            return prm.get_integer(e.name);
          case EntryKind::flag:
            return prm.get_bool(e.name);
          case EntryKind::selection:
          case EntryKind::text:
            break;
        }
      return prm.get(e.name);
    }
  } // namespace

  bool register_parameter_subsection(const ParameterSubsection &subsection)
  {
    if (!registry().emplace(subsection.position, subsection).second)
      throw std::logic_error("two parameter subsections are registered at position " +
                             std::to_string(subsection.position));
    return true;
  }

  void declare_entries(ParameterHandler &prm, const ParameterDeclarations &declarations)
  {
    for (const EntryDeclaration &e : declarations.entries())
      if (e.declared_here)
        {
          prm.enter_subsection(e.subsection);
          prm.declare_entry(e.name, e.default_value, *pattern(e), e.documentation);
          prm.leave_subsection();
        }
  }

  void read_entries(ParameterHandler &prm, const ParameterDeclarations &declarations)
  {
    for (const EntryDeclaration &e : declarations.entries())
      if (e.assign)
        {
          prm.enter_subsection(e.subsection);
          const EntryValue value = value_of(prm, e);
          prm.leave_subsection();
          e.assign(value);
        }
  }

  ParameterDeclarations Parameters::declarations()
  {
    ParameterDeclarations prm;
    for (const auto &[position, subsection] : registry())
      subsection.declare(prm, *this);
    return prm;
  }

  void Parameters::declare(ParameterHandler &prm)
  {
    Parameters defaults;
    declare_entries(prm, defaults.declarations());
  }

  void Parameters::parse(ParameterHandler &prm)
  {
    read_entries(prm, declarations());
  }

  void Parameters::check_subsections() const
  {
    for (const auto &[position, subsection] : registry())
      if (subsection.check)
        subsection.check(*this);
  }

  namespace
  {
    std::string format(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    /// Sizes and constants a scene cannot be built from.
    void check_geometry_and_material(const parameters::Geometry &geometry,
                                     const parameters::Material &material,
                                     const parameters::Loading  &loading)
    {
      require_positive(geometry.disk_radius_mm, "Geometry/Disk radius (mm)");
      require_positive(geometry.frame_radius_mm, "Geometry/Frame radius (mm)");
      require_positive(geometry.film_thickness_mm, "Geometry/Film thickness (mm)");
      if (geometry.frame_radius_mm <= geometry.disk_radius_mm)
        throw InputError("Geometry/Frame radius (mm) must be larger than Geometry/Disk radius "
                         "(mm) (" + format(geometry.disk_radius_mm) + "), got " +
                         format(geometry.frame_radius_mm));
      if (!(geometry.prestretch > 1.))
        throw InputError("Geometry/Prestretch must be larger than 1 (the film has to be taut), "
                         "got " + format(geometry.prestretch));
      require_positive(material.shear_modulus_kPa, "Material/Shear modulus (kPa)");
      require_positive(material.jlim, "Material/Jlim");
      require_positive(material.permittivity, "Material/Permittivity (F/m)");
      if (loading.mass_g < 0.)
        throw InputError("Loading/Mass (g) must be zero or positive, got " +
                         format(loading.mass_g));
      require_positive(loading.gravity, "Loading/Gravity (m/s^2)");

      // The equi-biaxial pre-stretch alone must stay inside the Gent limit:
      // I - 3 = 2 lam^2 + lam^-4 - 3 < Jlim.
      const double lam = geometry.prestretch;
      const double I3  = 2. * lam * lam + 1. / (lam * lam * lam * lam) - 3.;
      if (I3 >= material.jlim)
        throw InputError("Geometry/Prestretch " + format(lam) +
                         " already exceeds the Gent limit: I1 - 3 = " + format(I3) +
                         " must be below Material/Jlim = " + format(material.jlim));
    }

    /// Electrodes/Ring edges (r/a): 1 first, b/a last, increasing, no ring
    /// narrower than 1e-6.
    std::vector<double> ring_edges(const std::string &text, const double b_over_a)
    {
      const std::string name  = "Electrodes/Ring edges (r/a)";
      auto              edges = parse_number_list(text, name);
      if (edges.size() < 2)
        throw InputError(name + ": needs at least two edges (1 and b/a = " + format(b_over_a) +
                         "), got '" + text + "'");
      if (std::abs(edges.front() - 1.) > 1e-9)
        throw InputError(name + ": the first edge must be 1 (the disk edge), got " +
                         format(edges.front()));
      if (std::abs(edges.back() - b_over_a) > 1e-6 * b_over_a)
        throw InputError(name + ": the last edge must be b/a = " + format(b_over_a) +
                         " (the frame), got " + format(edges.back()));
      for (std::size_t i = 1; i < edges.size(); ++i)
        if (!(edges[i] > edges[i - 1]))
          throw InputError(name + ": edges must increase strictly, but " + format(edges[i]) +
                           " follows " + format(edges[i - 1]));
      // A narrower ring's elements are too short for the Newton update and
      // residual criteria (relative to a) to resolve it.
      for (std::size_t i = 1; i < edges.size(); ++i)
        if (edges[i] - edges[i - 1] < 1e-6)
          throw InputError(name + ": every ring must be at least 1e-6 (r/a) wide, but the "
                           "ring from " + format(edges[i - 1]) + " to " + format(edges[i]) +
                           " is narrower");
      edges.front() = 1.;
      edges.back()  = b_over_a;
      return edges;
    }

    /// Electrodes/Voltage path (kV): waypoints separated by ';', one
    /// voltage per ring each, in V.
    VoltagePath voltage_path(const std::string &text, const unsigned int n_rings)
    {
      const std::string                name = "Electrodes/Voltage path (kV)";
      std::vector<std::vector<double>> waypoints;
      for (const std::string &item : split_list(text, ';'))
        {
          auto w = parse_number_list(item, name);
          if (w.size() != n_rings)
            throw InputError(name + ": waypoint '" + item + "' has " +
                             std::to_string(w.size()) + " voltage(s), but there are " +
                             std::to_string(n_rings) +
                             " ring(s): give one voltage per ring, waypoints separated by ';'");
          for (double &v : w)
            {
              if (v < 0.)
                throw InputError(name + ": voltages must not be negative (the energy "
                                 "depends on Phi^2 only), got " + format(v));
              v *= 1e3;
            }
          waypoints.push_back(w);
        }
      if (waypoints.empty())
        throw InputError(name + ": no waypoint given");
      if (ends_with_separator(text, ';'))
        throw InputError(name + ": empty waypoint at the end of '" + text + "'");
      return VoltagePath(waypoints);
    }

    void check_output_and_increments(const parameters::Output &output,
                                     const parameters::Solver &solver)
    {
      if (output.base_name.empty() || output.base_name.find('/') != std::string::npos)
        throw InputError("Output/Base name must be a non-empty file name without '/', got '" +
                         output.base_name + "'");
      if (output.directory.empty())
        throw InputError("Output/Directory must not be empty (use . for the working directory)");
      if (solver.min_voltage_increment_kV > solver.voltage_increment_kV)
        throw InputError("Solver/Min voltage increment (kV) must not exceed Solver/Voltage "
                         "increment (kV)");
    }
  } // namespace

  Scene Parameters::scene() const
  {
    check_geometry_and_material(geometry, material, loading);
    Scene scene;
    scene.disk_radius  = units::mm.in_si(geometry.disk_radius_mm);
    scene.frame_radius = units::mm.in_si(geometry.frame_radius_mm);
    scene.prestretch   = geometry.prestretch;
    scene.material     = {units::kPa.in_si(material.shear_modulus_kPa), material.jlim,
                          material.permittivity, units::mm.in_si(geometry.film_thickness_mm)};
    scene.material_model = material_law.model;
    scene.law_constants  = material_law.constants;
    scene.law_texts      = material_law.texts;
    scene.mass         = units::g.in_si(loading.mass_g);
    scene.gravity      = loading.gravity;
    scene.ring_edges_over_a =
      ring_edges(electrodes.ring_edges_text, geometry.frame_radius_mm / geometry.disk_radius_mm);
    scene.path = voltage_path(electrodes.voltage_path_text, scene.n_rings());
    check_output_and_increments(output, solver);
    return scene;
  }

  std::string Parameters::results_path(const std::string &suffix) const
  {
    return output.directory + "/" + output.base_name + suffix + ".h5";
  }

  std::string default_parameter_file(const ParameterFormat format)
  {
    ParameterHandler prm;
    Parameters::declare(prm);
    std::ostringstream out;
    prm.print_parameters(out, format == ParameterFormat::json ? ParameterHandler::JSON :
                                                                ParameterHandler::PRM);
    return out.str();
  }
} // namespace cdea
