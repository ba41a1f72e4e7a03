// The subsections of the model: each declares its entries bound to its
// members (parameters.h) and registers itself at its position (10 to 130).

#include <cdea/input/parameters.h>

namespace cdea
{
  namespace
  {
    const Choices<Continuation> continuation_choices{{"load stepping", Continuation::load_stepping},
                                                     {"arc length", Continuation::arc_length}};
    const Choices<LinearSolver> linear_solver_choices{{"banded LU", LinearSolver::banded_lu},
                                                      {"Trilinos KLU", LinearSolver::trilinos_klu}};
    const Choices<StabilityEigenvalue> eigenvalue_choices{
      {"every step", StabilityEigenvalue::every_step},
      {"near folds", StabilityEigenvalue::near_folds}};
    const Choices<WrinklingModel> wrinkling_choices{{"check", WrinklingModel::check},
                                                    {"relaxed", WrinklingModel::relaxed}};
    const Choices<StepRows> step_rows_choices{{"every", StepRows::every},
                                              {"progress", StepRows::progress},
                                              {"none", StepRows::none}};
  } // namespace

  std::string to_string(const Continuation choice)
  {
    return continuation_choices.name(choice);
  }

  std::string to_string(const WrinklingModel choice)
  {
    return wrinkling_choices.name(choice);
  }

  namespace parameters
  {
    void Geometry::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Geometry");
      prm.add("Disk radius (mm)", "14", disk_radius_mm,
              "Radius a of the rigid disk, measured on the pre-stretched flat film.");
      prm.add("Frame radius (mm)", "42", frame_radius_mm,
              "Inner radius b of the rigid frame, measured on the pre-stretched flat film.");
      prm.add("Film thickness (mm)", "1", film_thickness_mm,
              "Thickness H of the undeformed (unstretched) film.");
      prm.add("Prestretch", "2.5", prestretch,
              "Equi-biaxial pre-stretch lam_pre of the film before the disk is attached.");
      prm.leave_subsection();
    }

