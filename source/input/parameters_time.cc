// Subsection Time (position 150): its entries bound to parameters::Time.

#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/input/parameters.h>

#include <limits>

namespace cdea
{
  namespace
  {
    const Choices<WaveformKind> waveform_choices{{"ramp-hold", WaveformKind::ramp_hold},
                                                 {"square", WaveformKind::square},
                                                 {"sine", WaveformKind::sine},
                                                 {"table", WaveformKind::table}};

    const Choices<TimeMethod> scheme_choices{{"ESDIRK3", TimeMethod::esdirk3},
                                             {"ESDIRK4", TimeMethod::esdirk4},
                                             {"backward Euler", TimeMethod::backward_euler},
                                             {"trapezoidal", TimeMethod::trapezoidal}};

    const Choices<TimeStepControl> step_control_choices{{"error", TimeStepControl::error},
                                                        {"fixed", TimeStepControl::fixed}};
  } // namespace

  namespace parameters
  {
    void Time::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Time");
      prm.add("Enabled", "false", enabled,
              "true: after the quasi-static pre-stretch and weight, integrate in time "
              "through the voltage waveform (cdea run only); false: the quasi-static "
              "voltage path.");
      prm.add("Waveform", "ramp-hold", waveform, waveform_choices,
              "ramp-hold: from 0 to the last waypoint's voltages in Ramp time, then held "
              "for Hold time. square, sine: between 0 and the last waypoint's voltages "
              "at Frequency for Cycles periods. table: the Table file.");
      prm.add("Ramp time (s)", "1", ramp_time_s, "ramp-hold: duration of the ramp.");
      prm.add("Hold time (s)", "20", hold_time_s, "ramp-hold: how long the peak is held.");
      prm.add("Frequency (Hz)", "0.5", frequency_Hz, "square, sine: drive frequency.");
      prm.add("Cycles", "10", cycles, "square, sine: periods driven.", between(1, 10000000));
      prm.add("Rise time (s)", "0.01", rise_time_s,
              "square: each edge is a linear ramp of this duration (below half a period).");
      prm.add("Table file", "", table_file,
              "table: a CSV file (relative to the working directory) of rows 'time_s, "
              "one voltage per ring (kV)' with increasing times from 0; '#' lines and a "
              "first line that starts with a name (a header) are skipped. The voltages "
              "are linear between rows and start from 0 V at t = 0 when the first row "
              "is later.");
      prm.add("Time step (s)", "0.01", time_step_s,
              "ESDIRK schemes with Step control = error (the default): the cap on the "
              "steps the error estimate sizes (for a sine at most 1/16 of its period). "
              "backward Euler, trapezoidal and Step control = fixed: the step itself. "
              "Steps land on every ramp end, square edge and table row and are halved "
              "where Newton needs it.");
      prm.add("Min time step (s)", "1e-8", min_time_step_s,
              "A step cut below this ends the run (exit code 2).");
      prm.add("Scheme", "ESDIRK4", scheme, scheme_choices,
              "ESDIRK4 (the default), ESDIRK3: L-stable diagonally implicit Runge-Kutta "
              "methods of order 4 (5 implicit stages) and 3 (3 stages) for the film's "
              "internal variables, the disk's and the water's inertia alike, with an "
              "error estimate (Step control). backward Euler, trapezoidal: the "
              "fixed-step schemes for the dashpots (first and second order), the inertia "
              "by Newmark's average acceleration; they take steps of Time step (s) "
              "(Step control does not apply).");
      prm.add("Step control", "error", step_control, step_control_choices,
              "ESDIRK schemes: error: each step's local error estimate against the "
              "tolerances sizes the next step (up to Time step (s)); fixed: steps of "
              "Time step (s).");
      prm.add("Relative tolerance", "1e-6", relative_tolerance,
              "Error control: the local error of the disk's position, its velocity "
              "(over its natural angular frequency), the water level and the film's "
              "internal variables, relative to their values.");
      prm.add("Absolute tolerance (mm)", "1e-6", absolute_tolerance_mm,
              "Error control: the absolute part for the disk's position and the "
              "water level in the tube.");
      prm.add("Internal variable tolerance", "1e-9", internal_tolerance,
              "Error control: the absolute part for the film's internal variables "
              "(log viscous stretches).");
      prm.add("Inertia", "true", inertia,
              "The disk's mass (Loading/Mass) in m z'' on the disk (Newmark); the "
              "membrane's own mass is neglected. false: quasi-static in time.");
      prm.add("Water inertia", "false", water_inertia,
              "With Inertia and Reservoir/Water load: the water column in the level "
              "tube moves with the enclosed volume (kinetic energy rho h V'^2 / (2 S)).");
      prm.add("Fields interval (s)", "0", fields_interval_s,
              "Every time step is a row of /summary; the fields along the meridian "
              "(/steps) are written at the start, at every ramp end and square edge "
              "(breakpoint) of the waveform, at the end, and every this much time "
              "(0: only there).");
      prm.add("Rest time before voltage (s)", "relaxed", rest_time_text,
              "'relaxed': network B has relaxed under the pre-stretch and the weight "
              "before t = 0. A time in s: the pre-stretched film is relaxed, the weight "
              "is hung quickly and held that long at 0 V before the waveform starts.");
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
          throw InputError(name + " must be 'relaxed' or a time >= 0 in s, got '" + rest_time_text +
                           "'");
        }
      if (!(value >= 0.))
        throw InputError(name + " must be 'relaxed' or a time >= 0 in s, got " +
                         format_number(value));
      return value;
    }
  } // namespace parameters

  std::string to_string(const WaveformKind choice) { return waveform_choices.name(choice); }

  std::string to_string(const TimeMethod choice) { return scheme_choices.name(choice); }

  std::string to_string(const TimeStepControl choice) { return step_control_choices.name(choice); }

  CDEA_REGISTER_MEMBER_SUBSECTION(time, 150)
} // namespace cdea
