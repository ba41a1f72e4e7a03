// The subsections of the dynamics: Response (position 170), Steady state
// (180) and Frequency sweep (190), their entries bound to the structs of
// input/parameters.h.

#include <cdea/input/parameters.h>

namespace cdea
{
  namespace
  {
    const Choices<bool> spacing_choices{{"log", true}, {"linear", false}};
  } // namespace

  namespace parameters
  {
    void Response::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Response");
      prm.add("Lowest frequency (Hz)", "0.01", lowest_frequency_Hz,
              "cdea response: the transfer functions about the equilibrium at the end "
              "of the voltage path, from this frequency to Highest frequency at "
              "Frequencies frequencies evenly spaced in log(f).");
      prm.add("Highest frequency (Hz)", "100", highest_frequency_Hz,
              "The highest frequency of the transfer functions.");
      prm.add("Frequencies", "200", frequencies,
              "How many frequencies the transfer functions are evaluated at.", between(2, 100000));
      prm.add("Modes", "3", modes,
              "Natural frequencies and mode shapes reported (at most the rank of the "
              "mass: one for the disk alone, two with the water column).",
              between(0, 1000));
      prm.add("Membrane density (kg/m^3)", "0", membrane_density,
              "The membrane's consistent mass in the small-signal response (VHB 4910: "
              "about 960). 0: massless, as the time runs take it (its 0.76 g are 0.3 % "
              "of the disk's mass, and its own modes lie above 100 Hz).");
      prm.leave_subsection();
    }

    void SteadyState::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Steady state");
      prm.add("Tolerance", "1e-6", tolerance,
              "cdea frequency-sweep: the periodic steady state is converged when one "
              "period moves the disk's position and velocity (and the water column's "
              "volume) by less than this times their half swing over the period, and "
              "the internal variables by less than this times the largest half swing "
              "of any of them.");
      prm.add("Max Newton iterations", "12", max_newton_iterations,
              "Newton iterations on the periodicity condition.", between(1, 1000));
      prm.add("Krylov dimension", "40", krylov_dimension,
              "GMRES iterations (period maps) per Newton iteration at most.", between(1, 1000));
      prm.add("Start periods", "2", start_periods,
              "Periods of plain time integration from the time run's start before "
              "Newton.",
              between(0, 1000));
      prm.add("Low voltage (fraction of peak)", "0", low_fraction,
              "The sine and the square wave of the steady states swing between this "
              "fraction of the voltage path's last waypoint and that waypoint (0: from "
              "0 V, as Time/Waveform drives a time run; close to 1: a small swing "
              "about a bias).");
      prm.leave_subsection();
    }

    void FrequencySweep::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Frequency sweep");
      prm.add("Lowest frequency (Hz)", "0.01", lowest_frequency_Hz,
              "cdea frequency-sweep: the periodic steady state of Time/Waveform at "
              "Frequencies frequencies from this one to Highest frequency (unless "
              "Frequencies (Hz) lists them).");
      prm.add("Highest frequency (Hz)", "20", highest_frequency_Hz,
              "The highest frequency of the sweep.");
      prm.add("Frequencies", "17", frequencies,
              "How many frequencies between the lowest and the highest.");
      prm.add("Spacing", "log", log_spacing, spacing_choices,
              "Frequencies evenly spaced in log(f) or in f.");
      prm.add("Frequencies (Hz)", "", frequency_list,
              "A comma-separated list of frequencies; if given, it replaces the range.");
      prm.add("Usable stroke factor", "1.5", usable_factor,
              "A frequency is usable if its swing keeps the film taut and its stroke "
              "amplitude lies between the quasi-static one divided by this factor "
              "and the quasi-static one times it; the usable band is the longest run "
              "of consecutive usable frequencies.");
      prm.add("Confirm long sweep", "false", confirm_long,
              "A sweep of more than 1000 frequencies (each a periodic steady state "
              "of seconds to minutes) is refused unless this is true.");
      prm.leave_subsection();
    }

  } // namespace parameters

  CDEA_REGISTER_MEMBER_SUBSECTION(response, 170)
  CDEA_REGISTER_MEMBER_SUBSECTION(steady_state, 180)
  CDEA_REGISTER_MEMBER_SUBSECTION(frequency_sweep, 190)
} // namespace cdea
