// The subsections of the design studies: Sweep (position 90), Optimization
// (110) and Calibration (120), their entries bound to the structs of
// input/parameters.h.

#include <cdea/base/text.h>
#include <cdea/input/parameters.h>

namespace cdea
{
  namespace
  {
    const Choices<DesignObjective> objective_choices{{"stroke", DesignObjective::stroke},
                                                     {"volume change",
                                                      DesignObjective::volume_change}};

    const Choices<DesignAlgorithm> algorithm_choices{{"SLSQP", DesignAlgorithm::slsqp},
                                                     {"MMA", DesignAlgorithm::mma}};
  } // namespace

  std::string to_string(const DesignObjective choice) { return objective_choices.name(choice); }

  std::string to_string(const DesignAlgorithm choice) { return algorithm_choices.name(choice); }

  namespace parameters
  {
    void Sweep::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Sweep");
      prm.add("Ring edge values (r/a)", "1.2, 1.25, 1.3, ..., 2.6", ring_edge_values_text,
              "Inner-ring outer edges r_v/a of the two-ring layouts 1, r_v/a, b/a "
              "swept by `cdea sweep`, separated by ','. '...' continues the "
              "arithmetic sequence of the two values before it up to the value after "
              "it. Every value must lie strictly between 1 and b/a.");
      prm.add_parsed(
        "Inner voltage (kV)", "5",
        [this](const std::string &inner) {
          const auto v = parse_number_list(inner, "Sweep/Inner voltage (kV)");
          if (v.size() != 1 || v[0] < 0.)
            throw InputError("Sweep/Inner voltage (kV) must be one voltage >= 0, got '" + inner +
                             "'");
          inner_voltage_kV = v[0];
        },
        "Voltage of the inner ring; both rings are first raised to it together.");
      prm.add("Outer voltage range (kV)", "5, 8, 0.05", outer_voltage_range_text,
              "from, to, step of the outer ring's voltage in the map.");
      prm.add("Confirm long sweep", "false", confirm_long,
              "A map of more than 1e6 points (edge values x outer voltages) is "
              "refused unless this is true.");
      prm.leave_subsection();
    }

    void Optimization::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Optimization");
      prm.add("Rings", "2", rings,
              "Number N of electrode rings of the layout `cdea optimize` designs.", between(1, 64));
      prm.add("Fixed voltages (kV)", "free", fixed_voltages_text,
              "One entry per ring, separated by ',': a voltage fixes that ring, "
              "'free' lets the optimizer choose it. A single 'free' frees all.");
      prm.add("Fixed ring edges (r/a)", "free", fixed_edges_text,
              "N-1 entries for the interior ring edges (r/a on the pre-stretched "
              "flat film, increasing), each a number or 'free'; a single 'free' "
              "frees all.");
      prm.add("Edge bounds (r/a)", "1.2, 2.6", edge_bounds_text,
              "lower, upper bound of every free ring edge, inside [1, b/a].");
      prm.add("Voltage bounds (kV)", "0, 8", voltage_bounds_text,
              "lower, upper bound of every free ring voltage.");
      prm.add("Minimum hoop stress (kPa)", "0", min_hoop_stress_text,
              "Constraint s2 >= this at every quadrature point and at the inner "
              "edge of every ring (that ring's side) of the final state.");
      prm.add("Maximum field (MV/m)", "inf", max_field_text,
              "Constraint E = Phi lambda1 lambda2 / H <= this at the same points "
              "('inf': no field limit).");
      prm.add("Minimum ring width (mm)", "1.4", min_ring_width_text,
              "Every ring at least this wide on the pre-stretched flat film.");
      prm.add("Objective", "stroke", objective, objective_choices,
              "What is maximised: the stroke (displacement against zero voltage "
              "under the same load) or the change of the enclosed volume (pump).");
      prm.add("Starts", "8", starts,
              "Starting layouts of the multistart (distributed over the MPI ranks "
              "under mpirun).",
              between(1, 100000));
      prm.add("Algorithm", "SLSQP", algorithm, algorithm_choices,
              "NLopt's gradient-based method, with the exact gradients.");
      prm.add("Max evaluations", "300", max_evaluations,
              "Evaluations (equilibria with their sensitivities) per start before "
              "the optimizer stops unconverged.",
              between(1, 1000000));
      prm.add("Tolerance", "1e-9", tolerance,
              "Relative change of the design variables (scaled to their bounds) "
              "and of the objective at which the optimizer has converged.",
              at_least(0.));
      prm.leave_subsection();
    }

    void Calibration::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Calibration");
      prm.add("Free parameters", "shear modulus, Jlim", free_parameters_text,
              "What `cdea fit` adjusts to the data, separated by ',': any of shear "
              "modulus, Jlim, permittivity, mass, pre-stretch, and any constant of "
              "the film's law by its Material entry, with or without the unit "
              "(Mooney-Rivlin C2, Ogden mu 2, ...); a viscoelastic film's branches "
              "as branch K shear modulus and branch K relaxation time (K from 1). "
              "An unknown name is refused with the list the prm's law accepts. The "
              "others keep their values from the file; an actuator, creep or DMA fit "
              "starts from them, a material-test fit from guesses made from the data.");
      prm.add("Max iterations", "100", max_iterations,
              "Iterations of the least-squares solver before it stops unconverged.",
              between(1, 100000));
      prm.add("Tolerance", "1e-10", tolerance,
              "Relative change of the cost, of the parameters and of the gradient "
              "at which the least-squares solver has converged.",
              at_least(0.));
      prm.add("Candidate models", "", candidate_models_text,
              "Material tests only: models `cdea fit` fits and compares (model "
              "selection, doc/materials.md), separated by ',', each a law of "
              "Material/Model without internal variables and a number of viscous "
              "branches, e.g. 'elastic 0, elastic 1, elastic 2, neo-hooke 0'; "
              "branches (1 to 20) stand beside network A's Gent law (elastic) "
              "only. Each model's free constants are its law's own (shear "
              "modulus, Jlim where it has one, the law's constants) and every "
              "branch's modulus and relaxation time; Free parameters is not used. "
              "Empty: one fit of Free parameters.");
      prm.leave_subsection();
    }

  } // namespace parameters

  CDEA_REGISTER_MEMBER_SUBSECTION(sweep, 90)
  CDEA_REGISTER_MEMBER_SUBSECTION(optimization, 110)
  CDEA_REGISTER_MEMBER_SUBSECTION(calibration, 120)
} // namespace cdea
