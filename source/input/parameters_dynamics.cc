#include <deal.II/base/parameter_handler.h>

#include <cdea/input/parameters_dynamics.h>

namespace cdea
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Anything;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Selection;

  namespace parameters
  {
    void Response::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Response");
      prm.declare_entry("Lowest frequency (Hz)", "0.01", Double(),
                        "cdea response: the transfer functions about the equilibrium at the end "
                        "of the voltage path, from this frequency to Highest frequency at "
                        "Frequencies frequencies evenly spaced in log(f).");
      prm.declare_entry("Highest frequency (Hz)", "100", Double(),
                        "The highest frequency of the transfer functions.");
      prm.declare_entry("Frequencies", "200", Integer(2, 100000),
                        "How many frequencies the transfer functions are evaluated at.");
      prm.declare_entry("Modes", "3", Integer(0, 1000),
                        "Natural frequencies and mode shapes reported (at most the rank of the "
                        "mass: one for the disk alone, two with the water column).");
      prm.declare_entry("Membrane density (kg/m^3)", "0", Double(),
                        "The membrane's consistent mass in the small-signal response (VHB 4910: "
                        "about 960). 0: massless, as the time runs take it (its 0.76 g are 0.3 % "
                        "of the disk's mass, and its own modes lie above 100 Hz).");
      prm.leave_subsection();
    }

    void Response::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Response");
      lowest_frequency_Hz  = prm.get_double("Lowest frequency (Hz)");
      highest_frequency_Hz = prm.get_double("Highest frequency (Hz)");
      frequencies          = prm.get_integer("Frequencies");
      modes                = prm.get_integer("Modes");
      membrane_density     = prm.get_double("Membrane density (kg/m^3)");
      prm.leave_subsection();
    }

    void SteadyState::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Steady state");
      prm.declare_entry("Tolerance", "1e-6", Double(),
                        "cdea frequency-sweep: the periodic steady state is converged when one "
                        "period moves the disk's position and velocity (and the water column's "
                        "volume) by less than this times their half swing over the period, and "
                        "the internal variables by less than this times the largest half swing "
                        "of any of them.");
      prm.declare_entry("Max Newton iterations", "12", Integer(1, 1000),
                        "Newton iterations on the periodicity condition.");
      prm.declare_entry("Krylov dimension", "40", Integer(1, 1000),
                        "GMRES iterations (period maps) per Newton iteration at most.");
      prm.declare_entry("Start periods", "2", Integer(0, 1000),
                        "Periods of plain time integration from the time run's start before "
                        "Newton.");
      prm.declare_entry("Low voltage (fraction of peak)", "0", Double(),
                        "The sine and the square wave of the steady states swing between this "
                        "fraction of the voltage path's last waypoint and that waypoint (0: from "
                        "0 V, as Time/Waveform drives a time run; close to 1: a small swing "
                        "about a bias).");
      prm.leave_subsection();
    }

    void SteadyState::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Steady state");
      tolerance             = prm.get_double("Tolerance");
      max_newton_iterations = prm.get_integer("Max Newton iterations");
      krylov_dimension      = prm.get_integer("Krylov dimension");
      start_periods         = prm.get_integer("Start periods");
      low_fraction          = prm.get_double("Low voltage (fraction of peak)");
      prm.leave_subsection();
    }

    void FrequencySweep::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Frequency sweep");
      prm.declare_entry("Lowest frequency (Hz)", "0.01", Double(),
                        "cdea frequency-sweep: the periodic steady state of Time/Waveform at "
                        "Frequencies frequencies from this one to Highest frequency (unless "
                        "Frequencies (Hz) lists them).");
      prm.declare_entry("Highest frequency (Hz)", "20", Double(),
                        "The highest frequency of the sweep.");
      prm.declare_entry("Frequencies", "17", Integer(),
                        "How many frequencies between the lowest and the highest.");
      prm.declare_entry("Spacing", "log", Selection("log|linear"),
                        "Frequencies evenly spaced in log(f) or in f.");
      prm.declare_entry("Frequencies (Hz)", "", Anything(),
                        "A comma-separated list of frequencies; if given, it replaces the range.");
      prm.declare_entry("Usable stroke factor", "1.5", Double(),
                        "A frequency is usable if its swing keeps the film taut and its stroke "
                        "amplitude lies between the quasi-static one divided by this factor "
                        "and the quasi-static one times it; the usable band is the longest run "
                        "of consecutive usable frequencies.");
      prm.declare_entry("Confirm long sweep", "false", Bool(),
                        "A sweep of more than 1000 frequencies (each a periodic steady state "
                        "of seconds to minutes) is refused unless this is true.");
      prm.leave_subsection();
    }

    void FrequencySweep::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Frequency sweep");
      lowest_frequency_Hz  = prm.get_double("Lowest frequency (Hz)");
      highest_frequency_Hz = prm.get_double("Highest frequency (Hz)");
      frequencies          = prm.get_integer("Frequencies");
      log_spacing          = prm.get("Spacing") == "log";
      frequency_list       = prm.get("Frequencies (Hz)");
      usable_factor        = prm.get_double("Usable stroke factor");
      confirm_long         = prm.get_bool("Confirm long sweep");
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace cdea
