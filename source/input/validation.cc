#include <cdea/input/parameters.h>
#include <cdea/base/text.h>
#include <cdea/input/validation.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace cdea
{

  namespace
  {
    std::string format(const double x)
    {
      std::ostringstream o;
      o << x;
      return o.str();
    }

    /// [lo, hi] in the entry's unit; with zero_allowed, 0 as well.
    void require_range(const double value, const double lo, const double hi,
                       const std::string &name, const std::string &why,
                       const bool zero_allowed = false)
    {
      if (zero_allowed && value == 0.)
        return;
      if (lo > 0. && value <= 0.)
        throw InputError(name + (zero_allowed ? " must be zero or positive, got " :
                                                " must be positive, got ") +
                         format(value));
      if (!(value >= lo && value <= hi))
        throw InputError(name + " must be " + (zero_allowed ? "0 or " : "") + "between " +
                         format(lo) + " and " + format(hi) + why + ", got " + format(value));
    }

    constexpr double lo_dimensional = 1e-12, hi_dimensional = 1e12;
    const std::string dimensional   = " (in its unit)";

    /// Vacuum permittivity (F/m): no dielectric has less.
    constexpr double epsilon_0 = 8.8541878128e-12;

    /// The run's size: steps, samples and the results file held in memory.
    constexpr double max_steps          = 1e6;
    constexpr double max_elements       = 1e5;
    constexpr double max_samples        = 1e5; ///< per step
    constexpr double max_results_bytes  = 2e9;
    constexpr double bytes_per_step     = 6000.; ///< HDF5 objects of one step (measured)
    constexpr double bytes_per_sample   = 11 * 8.;
    constexpr std::size_t max_base_name = 200; ///< bytes; the file system allows 255

    /// Steps the load stages take at least (no cut-backs).
    double estimated_steps(const Parameters &p, const Scene &scene)
    {
      double steps = p.solver.prestretch_steps + std::ceil(1. / p.solver.load_increment);
      if (p.solver.continuation == Continuation::arc_length)
        return steps + p.solver.max_arc_length_steps;
      std::vector<double> previous(scene.n_rings(), 0.);
      const double        increment = p.solver.voltage_increment_kV * 1e3;
      for (const auto &waypoint : scene.path.waypoints())
        {
          double change = 0.;
          for (std::size_t k = 0; k < waypoint.size(); ++k)
            change = std::max(change, std::abs(waypoint[k] - previous[k]));
          // The stepper takes at least one step per waypoint, also to a
          // waypoint equal to the one before.
          steps += std::max(1., std::ceil(change / increment));
          previous = waypoint;
        }
      return steps;
    }

    void check_voltage(const double kV, const double ceiling, const std::string &name)
    {
      if (!(kV <= ceiling * 1e-3))
        throw InputError(name + ": " + format(kV) + " kV is above the ceiling of " +
                         format(ceiling * 1e-3) +
                         " kV for this film (the field V lam_pre^2 / H in the flat "
                         "pre-stretched film must stay below " +
                         format(max_flat_field * 1e-9) + " GV/m)");
    }
  } // namespace

  double voltage_ceiling(const Scene &scene)
  {
    return max_flat_field * scene.material.thickness / (scene.prestretch * scene.prestretch);
  }

  void validate_ranges(const Parameters &p, const Scene &scene)
  {
    const auto dim = [](const double v, const std::string &name, const bool zero = false) {
      require_range(v, lo_dimensional, hi_dimensional, name, dimensional, zero);
    };
    dim(p.geometry.disk_radius_mm, "Geometry/Disk radius (mm)");
    dim(p.geometry.frame_radius_mm, "Geometry/Frame radius (mm)");
    dim(p.geometry.film_thickness_mm, "Geometry/Film thickness (mm)");
    require_range(p.geometry.frame_radius_mm / p.geometry.disk_radius_mm, 1., 1000.,
                  "Geometry/Frame radius (mm) / Geometry/Disk radius (mm)",
                  " (b/a; the meridian is meshed between them)");
    require_range(p.geometry.prestretch, 1., 1000., "Geometry/Prestretch", "");
    dim(p.material.shear_modulus_kPa, "Material/Shear modulus (kPa)");
    require_range(p.material.jlim, lo_dimensional, hi_dimensional, "Material/Jlim", "");
    require_range(p.material.permittivity, epsilon_0, 1e6 * epsilon_0,
                  "Material/Permittivity (F/m)",
                  " (from the vacuum permittivity to a relative permittivity of 1e6)");
    dim(p.loading.mass_g, "Loading/Mass (g)", true);
    dim(p.loading.gravity, "Loading/Gravity (m/s^2)");
    dim(p.reservoir.width_mm, "Reservoir/Width (mm)");
    dim(p.reservoir.depth_mm, "Reservoir/Depth (mm)");
    dim(p.reservoir.water_volume_ml, "Reservoir/Water volume (ml)");
    dim(p.reservoir.water_density, "Reservoir/Water density (kg/m^3)");

    // Voltages: below the ceiling of this film.
    const double ceiling = voltage_ceiling(scene);
    {
      // From the text: a value near the largest double overflows in volts.
      std::stringstream waypoints(p.electrodes.voltage_path_text);
      std::string       waypoint;
      while (std::getline(waypoints, waypoint, ';'))
        for (const double kV : parse_number_list(waypoint, "Electrodes/Voltage path (kV)"))
          check_voltage(kV, ceiling, "Electrodes/Voltage path (kV)");
    }
    // The Sweep lists' syntax is checked for every command, so that a file
    // is refused (or accepted) by run and sweep alike.
    expand_value_list(p.sweep.ring_edge_values_text, "Sweep/Ring edge values (r/a)");
    check_voltage(p.sweep.inner_voltage_kV, ceiling, "Sweep/Inner voltage (kV)");
    {
      const auto range = parse_number_list(p.sweep.outer_voltage_range_text,
                                           "Sweep/Outer voltage range (kV)");
      for (std::size_t i = 0; i < std::min<std::size_t>(range.size(), 2); ++i)
        check_voltage(range[i], ceiling, "Sweep/Outer voltage range (kV)");
    }
    require_range(p.solver.breakdown_field_MV_per_m, 0., max_flat_field * 1e-6,
                  "Solver/Breakdown field (MV/m)", " (0: off)");

    // Solver settings.
    // Relative criteria: below about 100 double roundoffs Newton cannot get there.
    require_range(p.solver.residual_tolerance, 1e-14, 0.1, "Solver/Residual tolerance",
                  " (relative; rounding keeps the residual above about 1e-14)");
    require_range(p.solver.update_tolerance, 1e-14, 0.1, "Solver/Update tolerance",
                  " (relative; rounding keeps the update above about 1e-14)");
    require_range(p.solver.voltage_increment_kV, 1e-8, ceiling * 1e-3,
                  "Solver/Voltage increment (kV)", " (up to the voltage ceiling)");
    require_range(p.solver.max_displacement_mm, 0., hi_dimensional,
                  "Solver/Max displacement (mm)", " (0: no limit)");
    require_range(p.wrinkling.onset_tolerance_V, 1e-9, 1e6, "Wrinkling/Onset tolerance (V)", "");

    // The size of the run.
    const double elements = double(scene.n_rings()) * p.discretization.elements_per_ring *
                            std::pow(2., p.discretization.refinements);
    if (elements > max_elements)
      throw InputError("Discretization: " + format(elements) + " elements (rings x Elements "
                       "per ring x 2^Global refinements) are too many; at most " +
                       format(max_elements));
    const double samples = elements * p.discretization.samples_per_element;
    if (samples > max_samples)
      throw InputError("Discretization/Samples per element: " + format(samples) +
                       " samples per step are too many; at most " + format(max_samples));
    const double steps = estimated_steps(p, scene);
    const std::string step_entries =
      p.solver.continuation == Continuation::arc_length ?
        "Solver/Max arc-length steps, Load increment or Prestretch steps" :
        "Solver/Voltage increment (kV), Load increment or Prestretch steps";
    if (steps > max_steps)
      throw InputError("the run would take at least " + format(steps) + " steps (at most " +
                       format(max_steps) + "): raise " + step_entries);
    const double bytes = steps * (bytes_per_step + bytes_per_sample * samples);
    if (bytes > max_results_bytes)
      throw InputError("the results of at least " + format(steps) + " steps of " +
                       format(samples) + " samples would take about " + format(bytes * 1e-9) +
                       " GB, above the " + format(max_results_bytes * 1e-9) +
                       " GB that a results file may hold in memory: change " + step_entries +
                       " or Discretization/Samples per element");

    // Output names the file system can take, with room for the suffixes
    // of the run's side files (".partial.h5.tmp", ".recovered-N.h5").
    const std::string &base = p.output.base_name;
    if (base.size() > max_base_name)
      throw InputError("Output/Base name must have at most " + std::to_string(max_base_name) +
                       " characters, got " + std::to_string(base.size()));
    if (base == "." || base == "..")
      throw InputError("Output/Base name must be a file name, got '" + base + "'");
    for (const char c : base + p.output.directory)
      if (static_cast<unsigned char>(c) < 0x20)
        throw InputError("Output/Directory and Output/Base name must not contain control "
                         "characters");
    if (p.output.directory.size() > 3000)
      throw InputError("Output/Directory must have at most 3000 characters, got " +
                       std::to_string(p.output.directory.size()));
    {
      std::stringstream parts(p.output.directory);
      std::string       part;
      while (std::getline(parts, part, '/'))
        if (part.size() > 255)
          throw InputError("Output/Directory: a folder name has " + std::to_string(part.size()) +
                           " characters, more than the file system allows (255)");
    }
  }

  std::vector<std::string> duplicate_entry_warnings(const std::string &prm_text,
                                                    const std::string &filename)
  {
    std::vector<std::string>              warnings;
    std::vector<std::string>              sections;
    std::map<std::string, unsigned int>   first_line;
    std::istringstream                    in(prm_text);
    std::string                           line, logical;
    unsigned int                          number = 0, start = 0;
    const auto trim = [](const std::string &s) {
      const auto a = s.find_first_not_of(" \t\r");
      const auto b = s.find_last_not_of(" \t\r");
      return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
    };
    while (std::getline(in, line))
      {
        ++number;
        if (logical.empty())
          start = number;
        // A trailing backslash continues the line (deal.II's syntax).
        const std::string stripped = trim(line.substr(0, line.find('#')));
        if (!stripped.empty() && stripped.back() == '\\')
          {
            logical += stripped.substr(0, stripped.size() - 1) + ' ';
            continue;
          }
        logical += stripped;
        const std::string statement = trim(logical);
        logical.clear();
        if (statement.rfind("subsection", 0) == 0)
          sections.push_back(trim(statement.substr(10)));
        else if (statement == "end")
          {
            if (!sections.empty())
              sections.pop_back();
          }
        else if (statement.rfind("set", 0) == 0)
          {
            const auto equal = statement.find('=');
            if (equal == std::string::npos)
              continue;
            std::string name;
            for (const auto &s : sections)
              name += s + "/";
            // deal.II folds runs of blanks in names.
            std::string entry;
            for (const char c : trim(statement.substr(3, equal - 3)))
              if (c != ' ' || entry.empty() || entry.back() != ' ')
                entry += c;
            name += entry;
            const auto [it, fresh] = first_line.emplace(name, start);
            if (!fresh)
              warnings.push_back(filename + " line " + std::to_string(start) + ": " + name +
                                 " is set again (first on line " +
                                 std::to_string(it->second) + "); the last value is used");
          }
      }
    return warnings;
  }

} // namespace cdea
