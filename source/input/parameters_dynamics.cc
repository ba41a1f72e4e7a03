#include <deal.II/base/parameter_handler.h>

#include <cdea/input/parameters_dynamics.h>

namespace cdea
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;

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
  } // namespace parameters
} // namespace cdea