    void Material::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Material");
      prm.add("Shear modulus (kPa)", "25.1", shear_modulus_kPa,
              "Small-strain shear modulus mu of the Gent law.");
      prm.add("Jlim", "270", jlim,
              "Gent limit: the law stiffens without bound as I1 - 3 approaches Jlim.");
      prm.add("Permittivity (F/m)", "3.98e-11", permittivity,
              "Permittivity eps of the ideal dielectric.");
      prm.leave_subsection();
    }

    void Loading::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Loading");
      prm.add("Mass (g)", "280", mass_g,
              "Dead weight hanging from the disk; the load F = m g pulls the disk "
              "out of the frame plane.");
      prm.add("Gravity (m/s^2)", "9.81", gravity, "Gravitational acceleration g.");
      prm.leave_subsection();
    }

    void Electrodes::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Electrodes");
      prm.add("Ring edges (r/a)", "1, 3", ring_edges_text,
              "n+1 increasing edges of n concentric electrode rings, as radii on the "
              "pre-stretched flat film over the disk radius: the first is 1 (disk "
              "edge), the last b/a (frame).");
      prm.add("Voltage path (kV)", "5", voltage_path_text,
              "Waypoints separated by ';', each one voltage per ring separated by ','. "
              "All rings start at 0 kV and move linearly from one waypoint to the next.");
      prm.leave_subsection();
    }

    void Discretization::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Discretization");
      prm.add("Polynomial degree", "4", polynomial_degree,
              "Degree p of the FE_Q elements for r(R) and z(R).", between(1, 8));
      prm.add("Elements per ring", "4", elements_per_ring,
              "Elements in every electrode ring before global refinement; element "
              "boundaries always lie on the ring edges.",
              between(1, 100000));
      prm.add("Grading", "4", grading,
              "Ratio of the outermost to the innermost element length in each ring: "
              "elements are geometrically smaller towards the ring's inner edge, where "
              "the meridian stretch varies fastest. 1 is uniform.",
              between(1., 1000.));
      prm.add("Global refinements", "0", refinements,
              "Times every element is bisected (h-refinement studies).", between(0, 20));
      prm.add("Samples per element", "16", samples_per_element,
              "Equally spaced points per element at which fields are written (enough for "
              "smooth profiles in plots and ParaView).",
              between(1, 1000));
      prm.add("Error estimate", "true", error_estimate,
              "Estimate the numerical error of a quasi-static run's final displacement, "
              "stroke, volume change, smallest hoop stress and onset voltages (degree p + 1 "
              "on the same mesh from the converged states, Newton's remaining residual, the "
              "onset search's bracket): the *_error attributes of /summary and the printed "
              "final state (doc/accuracy.md). It does not change the run's results.");
      prm.leave_subsection();
    }

    void Solver::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Solver");
      prm.add("Residual tolerance", "1e-10", residual_tolerance,
              "Newton has converged when the largest residual entry over the force "
              "scale max(F, 2 pi H mu a) is below this and the update criterion holds.",
              at_least(0.));
      prm.add("Update tolerance", "1e-10", update_tolerance,
              "Newton has converged when the largest update over the disk radius a "
              "is below this and the residual criterion holds.",
              at_least(0.));
      prm.add("Max Newton iterations", "25", max_newton_iterations,
              "Newton iterations before a load step counts as failed and is cut back.",
              between(1, 1000));
      prm.add("Prestretch steps", "1", prestretch_steps,
              "Steps from the unstretched film to lam_pre (the state is homogeneous).",
              between(1, 10000));
      prm.add("Load increment", "0.25", load_increment,
              "Largest increment of the dead load, as a fraction of m g.", between(1e-8, 1.));
      prm.add("Voltage increment (kV)", "0.25", voltage_increment_kV,
              "Largest change of any ring voltage in one step of the voltage path.",
              at_least(1e-8));
      prm.add("Min voltage increment (kV)", "1e-6", min_voltage_increment_kV,
              "Cut-backs below this voltage change (or below 1e-8 of the load in "
              "the other stages) end the run with an error.",
              at_least(0.));
      prm.add("Max cutbacks", "30", max_cutbacks,
              "Successive halvings of a failed increment before the run gives up.",
              between(0, 1000));
      prm.add("Continuation", "load stepping", continuation, continuation_choices,
              "How the voltage path is followed. 'load stepping' prescribes the path "
              "parameter and stops at a fold; 'arc length' (pseudo-arclength with a "
              "bordered Newton corrector) follows the curve through folds and locates "
              "every limit point.");
      prm.add("Linear solver", "banded LU", linear_solver, linear_solver_choices,
              "Direct solver of the tangent systems: LAPACK's banded LU, factored "
              "once per assembly (fast for these 1D meshes), or Trilinos' sparse "
              "KLU through deal.II.");
      prm.add("Max arc-length steps", "400", max_arc_length_steps,
              "Arc-length continuation ends after this many steps ...", between(1, 1000000));
      prm.add("Max displacement (mm)", "60", max_displacement_mm,
              "... or when the displacement exceeds this (0: no limit), or when the "
              "path parameter leaves [0, end of path].",
              at_least(0.));
      prm.add("Stability check", "true", stability_check,
              "Compute the smallest eigenvalue of the tangent (dead load and voltages "
              "held) at every converged state: negative means unstable.");
      prm.add("Stability eigenvalue", "every step", stability_eigenvalue, eigenvalue_choices,
              "Where the stability check computes the smallest eigenvalue. 'every "
              "step': at every converged state. 'near folds': stable or not from the "
              "inertia of one factorization at every state, the eigenvalue only where "
              "the state is not positive definite or near a fold (where it has fallen "
              "below 0.8 of the last one computed; the first state of a run computes "
              "it); elsewhere min_eigenvalue is NaN. Cheaper; the stable column is the "
              "same.");
      prm.add("Breakdown field (MV/m)", "0", breakdown_field_MV_per_m,
              "Electrical breakdown check: report where and when the true field E "
              "first exceeds this value (0: off).",
              at_least(0.));
      prm.leave_subsection();
    }

    void Wrinkling::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Wrinkling");
      prm.add("Onset tolerance (V)", "1e-3", onset_tolerance_V,
              "The load at which the hoop stress s2 first reaches zero is located "
              "by root finding to within this voltage.",
              at_least(1e-9));
      prm.add("Model", "check", model, wrinkling_choices,
              "'check': the plain membrane law everywhere; s2 < 0 is only detected "
              "and flagged. 'relaxed': tension-field theory where s2 would be "
              "negative (the energy minimised over hoop stretches above the "
              "kinematic one); the run stops where the relaxed law loses "
              "ellipticity (pull-in) or has no natural width below the Gent limit.");
      prm.leave_subsection();
    }

    void Shooting::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Shooting");
      prm.add("Tolerance", "1e-10", tolerance,
              "Relative (and, in units of the disk radius, absolute) error tolerance "
              "of the adaptive Dormand-Prince integrator of `cdea shoot` and "
              "`cdea compare`.",
              between(1e-14, 1e-2));
      prm.add("Samples per ring", "100", samples_per_ring,
              "Equally spaced points per ring at which the shooting fields are written.",
              between(2, 100000));
      prm.leave_subsection();
    }

    void Reservoir::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Reservoir");
      prm.add("Width (mm)", "20", width_mm,
              "Inner width of the pump's level tube (rectangular cross-section).");
      prm.add("Depth (mm)", "20", depth_mm,
              "Inner depth of the level tube; level drop = volume change / (width depth).");
      prm.leave_subsection();
    }

    void Output::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Output");
      prm.add("Directory", "results", directory,
              "Folder of the results file (created if missing), relative to the "
              "working directory.");
      prm.add("Base name", "default", base_name, "The results go to <Directory>/<Base name>.h5.");
      prm.add("ParaView", "false", paraview,
              "cdea run: also write <Directory>/<Base name>.pvd with one VTU file "
              "per converged step in <Directory>/<Base name>_vtu/ (the film as "
              "the revolved surface, the disk as a second piece).");
      prm.add("ParaView segments", "36", paraview_segments,
              "Cells around the axis in the revolved surface of the ParaView "
              "output.",
              between(3, 3600));
      prm.add("Step rows", "every", step_rows, step_rows_choices,
              "The rows of a time run's table in the terminal (the results file has "
              "every step whatever this says): every (a row per step), progress (a "
              "row each time another twentieth of the waveform's time has passed, "
              "and every row of the stages before it), none (the banner, the events "
              "and the final state only).");
      prm.leave_subsection();
    }
  } // namespace parameters

  CDEA_REGISTER_MEMBER_SUBSECTION(geometry, 10)
  CDEA_REGISTER_MEMBER_SUBSECTION(material, 20)
  CDEA_REGISTER_MEMBER_SUBSECTION(loading, 30)
  CDEA_REGISTER_MEMBER_SUBSECTION(electrodes, 40)
  CDEA_REGISTER_MEMBER_SUBSECTION(discretization, 50)
  CDEA_REGISTER_MEMBER_SUBSECTION(solver, 60)
  CDEA_REGISTER_MEMBER_SUBSECTION(wrinkling, 70)
  CDEA_REGISTER_MEMBER_SUBSECTION(shooting, 80)
  CDEA_REGISTER_MEMBER_SUBSECTION(reservoir, 100)
  CDEA_REGISTER_MEMBER_SUBSECTION(output, 130)
} // namespace cdea
