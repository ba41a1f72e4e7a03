#include <deal.II/base/parameter_handler.h>

#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/input/parameters_time.h>

#include <limits>

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
                        "ESDIRK schemes with Step control = error (the default): the cap on the "
                        "steps the error estimate sizes (for a sine at most 1/16 of its period). "
                        "backward Euler, trapezoidal and Step control = fixed: the step itself. "
                        "Steps land on every ramp end, square edge and table row and are halved "
                        "where Newton needs it.");
      prm.declare_entry("Min time step (s)", "1e-8", Double(),
                        "A step cut below this ends the run (exit code 2).");
      prm.declare_entry("Scheme", "ESDIRK4",
                        Selection("ESDIRK3|ESDIRK4|backward Euler|trapezoidal"),
                        "ESDIRK4 (the default), ESDIRK3: L-stable diagonally implicit Runge-Kutta "
                        "methods of order 4 (5 implicit stages) and 3 (3 stages) for the film's "
                        "internal variables, the disk's and the water's inertia alike, with an "
                        "error estimate (Step control). backward Euler, trapezoidal: the "
                        "fixed-step schemes for the dashpots (first and second order), the inertia "
                        "by Newmark's average acceleration; they take steps of Time step (s) "
                        "(Step control does not apply).");
      prm.declare_entry("Step control", "error", Selection("error|fixed"),
                        "ESDIRK schemes: error: each step's local error estimate against the "
                        "tolerances sizes the next step (up to Time step (s)); fixed: steps of "
                        "Time step (s).");
      prm.declare_entry("Relative tolerance", "1e-6", Double(),
                        "Error control: the local error of the disk's position, its velocity "
                        "(over its natural angular frequency), the water level and the film's "
                        "internal variables, relative to their values.");
      prm.declare_entry("Absolute tolerance (mm)", "1e-6", Double(),
                        "Error control: the absolute part for the disk's position and the "
                        "water level in the tube.");
      prm.declare_entry("Internal variable tolerance", "1e-9", Double(),
                        "Error control: the absolute part for the film's internal variables "
                        "(log viscous stretches).");
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
      const std::string m   = prm.get("Scheme");
      scheme                = m == "ESDIRK4"        ? TimeMethod::esdirk4 :
                              m == "backward Euler" ? TimeMethod::backward_euler :
                              m == "trapezoidal"    ? TimeMethod::trapezoidal :
                                                      TimeMethod::esdirk3;
      step_control          = prm.get("Step control") == "fixed" ? TimeStepControl::fixed :
                                                                   TimeStepControl::error;
      relative_tolerance    = prm.get_double("Relative tolerance");
      absolute_tolerance_mm = prm.get_double("Absolute tolerance (mm)");
      internal_tolerance    = prm.get_double("Internal variable tolerance");
      inertia               = prm.get_bool("Inertia");
      water_inertia         = prm.get_bool("Water inertia");
      rest_time_text        = prm.get("Rest time before voltage (s)");
      fields_interval_s     = prm.get_double("Fields interval (s)");
      prm.leave_subsection();
    }

    double Time::rest_time() const
    {
      const std::string name = "Time/Rest time before voltage (s)";
      if (rest_time_text == "relaxed")
        return std::numeric_limits<double>::infinity();
      double value = 0.;
      try
        {
          value = parse_number(rest_time_text, name, rest_time_text);
        }
      catch (const InputError &)
        {
          throw InputError(name + " must be 'relaxed' or a time >= 0 in s, got '" +
                           rest_time_text + "'");
        }
      if (!(value >= 0.))
        throw InputError(name + " must be 'relaxed' or a time >= 0 in s, got " +
                         format_number(value));
      return value;
    }
  } // namespace parameters

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

  std::string to_string(const TimeMethod choice)
  {
    switch (choice)
      {
        case TimeMethod::backward_euler:
          return "backward Euler";
        case TimeMethod::trapezoidal:
          return "trapezoidal";
        case TimeMethod::esdirk4:
          return "ESDIRK4";
        case TimeMethod::esdirk3:
          break;
      }
    return "ESDIRK3";
  }

  std::string to_string(const TimeStepControl choice)
  {
    return choice == TimeStepControl::fixed ? "fixed" : "error";
  }
} // namespace cdea
