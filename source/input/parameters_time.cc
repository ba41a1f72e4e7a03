#include <deal.II/base/parameter_handler.h>

#include <cdea/input/parameters.h>
#include <cdea/input/parameters_time.h>
#include <cdea/input/pump.h>
#include <cdea/input/validation.h>
#include <cdea/base/format.h>
#include <cdea/material/law_factory.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace cdea
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  namespace parameters
  {
    void ViscousMaterial::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("Model", "elastic", Selection("elastic|viscoelastic"),
                        "'elastic': the Gent law of Shear modulus and Jlim. 'viscoelastic': that "
                        "law is network A (the long-time response), in parallel with network B, a "
                        "Gent spring in series with a dashpot (two-network model of Hong 2011 and "
                        "Zhao, Koh, Suo 2011); needs Time/Enabled = true.");
      prm.declare_entry("Network B shear modulus (kPa)", "45", Double(),
                        "Shear modulus mu_B of network B's spring (viscoelastic model).");
      prm.declare_entry("Network B Jlim", "270", Double(), "Gent limit Jlim_B of network B's spring.");
      prm.declare_entry("Relaxation time (s)", "2", Double(),
                        "tau = eta / mu_B of network B (eta: the dashpot's viscosity).");
      prm.leave_subsection();
    }

    void ViscousMaterial::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      model = prm.get("Model") == "viscoelastic" ? MaterialModel::viscoelastic :
                                                   MaterialModel::elastic;
      network_b_shear_modulus_kPa = prm.get_double("Network B shear modulus (kPa)");
      network_b_jlim              = prm.get_double("Network B Jlim");
      relaxation_time_s           = prm.get_double("Relaxation time (s)");
      prm.leave_subsection();
    }

    void Time::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      prm.declare_entry("Enabled", "false", Bool(),
                        "true: after the quasi-static pre-stretch and weight, integrate in time "
                        "through the voltage waveform (cdea run only); false: the quasi-static "
                        "voltage path.");
      prm.declare_entry("Waveform", "ramp-hold", Selection("ramp-hold|square|sine|table"),
                        "ramp-hold: from 0 to the last waypoint's voltages in Ramp time, then held "
                        "for Hold time. square, sine: between 0 and the last waypoint's voltages "
                        "at Frequency for Cycles periods. table: the Table file.");
      prm.declare_entry("Ramp time (s)", "1", Double(), "ramp-hold: duration of the ramp.");
      prm.declare_entry("Hold time (s)", "20", Double(), "ramp-hold: how long the peak is held.");
      prm.declare_entry("Frequency (Hz)", "0.5", Double(), "square, sine: drive frequency.");
      prm.declare_entry("Cycles", "10", Integer(1, 10000000), "square, sine: periods driven.");
      prm.declare_entry("Rise time (s)", "0.01", Double(),
                        "square: each edge is a linear ramp of this duration (below half a period).");
      prm.declare_entry("Table file", "", Anything(),
                        "table: a CSV file (relative to the working directory) of rows 'time_s, "
                        "one voltage per ring (kV)' with increasing times from 0; '#' lines and a "
                        "first line that starts with a name (a header) are skipped. The voltages "
                        "are linear between rows and start from 0 V at t = 0 when the first row "
                        "is later.");
      prm.declare_entry("Time step (s)", "0.01", Double(),
                        "Largest time step; steps are halved where Newton needs it and land on "
                        "every ramp end and square edge.");
      prm.declare_entry("Min time step (s)", "1e-8", Double(),
                        "A step cut below this ends the run (exit code 2).");
      prm.declare_entry("Scheme", "backward Euler", Selection("backward Euler|trapezoidal"),
                        "Time integration of the dashpots' stretches: backward Euler (first order, "
                        "L-stable) or the trapezoidal rule (second order). The disk's inertia "
                        "always uses Newmark's average acceleration (second order).");
      prm.declare_entry("Inertia", "true", Bool(),
                        "The disk's mass (Loading/Mass) in m z'' on the disk (Newmark); the "
                        "membrane's own mass is neglected. false: quasi-static in time.");
      prm.declare_entry("Water inertia", "false", Bool(),
                        "With Inertia and Reservoir/Water load: the water column in the level "
                        "tube moves with the enclosed volume (kinetic energy rho h V'^2 / (2 S)).");
      prm.declare_entry("Fields interval (s)", "0", Double(),
                        "Every time step is a row of /summary; the fields along the meridian "
                        "(/steps) are written at the start, at every ramp end and square edge "
                        "(breakpoint) of the waveform, at the end, and every this much time "
                        "(0: only there).");
      prm.declare_entry("Rest time before voltage (s)", "relaxed", Anything(),
                        "'relaxed': network B has relaxed under the pre-stretch and the weight "
                        "before t = 0. A time in s: the pre-stretched film is relaxed, the weight "
                        "is hung quickly and held that long at 0 V before the waveform starts.");
      prm.leave_subsection();
    }

    void Time::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      enabled               = prm.get_bool("Enabled");
      const std::string w   = prm.get("Waveform");
      waveform              = w == "square" ? WaveformKind::square :
                              w == "sine"   ? WaveformKind::sine :
                              w == "table"  ? WaveformKind::table :
                                              WaveformKind::ramp_hold;
      ramp_time_s           = prm.get_double("Ramp time (s)");
      hold_time_s           = prm.get_double("Hold time (s)");
      frequency_Hz          = prm.get_double("Frequency (Hz)");
      cycles                = prm.get_integer("Cycles");
      rise_time_s           = prm.get_double("Rise time (s)");
      table_file            = prm.get("Table file");
      time_step_s           = prm.get_double("Time step (s)");
      min_time_step_s       = prm.get_double("Min time step (s)");
      scheme                = prm.get("Scheme") == "trapezoidal" ? TimeScheme::trapezoidal :
                                                                   TimeScheme::backward_euler;
      inertia               = prm.get_bool("Inertia");
      water_inertia         = prm.get_bool("Water inertia");
      rest_time_text        = prm.get("Rest time before voltage (s)");
      fields_interval_s     = prm.get_double("Fields interval (s)");
      prm.leave_subsection();
    }
  } // namespace parameters

  std::string to_string(const MaterialModel choice)
  {
    return choice == MaterialModel::viscoelastic ? "viscoelastic" : "elastic";
  }

  std::string to_string(const WaveformKind choice)
  {
    switch (choice)
      {
        case WaveformKind::square:
          return "square";
        case WaveformKind::sine:
          return "sine";
        case WaveformKind::table:
          return "table";
        case WaveformKind::ramp_hold:
          break;
      }
    return "ramp-hold";
  }

  std::string to_string(const TimeScheme choice)
  {
    return choice == TimeScheme::trapezoidal ? "trapezoidal" : "backward Euler";
  }

  namespace
  {
    double rest_time(const parameters::Time &t)
    {
      const std::string name = "Time/Rest time before voltage (s)";
      if (t.rest_time_text == "relaxed")
        return std::numeric_limits<double>::infinity();
      double value = 0.;
      try
        {
          value = parse_number(t.rest_time_text, name, t.rest_time_text);
        }
      catch (const InputError &)
        {
          throw InputError(name + " must be 'relaxed' or a time >= 0 in s, got '" +
                           t.rest_time_text + "'");
        }
      if (!(value >= 0.))
        throw InputError(name + " must be 'relaxed' or a time >= 0 in s, got " +
                         format_number(value));
      return value;
    }

    /// The table file as messages name it: a relative path with the path it
    /// resolves to from the working directory.
    std::string describe_file(const std::string &file)
    {
      const std::filesystem::path path(file);
      std::error_code             error;
      const auto                  resolved = std::filesystem::absolute(path, error);
      if (path.is_absolute() || error)
        return "'" + file + "'";
      return "'" + file + "' (relative to the working directory: " + resolved.string() + ")";
    }

    /// Rows of the table file: times (s) and voltages (V) per ring, each
    /// voltage at most @p ceiling (V; the film's, as for the voltage path).
    void read_table(const std::string &file, const Scene &scene, std::vector<double> &times,
                    std::vector<std::vector<double>> &volts)
    {
      const unsigned int n_rings = scene.n_rings();
      const double       ceiling = voltage_ceiling(scene);
      const std::string name = "Time/Table file";
      if (file.empty())
        throw InputError(name + " must be given for Time/Waveform = table");
      std::error_code error;
      if (std::filesystem::is_directory(file, error))
        throw InputError(name + ": cannot read " + describe_file(file) + ": it is a directory");
      std::ifstream in(file);
      if (!in)
        throw InputError(name + ": cannot read " + describe_file(file));
      std::string  line;
      unsigned int number         = 0;
      bool         header_allowed = true; // the first non-comment line may be a header
      while (std::getline(in, line))
        {
          ++number;
          const auto first = line.find_first_not_of(" \t\r");
          if (first == std::string::npos || line[first] == '#')
            continue;
          while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
            line.pop_back();
          // A header starts with a name; a row that starts like a number and
          // does not parse is a mistake in the data, not a header.
          const bool header = std::string("0123456789+-.").find(line[first]) == std::string::npos;
          if (header && header_allowed)
            {
              header_allowed = false;
              continue;
            }
          header_allowed          = false;
          const std::string where = name + " '" + file + "', line " + std::to_string(number);
          const std::vector<double> row = parse_number_list(line, where);
          if (row.size() != n_rings + 1)
            throw InputError(where + ": expected time and " + std::to_string(n_rings) +
                             " voltage(s), got " + std::to_string(row.size()) + " value(s)");
          if (row[0] < 0. || (!times.empty() && !(row[0] > times.back())))
            throw InputError(where + ": times must be >= 0 and increase strictly, got " +
                             format_number(row[0]));
          std::vector<double> v(row.begin() + 1, row.end());
          for (double &x : v)
            {
              if (x < 0.)
                throw InputError(where + ": voltages must not be negative, got " +
                                 format_number(x));
              if (!(x <= ceiling * 1e-3))
                throw InputError(where + ": " + format_number(x) + " kV is above the voltage "
                                 "ceiling of " + format_number(ceiling * 1e-3) + " kV for this "
                                 "film (as for Electrodes/Voltage path (kV))");
              x *= 1e3;
            }
          times.push_back(row[0]);
          volts.push_back(v);
        }
      if (in.bad())
        throw InputError(name + ": cannot read " + describe_file(file));
      if (times.empty())
        throw InputError(name + " " + describe_file(file) + " has no rows of numbers");
    }
  } // namespace

  void validate_time(const Parameters &p)
  {
    // A million steps (as for the quasi-static path) is three times the
    // longest documented scene (doc/time.md, 0.01 Hz at 1.25 ms) and keeps the
    // results held in memory below a gigabyte; more is most likely a mistyped
    // duration.
    constexpr double max_time_steps = 1e6;
    const auto &m = p.viscous_material;
    const auto &t = p.time;
    if (m.model == MaterialModel::viscoelastic)
      {
        // Bounds the solver can meet: network B more than 1e4 times as stiff
        // as network A leaves no equilibrium under the dead load (measured at
        // 1e5), and relaxation times outside 1e-12..1e12 s are below the
        // smallest time step or beyond any run's duration.
        const double mu_a = p.material.shear_modulus_kPa;
        const double mu_b = m.network_b_shear_modulus_kPa;
        if (!(mu_b >= 1e-6 * mu_a && mu_b <= 1e4 * mu_a))
          throw InputError("Material/Network B shear modulus (kPa) must be between 1e-6 and 1e4 "
                           "times Material/Shear modulus (kPa) (" + format_number(1e-6 * mu_a) +
                           " to " + format_number(1e4 * mu_a) + " kPa), got " +
                           format_number(mu_b));
        if (!(m.network_b_jlim >= 1e-12 && m.network_b_jlim <= 1e12))
          throw InputError("Material/Network B Jlim must be between 1e-12 and 1e12, got " +
                           format_number(m.network_b_jlim));
        if (!(m.relaxation_time_s >= 1e-12 && m.relaxation_time_s <= 1e12))
          throw InputError("Material/Relaxation time (s) must be between 1e-12 and 1e12 s, got " +
                           format_number(m.relaxation_time_s));
        if (!t.enabled)
          throw InputError("Material/Model = viscoelastic needs Time/Enabled = true (a "
                           "quasi-static run has no time for the dashpots; its long-time limit "
                           "is Material/Model = elastic)");
        if (p.wrinkling.model == WrinklingModel::relaxed)
          throw InputError("Wrinkling/Model = relaxed needs Material/Model = elastic (the "
                           "tension-field relaxation wraps an elastic law)");
      }
    if (!t.enabled)
      return;
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
    // How long the run is, to bound its number of steps.
    double      duration = 0.;
    std::string duration_entries;
    switch (t.waveform)
      {
        case WaveformKind::ramp_hold:
          require_positive(t.ramp_time_s, "Time/Ramp time (s)");
          if (!(t.hold_time_s >= 0.))
            throw InputError("Time/Hold time (s) must be zero or positive, got " +
                             format_number(t.hold_time_s));
          duration         = t.ramp_time_s + t.hold_time_s;
          duration_entries = "Time/Ramp time (s) + Time/Hold time (s)";
          break;
        case WaveformKind::square:
          require_positive(t.frequency_Hz, "Time/Frequency (Hz)");
          if (!(t.rise_time_s >= t.min_time_step_s))
            throw InputError("Time/Rise time (s) must be at least Time/Min time step (s) = " +
                             format_number(t.min_time_step_s) + " s (an edge needs a step), got " +
                             format_number(t.rise_time_s));
          if (!(t.rise_time_s < 0.5 / t.frequency_Hz))
            throw InputError("Time/Rise time (s) must be shorter than half a period, 1 / (2 "
                             "Frequency) = " + format_number(0.5 / t.frequency_Hz) + " s, got " +
                             format_number(t.rise_time_s));
          duration         = t.cycles / t.frequency_Hz;
          duration_entries = "Time/Cycles / Time/Frequency (Hz)";
          break;
        case WaveformKind::sine:
          require_positive(t.frequency_Hz, "Time/Frequency (Hz)");
          duration         = t.cycles / t.frequency_Hz;
          duration_entries = "Time/Cycles / Time/Frequency (Hz)";
          break;
        case WaveformKind::table:
          {
            std::vector<double>              times;
            std::vector<std::vector<double>> volts;
            read_table(t.table_file, p.scene(), times, volts);
            duration         = times.back();
            duration_entries = "the last time in Time/Table file";
          }
          break;
      }
    const double rest = rest_time(t);
    if (std::isfinite(rest) && rest > 1e12)
      throw InputError("Time/Rest time before voltage (s) must be 'relaxed' or at most 1e12 s, "
                       "got " + format_number(rest));
    if (std::isfinite(rest))
      {
        duration += rest;
        duration_entries += " + Time/Rest time before voltage (s)";
      }
    if (!(duration / t.time_step_s <= max_time_steps))
      throw InputError("the run would take " + format_number(duration / t.time_step_s) +
                       " time steps, more than " + format_number(max_time_steps) +
                       ": its duration " + format_number(duration) + " s (" + duration_entries +
                       ") over Time/Time step (s) = " + format_number(t.time_step_s) +
                       "; shorten the run or raise the time step");
  }

  std::shared_ptr<const MembraneLaw> material_law(const Parameters &p, const Scene &scene)
  {
    const auto &m = p.viscous_material;
    LawSettings settings;
    settings.model     = to_string(m.model);
    settings.material  = scene.material;
    settings.constants = {{"Network B shear modulus (kPa)", m.network_b_shear_modulus_kPa},
                          {"Network B Jlim", m.network_b_jlim},
                          {"Relaxation time (s)", m.relaxation_time_s}};
    return make_membrane_law(settings);
  }

  TimeSettings time_settings(const Parameters &p, const Scene &scene)
  {
    const auto  &t = p.time;
    TimeSettings s;
    s.max_step     = t.time_step_s;
    s.min_step     = t.min_time_step_s;
    s.max_cutbacks = p.solver.max_cutbacks;
    s.scheme       = t.scheme;
    s.inertia      = t.inertia;
    s.rest_time    = rest_time(t);
    s.fields_interval = t.fields_interval_s;
    if (t.inertia && t.water_inertia && p.reservoir.water_load)
      {
        s.water_density = p.reservoir.water_density;
        s.water_volume  = p.reservoir.water_volume_ml * 1e-6;
        s.tube_area     = tube_area(p);
      }
    const std::vector<double> peak = scene.path.voltages(scene.path.n_segments());
    switch (t.waveform)
      {
        case WaveformKind::ramp_hold:
          s.waveform = Waveform::ramp_hold(peak, t.ramp_time_s, t.hold_time_s);
          break;
        case WaveformKind::square:
          s.waveform = Waveform::square(peak, t.frequency_Hz, t.cycles, t.rise_time_s);
          break;
        case WaveformKind::sine:
          s.waveform = Waveform::sine(peak, t.frequency_Hz, t.cycles);
          break;
        case WaveformKind::table:
          {
            std::vector<double>              times;
            std::vector<std::vector<double>> volts;
            read_table(t.table_file, scene, times, volts);
            s.waveform = Waveform::table(times, volts);
          }
          break;
      }
    return s;
  }
} // namespace cdea
