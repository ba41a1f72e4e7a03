#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/base/units.h>
#include <cdea/fe/load_term.h>
#include <cdea/input/parameters.h>
#include <cdea/input/validation.h>
#include <cdea/input/voltage_table.h>
#include <cdea/material/law_factory.h>
#include <cdea/output/paraview_writer.h>

#include <algorithm>
#include <cmath>
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
      const double        increment = units::kV.in_si(p.solver.voltage_increment_kV);
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
      if (!(kV <= units::kV.from_si(ceiling)))
        throw InputError(name + ": " + format(kV) + " kV is above the ceiling of " +
                         format(units::kV.from_si(ceiling)) +
                         " kV for this film (the field V lam_pre^2 / H in the flat "
                         "pre-stretched film must stay below " +
                         format(units::GV_per_m.from_si(max_flat_field)) + " GV/m)");
    }

    /// Lengths, material constants, loads and the Reservoir: finite and
    /// physically sensible.
    void check_dimensions(const Parameters &p)
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
      // Every load term checks its entries as it reads them, on or off.
      for (const LoadTerms::Plugin &plugin : LoadTerms::plugins())
        plugin.create(p.load_terms.values);
    }

    /// The first load term that @p p switches on and that lacks @p support
    /// (LoadTermSupport), or none.
    std::unique_ptr<LoadTerm> unsupported_load_term(const Parameters &p, const unsigned int support)
    {
      for (const LoadTerms::Plugin &plugin : LoadTerms::plugins())
        if (!(plugin.flags & support))
          if (auto term = plugin.create(p.load_terms.values); term->active())
            return term;
      return nullptr;
    }

    /// "ENTRY = VALUE is not supported with OPTION (use OFF)" for a term
    /// switched on that lacks @p support, when @p option_on.
    void refuse_with_option(const Parameters &p, const bool option_on, const unsigned int support,
                            const std::string &option)
    {
      if (!option_on)
        return;
      if (const auto term = unsupported_load_term(p, support))
        throw InputError(term->switched_on() + " is not supported with " + option + " (use " +
                         term->off_value() + ")");
    }

    /// Every voltage of the file below the film's @p ceiling (V), and the
    /// Sweep lists' syntax: checked for every command, so that a file is
    /// refused (or accepted) by run and sweep alike.
    void check_voltages(const Parameters &p, const double ceiling)
    {
      // From the text: a value near the largest double overflows in volts.
      for (const std::string &waypoint : split_list(p.electrodes.voltage_path_text, ';'))
        for (const double kV : parse_number_list(waypoint, "Electrodes/Voltage path (kV)"))
          check_voltage(kV, ceiling, "Electrodes/Voltage path (kV)");
      expand_value_list(p.sweep.ring_edge_values_text, "Sweep/Ring edge values (r/a)");
      check_voltage(p.sweep.inner_voltage_kV, ceiling, "Sweep/Inner voltage (kV)");
      const auto range =
        parse_number_list(p.sweep.outer_voltage_range_text, "Sweep/Outer voltage range (kV)");
      for (std::size_t i = 0; i < std::min<std::size_t>(range.size(), 2); ++i)
        check_voltage(range[i], ceiling, "Sweep/Outer voltage range (kV)");
      require_range(p.solver.breakdown_field_MV_per_m, 0., units::MV_per_m.from_si(max_flat_field),
                    "Solver/Breakdown field (MV/m)", " (0: off)");
    }

    void check_solver(const Parameters &p, const double ceiling)
    {
      // Relative criteria: below about 100 double roundoffs Newton cannot get there.
      require_range(p.solver.residual_tolerance, 1e-14, 0.1, "Solver/Residual tolerance",
                    " (relative; rounding keeps the residual above about 1e-14)");
      require_range(p.solver.update_tolerance, 1e-14, 0.1, "Solver/Update tolerance",
                    " (relative; rounding keeps the update above about 1e-14)");
      require_range(p.solver.voltage_increment_kV, 1e-8, units::kV.from_si(ceiling),
                    "Solver/Voltage increment (kV)", " (up to the voltage ceiling)");
      require_range(p.solver.max_displacement_mm, 0., hi_dimensional,
                    "Solver/Max displacement (mm)", " (0: no limit)");
      require_range(p.wrinkling.onset_tolerance_V, 1e-9, 1e6, "Wrinkling/Onset tolerance (V)",
                    "");
    }

    /// The size of the run: elements, samples, steps, and the results held in memory.
    void check_run_size(const Parameters &p, const Scene &scene)
    {
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
      // A step's ParaView file is built in memory (output/paraview_writer.h).
      if (const double vtu = ParaViewWriter::step_file_bytes(std::size_t(samples),
                                                             p.output.paraview_segments);
          p.output.paraview && vtu > ParaViewWriter::max_step_file_bytes)
        throw InputError("Output/ParaView segments = " +
                         std::to_string(p.output.paraview_segments) + " with " +
                         format(samples) + " samples per step: a step's ParaView file would "
                         "take about " + format(std::round(units::MB.from_si(vtu))) +
                         " MB, more than the " +
                         format(units::MB.from_si(ParaViewWriter::max_step_file_bytes)) +
                         " MB allowed; lower the segments or the samples");
      const double      steps = estimated_steps(p, scene);
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
                         format(samples) + " samples would take about " + format(units::GB.from_si(bytes)) +
                         " GB, above the " + format(units::GB.from_si(max_results_bytes)) +
                         " GB that a results file may hold in memory: change " + step_entries +
                         " or Discretization/Samples per element");
    }

    /// Output names the file system can take, with room for the suffixes
    /// of the run's side files (".partial.h5.tmp", ".recovered-N.h5").
    void check_output_names(const parameters::Output &output)
    {
      const std::string &base = output.base_name;
      if (base.size() > max_base_name)
        throw InputError("Output/Base name must have at most " + std::to_string(max_base_name) +
                         " characters, got " + std::to_string(base.size()));
      if (base == "." || base == "..")
        throw InputError("Output/Base name must be a file name, got '" + base + "'");
      for (const char c : base + output.directory)
        if (static_cast<unsigned char>(c) < 0x20)
          throw InputError("Output/Directory and Output/Base name must not contain control "
                           "characters");
      if (output.directory.size() > 3000)
        throw InputError("Output/Directory must have at most 3000 characters, got " +
                         std::to_string(output.directory.size()));
      for (const std::string &part : split_list(output.directory, '/'))
        if (part.size() > 255)
          throw InputError("Output/Directory: a folder name has " + std::to_string(part.size()) +
                           " characters, more than the file system allows (255)");
    }

    /// The law of Material/Model built from its entries (the law checks
    /// their ranges) and its interplay with the rest of the file: a law with
    /// internal variables evolves them in time and is no elastic law for the
    /// tension-field relaxation.
    void check_material_law(const Parameters &p)
    {
      const auto law = make_membrane_law(p.material_law.settings(p.scene().material));
      if (law->n_internal_variables() == 0)
        return;
      if (!p.time.enabled)
        throw InputError("Material/Model = " + p.material_law.model +
                         " needs Time/Enabled = true (a quasi-static run has no time for the "
                         "law's internal variables to evolve)");
      if (p.wrinkling.model == WrinklingModel::relaxed)
        throw InputError("Wrinkling/Model = relaxed needs Material/Model = " +
                         LawSettings().model +
                         " (the tension-field relaxation wraps an elastic law)");
    }

    void check_time_steps(const Parameters &p)
    {
      const auto &t = p.time;
      if (p.solver.continuation == Continuation::arc_length)
        throw InputError("Time/Enabled = true follows the waveform in time steps: set "
                         "Solver/Continuation = load stepping");
      require_positive(t.time_step_s, "Time/Time step (s)");
      require_positive(t.min_time_step_s, "Time/Min time step (s)");
      if (t.min_time_step_s > t.time_step_s)
        throw InputError("Time/Min time step (s) must not exceed Time/Time step (s)");
      if (!(t.fields_interval_s >= 0.))
        throw InputError("Time/Fields interval (s) must be zero or positive, got " +
                         format_number(t.fields_interval_s));
      if (!(t.relative_tolerance >= 1e-14 && t.relative_tolerance <= 0.1))
        throw InputError("Time/Relative tolerance must be between 1e-14 and 0.1, got " +
                         format_number(t.relative_tolerance));
      if (!(t.absolute_tolerance_mm >= 0. && t.absolute_tolerance_mm <= 1e3))
        throw InputError("Time/Absolute tolerance (mm) must be between 0 and 1000, got " +
                         format_number(t.absolute_tolerance_mm));
      if (!(t.internal_tolerance >= 0. && t.internal_tolerance <= 1.))
        throw InputError("Time/Internal variable tolerance must be between 0 and 1, got " +
                         format_number(t.internal_tolerance));
    }

    /// A sine is sampled at the time steps only (a square, a ramp and a
    /// table put a step on each of their knots), so a step of a period or
    /// more samples it at the same phase every time: a 1 Hz sine with 1 s
    /// steps stays at 0 V. Ten steps per period are the least that show its
    /// shape (the documented frequency sweeps use 14 or more).
    void check_sine_resolved(const parameters::Time &t)
    {
      constexpr double min_steps_per_period = 10.;
      const double     period               = 1. / t.frequency_Hz;
      if (t.time_step_s * min_steps_per_period > period * (1. + 1e-12))
        throw InputError("Time/Time step (s) = " + format_number(t.time_step_s) +
                         " is too coarse for the sine of Time/Frequency (Hz) = " +
                         format_number(t.frequency_Hz) + ": it needs at least " +
                         format_number(min_steps_per_period) +
                         " steps per period, a time step of at most " +
                         format_number(period / min_steps_per_period) + " s");
    }

    /// How long the waveform lasts (s), its entries checked; @p entries
    /// receives the entries the duration comes from, for messages.
    double waveform_duration(const Parameters &p, std::string &entries)
    {
      const auto &t = p.time;
      switch (t.waveform)
        {
          case WaveformKind::ramp_hold:
            require_positive(t.ramp_time_s, "Time/Ramp time (s)");
            if (!(t.hold_time_s >= 0.))
              throw InputError("Time/Hold time (s) must be zero or positive, got " +
                               format_number(t.hold_time_s));
            entries = "Time/Ramp time (s) + Time/Hold time (s)";
            return t.ramp_time_s + t.hold_time_s;
          case WaveformKind::square:
            require_positive(t.frequency_Hz, "Time/Frequency (Hz)");
            if (!(t.rise_time_s >= t.min_time_step_s))
              throw InputError("Time/Rise time (s) must be at least Time/Min time step (s) = " +
                               format_number(t.min_time_step_s) +
                               " s (an edge needs a step), got " + format_number(t.rise_time_s));
            if (!(t.rise_time_s < 0.5 / t.frequency_Hz))
              throw InputError("Time/Rise time (s) must be shorter than half a period, 1 / (2 "
                               "Frequency) = " + format_number(0.5 / t.frequency_Hz) +
                               " s, got " + format_number(t.rise_time_s));
            entries = "Time/Cycles / Time/Frequency (Hz)";
            return t.cycles / t.frequency_Hz;
          case WaveformKind::sine:
            require_positive(t.frequency_Hz, "Time/Frequency (Hz)");
            check_sine_resolved(t);
            entries = "Time/Cycles / Time/Frequency (Hz)";
            return t.cycles / t.frequency_Hz;
          case WaveformKind::table:
            break;
        }
      const Scene scene = p.scene();
      entries           = "the last time in Time/Table file";
      return read_voltage_table(t.table_file, scene.n_rings(), voltage_ceiling(scene))
        .times.back();
    }
  } // namespace

  double voltage_ceiling(const Scene &scene)
  {
    return max_flat_field * scene.material.thickness / (scene.prestretch * scene.prestretch);
  }

  void validate_ranges(const Parameters &p, const Scene &scene)
  {
    check_dimensions(p);
    const double ceiling = voltage_ceiling(scene);
    check_voltages(p, ceiling);
    check_solver(p, ceiling);
    check_run_size(p, scene);
    check_output_names(p.output);
  }

  void validate_time(const Parameters &p)
  {
    // A million steps (as for the quasi-static path) is three times the
    // longest documented scene (doc/time.md, 0.01 Hz at 1.25 ms) and keeps the
    // results held in memory below a gigabyte; more is most likely a mistyped
    // duration.
    constexpr double max_time_steps = 1e6;
    check_material_law(p);
    if (!p.time.enabled)
      return;
    check_time_steps(p);
    std::string  duration_entries;
    double       duration = waveform_duration(p, duration_entries);
    const double rest     = p.time.rest_time();
    if (std::isfinite(rest) && rest > 1e12)
      throw InputError("Time/Rest time before voltage (s) must be 'relaxed' or at most 1e12 s, "
                       "got " + format_number(rest));
    if (std::isfinite(rest))
      {
        duration += rest;
        duration_entries += " + Time/Rest time before voltage (s)";
      }
    const double step = p.time.time_step_s;
    if (!(duration / step <= max_time_steps))
      throw InputError("the run would take " + format_number(duration / step) +
                       " time steps, more than " + format_number(max_time_steps) +
                       ": its duration " + format_number(duration) + " s (" + duration_entries +
                       ") over Time/Time step (s) = " + format_number(step) +
                       "; shorten the run or raise the time step");
  }

  void validate_dynamics(const Parameters &p)
  {
    const auto &r = p.response;
    require_positive(r.lowest_frequency_Hz, "Response/Lowest frequency (Hz)");
    if (!(r.highest_frequency_Hz > r.lowest_frequency_Hz && r.highest_frequency_Hz <= 1e9))
      throw InputError("Response/Highest frequency (Hz) must be above Response/Lowest frequency "
                       "(Hz) (" + format_number(r.lowest_frequency_Hz) + ") and at most 1e9, got " +
                       format_number(r.highest_frequency_Hz));
    if (!(r.membrane_density >= 0. && r.membrane_density <= 1e5))
      throw InputError("Response/Membrane density (kg/m^3) must be between 0 and 1e5, got " +
                       format_number(r.membrane_density));
  }

  void validate_reservoir(const Parameters &p)
  {
    const auto &r = p.reservoir;
    require_positive(r.width_mm, "Reservoir/Width (mm)");
    require_positive(r.depth_mm, "Reservoir/Depth (mm)");
  }

  void validate_load_terms(const Parameters &p)
  {
    refuse_with_option(p, p.time.enabled, supports_time_runs, "Time/Enabled = true");
    refuse_with_option(p, p.solver.continuation == Continuation::arc_length, supports_arc_length,
                       "Solver/Continuation = arc length");
    refuse_with_option(p, p.solver.stability_check, supports_stability,
                       "Solver/Stability check = true");
  }

  void require_load_term_support(const Parameters &p, const unsigned int support,
                                 const std::string &command, const std::string &why)
  {
    if (const auto term = unsupported_load_term(p, support))
      throw InputError(term->switched_on() + " is not supported by cdea " + command + ": " + why +
                       " (use " + term->off_value() + ")");
  }

  void require_shooting_options(const Parameters &p, const std::string &command)
  {
    if (const auto term = unsupported_load_term(p, supports_shooting))
      throw InputError(term->switched_on() + " is implemented in the FE model only: use "
                       "'cdea run', or set it to " + term->off_value() + " for 'cdea " +
                       command + "'");
    if (p.wrinkling.model == WrinklingModel::relaxed)
      throw InputError("Wrinkling/Model = relaxed is implemented in the FE model only: use "
                       "'cdea run', or set it to check for 'cdea " +
                       command + "'");
    if (p.time.enabled)
      throw InputError("Time/Enabled = true is implemented for 'cdea run' only: set it to "
                       "false for 'cdea " +
                       command + "'");
    if (!serves_every_model(p))
      throw InputError("Material/Model = " + p.material_law.model +
                       " is implemented in the FE model only: use 'cdea run', or set it to " +
                       LawSettings().model + " for 'cdea " + command + "'");
  }

  bool serves_every_model(const Parameters &p)
  {
    return p.scene().law()->serves_every_model();
  }

  void require_film_law(const Parameters &p, const std::string &command, const std::string &why)
  {
    const std::string film_law = LawSettings().model;
    if (!serves_every_model(p))
      throw InputError("Material/Model = " + p.material_law.model + " is not supported by cdea " +
                       command + ": " + why + " (use " + film_law + ")");
  }

  void require_quasi_static_elastic(const Parameters &p, const std::string &command)
  {
    require_film_law(p, command,
                     "its sensitivities are those of the " + LawSettings().model + " law");
    if (p.time.enabled)
      throw InputError("Time/Enabled = true is not supported by cdea " + command +
                       ": it works on quasi-static equilibria (use false)");
  }
} // namespace cdea
