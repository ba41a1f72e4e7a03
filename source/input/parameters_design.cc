#include <deal.II/base/parameter_handler.h>

#include <cdea/base/text.h>
#include <cdea/input/parameters_design.h>

namespace cdea
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  std::string to_string(const DesignObjective choice)
  {
    return choice == DesignObjective::volume_change ? "volume change" : "stroke";
  }

  std::string to_string(const DesignAlgorithm choice)
  {
    return choice == DesignAlgorithm::mma ? "MMA" : "SLSQP";
  }

  namespace parameters
  {
    void Sweep::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Sweep");
      prm.declare_entry("Ring edge values (r/a)", "1.2, 1.25, 1.3, ..., 2.6", Anything(),
                        "Inner-ring outer edges r_v/a of the two-ring layouts 1, r_v/a, b/a "
                        "swept by `cdea sweep`, separated by ','. '...' continues the "
                        "arithmetic sequence of the two values before it up to the value after "
                        "it. Every value must lie strictly between 1 and b/a.");
      prm.declare_entry("Inner voltage (kV)", "5", Anything(),
                        "Voltage of the inner ring; both rings are first raised to it together.");
      prm.declare_entry("Outer voltage range (kV)", "5, 8, 0.05", Anything(),
                        "from, to, step of the outer ring's voltage in the map.");
      prm.declare_entry("Confirm long sweep", "false", Bool(),
                        "A map of more than 1e6 points (edge values x outer voltages) is "
                        "refused unless this is true.");
      prm.leave_subsection();
    }

    void Sweep::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Sweep");
      ring_edge_values_text    = prm.get("Ring edge values (r/a)");
      const std::string inner  = prm.get("Inner voltage (kV)");
      outer_voltage_range_text = prm.get("Outer voltage range (kV)");
      confirm_long             = prm.get_bool("Confirm long sweep");
      prm.leave_subsection();
      const auto v = parse_number_list(inner, "Sweep/Inner voltage (kV)");
      if (v.size() != 1 || v[0] < 0.)
        throw InputError("Sweep/Inner voltage (kV) must be one voltage >= 0, got '" + inner + "'");
      inner_voltage_kV = v[0];
    }

    void Optimization::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Optimization");
      prm.declare_entry("Rings", "2", Integer(1, 64),
                        "Number N of electrode rings of the layout `cdea optimize` designs.");
      prm.declare_entry("Fixed voltages (kV)", "free", Anything(),
                        "One entry per ring, separated by ',': a voltage fixes that ring, "
                        "'free' lets the optimizer choose it. A single 'free' frees all.");
      prm.declare_entry("Fixed ring edges (r/a)", "free", Anything(),
                        "N-1 entries for the interior ring edges (r/a on the pre-stretched "
                        "flat film, increasing), each a number or 'free'; a single 'free' "
                        "frees all.");
      prm.declare_entry("Edge bounds (r/a)", "1.2, 2.6", Anything(),
                        "lower, upper bound of every free ring edge, inside [1, b/a].");
      prm.declare_entry("Voltage bounds (kV)", "0, 8", Anything(),
                        "lower, upper bound of every free ring voltage.");
      prm.declare_entry("Minimum hoop stress (kPa)", "0", Anything(),
                        "Constraint s2 >= this at every quadrature point and at the inner "
                        "edge of every ring (that ring's side) of the final state.");
      prm.declare_entry("Maximum field (MV/m)", "inf", Anything(),
                        "Constraint E = Phi lambda1 lambda2 / H <= this at the same points "
                        "('inf': no field limit).");
      prm.declare_entry("Minimum ring width (mm)", "1.4", Anything(),
                        "Every ring at least this wide on the pre-stretched flat film.");
      prm.declare_entry("Objective", "stroke", Selection("stroke|volume change"),
                        "What is maximised: the stroke (displacement against zero voltage "
                        "under the same load) or the change of the enclosed volume (pump).");
      prm.declare_entry("Starts", "8", Integer(1, 100000),
                        "Starting layouts of the multistart (distributed over the MPI ranks "
                        "under mpirun).");
      prm.declare_entry("Algorithm", "SLSQP", Selection("SLSQP|MMA"),
                        "NLopt's gradient-based method, with the exact gradients.");
      prm.declare_entry("Max evaluations", "300", Integer(1, 1000000),
                        "Evaluations (equilibria with their sensitivities) per start before "
                        "the optimizer stops unconverged.");
      prm.declare_entry("Tolerance", "1e-9", Double(0.),
                        "Relative change of the design variables (scaled to their bounds) "
                        "and of the objective at which the optimizer has converged.");
      prm.leave_subsection();
    }

    void Optimization::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Optimization");
      rings                = prm.get_integer("Rings");
      fixed_voltages_text  = prm.get("Fixed voltages (kV)");
      fixed_edges_text     = prm.get("Fixed ring edges (r/a)");
      edge_bounds_text     = prm.get("Edge bounds (r/a)");
      voltage_bounds_text  = prm.get("Voltage bounds (kV)");
      min_hoop_stress_text = prm.get("Minimum hoop stress (kPa)");
      max_field_text       = prm.get("Maximum field (MV/m)");
      min_ring_width_text  = prm.get("Minimum ring width (mm)");
      objective = prm.get("Objective") == "volume change" ? DesignObjective::volume_change :
                                                             DesignObjective::stroke;
      starts          = prm.get_integer("Starts");
      algorithm       = prm.get("Algorithm") == "MMA" ? DesignAlgorithm::mma :
                                                        DesignAlgorithm::slsqp;
      max_evaluations = prm.get_integer("Max evaluations");
      tolerance       = prm.get_double("Tolerance");
      prm.leave_subsection();
    }

    void Calibration::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Calibration");
      prm.declare_entry("Free parameters", "shear modulus, Jlim", Anything(),
                        "What `cdea fit` adjusts to the data, separated by ',': any of shear "
                        "modulus, Jlim, permittivity, mass, pre-stretch. The others keep "
                        "their values from the file, which are also the starting values.");
      prm.declare_entry("Max iterations", "100", Integer(1, 100000),
                        "Iterations of the least-squares solver before it stops unconverged.");
      prm.declare_entry("Tolerance", "1e-10", Double(0.),
                        "Relative change of the cost, of the parameters and of the gradient "
                        "at which the least-squares solver has converged.");
      prm.leave_subsection();
    }

    void Calibration::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Calibration");
      free_parameters_text = prm.get("Free parameters");
      max_iterations       = prm.get_integer("Max iterations");
      tolerance            = prm.get_double("Tolerance");
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace cdea
