#include <deal.II/base/parameter_handler.h>

#include <cdea/input/parameters.h>

#include <cmath>
#include <sstream>

namespace cdea
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;

  namespace parameters
  {
    void Geometry::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Disk radius (mm)", "14", Double(),
                        "Radius a of the rigid disk, measured on the pre-stretched flat film.");
      prm.declare_entry("Frame radius (mm)", "42", Double(),
                        "Inner radius b of the rigid frame, measured on the pre-stretched flat film.");
      prm.declare_entry("Film thickness (mm)", "1", Double(),
                        "Thickness H of the undeformed (unstretched) film.");
      prm.declare_entry("Prestretch", "2.5", Double(),
                        "Equi-biaxial pre-stretch lam_pre of the film before the disk is attached.");
      prm.leave_subsection();
    }

    void Geometry::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      disk_radius_mm    = prm.get_double("Disk radius (mm)");
      frame_radius_mm   = prm.get_double("Frame radius (mm)");
      film_thickness_mm = prm.get_double("Film thickness (mm)");
      prestretch        = prm.get_double("Prestretch");
      prm.leave_subsection();
    }

    void Material::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("Shear modulus (kPa)", "25.1", Double(),
                        "Small-strain shear modulus mu of the Gent law.");
      prm.declare_entry("Jlim", "270", Double(),
                        "Gent limit: the law stiffens without bound as I1 - 3 approaches Jlim.");
      prm.declare_entry("Permittivity (F/m)", "3.98e-11", Double(),
                        "Permittivity eps of the ideal dielectric.");
      prm.leave_subsection();
    }

    void Material::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      shear_modulus_kPa = prm.get_double("Shear modulus (kPa)");
      jlim              = prm.get_double("Jlim");
      permittivity      = prm.get_double("Permittivity (F/m)");
      prm.leave_subsection();
    }

    void Loading::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      prm.declare_entry("Mass (g)", "280", Double(),
                        "Dead weight hanging from the disk; the load F = m g pulls the disk "
                        "out of the frame plane.");
      prm.declare_entry("Gravity (m/s^2)", "9.81", Double(), "Gravitational acceleration g.");
      prm.leave_subsection();
    }

    void Loading::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      mass_g  = prm.get_double("Mass (g)");
      gravity = prm.get_double("Gravity (m/s^2)");
      prm.leave_subsection();
    }

    void Electrodes::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Electrodes");
      prm.declare_entry("Ring edges (r/a)", "1, 3", Anything(),
                        "n+1 increasing edges of n concentric electrode rings, as radii on the "
                        "pre-stretched flat film over the disk radius: the first is 1 (disk "
                        "edge), the last b/a (frame).");
      prm.declare_entry("Voltage path (kV)", "5", Anything(),
                        "Waypoints separated by ';', each one voltage per ring separated by ','. "
                        "All rings start at 0 kV and move linearly from one waypoint to the next.");
      prm.leave_subsection();
    }

    void Electrodes::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Electrodes");
      ring_edges_text   = prm.get("Ring edges (r/a)");
      voltage_path_text = prm.get("Voltage path (kV)");
      prm.leave_subsection();
    }

    void Discretization::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      prm.declare_entry("Polynomial degree", "4", Integer(1, 8),
                        "Degree p of the FE_Q elements for r(R) and z(R).");
      prm.declare_entry("Elements per ring", "4", Integer(1, 100000),
                        "Elements in every electrode ring before global refinement; element "
                        "boundaries always lie on the ring edges.");
      prm.declare_entry("Grading", "4", Double(1., 1000.),
                        "Ratio of the outermost to the innermost element length in each ring: "
                        "elements are geometrically smaller towards the ring's inner edge, where "
                        "the meridian stretch varies fastest. 1 is uniform.");
      prm.declare_entry("Global refinements", "0", Integer(0, 20),
                        "Times every element is bisected (h-refinement studies).");
      prm.declare_entry("Samples per element", "16", Integer(1, 1000),
                        "Equally spaced points per element at which fields are written (enough for "
                        "smooth profiles in plots and ParaView).");
      prm.leave_subsection();
    }

    void Discretization::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      polynomial_degree   = prm.get_integer("Polynomial degree");
      elements_per_ring   = prm.get_integer("Elements per ring");
      grading             = prm.get_double("Grading");
      refinements         = prm.get_integer("Global refinements");
      samples_per_element = prm.get_integer("Samples per element");
      prm.leave_subsection();
    }

    void Solver::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      prm.declare_entry("Residual tolerance", "1e-10", Double(0.),
                        "Newton has converged when the largest residual entry over the force "
                        "scale max(F, 2 pi H mu a) is below this and the update criterion holds.");
      prm.declare_entry("Update tolerance", "1e-10", Double(0.),
                        "Newton has converged when the largest update over the disk radius a "
                        "is below this and the residual criterion holds.");
      prm.declare_entry("Max Newton iterations", "25", Integer(1, 1000),
                        "Newton iterations before a load step counts as failed and is cut back.");
      prm.declare_entry("Prestretch steps", "1", Integer(1, 10000),
                        "Steps from the unstretched film to lam_pre (the state is homogeneous).");
      prm.declare_entry("Load increment", "0.25", Double(1e-8, 1.),
                        "Largest increment of the dead load, as a fraction of m g.");
      prm.declare_entry("Voltage increment (kV)", "0.25", Double(1e-8),
                        "Largest change of any ring voltage in one step of the voltage path.");
      prm.declare_entry("Min voltage increment (kV)", "1e-6", Double(0.),
                        "Cut-backs below this voltage change (or below 1e-8 of the load in "
                        "the other stages) end the run with an error.");
      prm.declare_entry("Max cutbacks", "30", Integer(0, 1000),
                        "Successive halvings of a failed increment before the run gives up.");
      prm.declare_entry("Continuation", "load stepping",
                        dealii::Patterns::Selection("load stepping|arc length"),
                        "How the voltage path is followed. 'load stepping' prescribes the path "
                        "parameter and stops at a fold; 'arc length' (pseudo-arclength with a "
                        "bordered Newton corrector) follows the curve through folds and locates "
                        "every limit point.");
      prm.declare_entry("Linear solver", "banded LU",
                        dealii::Patterns::Selection("banded LU|Trilinos KLU"),
                        "Direct solver of the tangent systems: LAPACK's banded LU, factored "
                        "once per assembly (fast for these 1D meshes), or Trilinos' sparse "
                        "KLU through deal.II.");
      prm.declare_entry("Max arc-length steps", "400", Integer(1, 1000000),
                        "Arc-length continuation ends after this many steps ...");
      prm.declare_entry("Max displacement (mm)", "60", Double(0.),
                        "... or when the displacement exceeds this (0: no limit), or when the "
                        "path parameter leaves [0, end of path].");
      prm.declare_entry("Stability check", "true", Bool(),
                        "Compute the smallest eigenvalue of the tangent (dead load and voltages "
                        "held) at every converged state: negative means unstable.");
      prm.declare_entry("Stability eigenvalue", "every step",
                        dealii::Patterns::Selection("every step|near folds"),
                        "Where the stability check computes the smallest eigenvalue. 'every "
                        "step': at every converged state. 'near folds': stable or not from the "
                        "inertia of one factorization at every state, the eigenvalue only where "
                        "the state is not positive definite or near a fold (where it has fallen "
                        "below 0.8 of the last one computed; the first state of a run computes "
                        "it); elsewhere min_eigenvalue is NaN. Cheaper; the stable column is the "
                        "same.");
      prm.declare_entry("Breakdown field (MV/m)", "0", Double(0.),
                        "Electrical breakdown check: report where and when the true field E "
                        "first exceeds this value (0: off).");
      prm.leave_subsection();
    }

    void Solver::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      residual_tolerance       = prm.get_double("Residual tolerance");
      update_tolerance         = prm.get_double("Update tolerance");
      max_newton_iterations    = prm.get_integer("Max Newton iterations");
      prestretch_steps         = prm.get_integer("Prestretch steps");
      load_increment           = prm.get_double("Load increment");
      voltage_increment_kV     = prm.get_double("Voltage increment (kV)");
      min_voltage_increment_kV = prm.get_double("Min voltage increment (kV)");
      max_cutbacks             = prm.get_integer("Max cutbacks");
      continuation = prm.get("Continuation") == "arc length" ? Continuation::arc_length :
                                                               Continuation::load_stepping;
      linear_solver = prm.get("Linear solver") == "Trilinos KLU" ? LinearSolver::trilinos_klu :
                                                                   LinearSolver::banded_lu;
      max_arc_length_steps     = prm.get_integer("Max arc-length steps");
      max_displacement_mm      = prm.get_double("Max displacement (mm)");
      stability_check          = prm.get_bool("Stability check");
      stability_eigenvalue     = prm.get("Stability eigenvalue") == "near folds" ?
                                   StabilityEigenvalue::near_folds :
                                   StabilityEigenvalue::every_step;
      breakdown_field_MV_per_m = prm.get_double("Breakdown field (MV/m)");
      prm.leave_subsection();
    }

    void Wrinkling::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Wrinkling");
      prm.declare_entry("Onset tolerance (V)", "1e-3", Double(1e-9),
                        "The load at which the hoop stress s2 first reaches zero is located "
                        "by root finding to within this voltage.");
      prm.declare_entry("Model", "check", dealii::Patterns::Selection("check|relaxed"),
                        "'check': the plain membrane law everywhere; s2 < 0 is only detected "
                        "and flagged. 'relaxed': tension-field theory where s2 would be "
                        "negative (the energy minimised over hoop stretches above the "
                        "kinematic one); the run stops where the relaxed law loses "
                        "ellipticity (pull-in) or has no natural width below the Gent limit.");
      prm.leave_subsection();
    }

    void Wrinkling::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Wrinkling");
      onset_tolerance_V = prm.get_double("Onset tolerance (V)");
      model = prm.get("Model") == "relaxed" ? WrinklingModel::relaxed : WrinklingModel::check;
      prm.leave_subsection();
    }

    void Shooting::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Shooting");
      prm.declare_entry("Tolerance", "1e-10", Double(1e-14, 1e-2),
                        "Relative (and, in units of the disk radius, absolute) error tolerance "
                        "of the adaptive Dormand-Prince integrator of `cdea shoot` and "
                        "`cdea compare`.");
      prm.declare_entry("Samples per ring", "100", Integer(2, 100000),
                        "Equally spaced points per ring at which the shooting fields are written.");
      prm.leave_subsection();
    }

    void Shooting::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Shooting");
      tolerance        = prm.get_double("Tolerance");
      samples_per_ring = prm.get_integer("Samples per ring");
      prm.leave_subsection();
    }

    void Reservoir::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Reservoir");
      prm.declare_entry("Width (mm)", "20", Double(),
                        "Inner width of the pump's level tube (rectangular cross-section).");
      prm.declare_entry("Depth (mm)", "20", Double(),
                        "Inner depth of the level tube; level drop = volume change / (width depth).");
      prm.leave_subsection();
    }

    void Reservoir::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Reservoir");
      width_mm        = prm.get_double("Width (mm)");
      depth_mm        = prm.get_double("Depth (mm)");
      prm.leave_subsection();
    }

    void Output::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory", "results", Anything(),
                        "Folder of the results file (created if missing), relative to the "
                        "working directory.");
      prm.declare_entry("Base name", "default", Anything(),
                        "The results go to <Directory>/<Base name>.h5.");
      prm.declare_entry("ParaView", "false", Bool(),
                        "cdea run: also write <Directory>/<Base name>.pvd with one VTU file "
                        "per converged step in <Directory>/<Base name>_vtu/ (the film as "
                        "the revolved surface, the disk as a second piece).");
      prm.declare_entry("ParaView segments", "36", Integer(3, 3600),
                        "Cells around the axis in the revolved surface of the ParaView "
                        "output.");
      prm.leave_subsection();
    }

    void Output::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory    = prm.get("Directory");
      base_name    = prm.get("Base name");
      paraview          = prm.get_bool("ParaView");
      paraview_segments = prm.get_integer("ParaView segments");
      prm.leave_subsection();
    }
  } // namespace parameters

  void Parameters::declare(ParameterHandler &prm)
  {
    // deal.II numbers the patterns in the order of declaration, and the JSON
    // form of print-parameters shows those numbers: the order is that of
    // earlier versions, the load terms' entries of subsection Reservoir
    // with the Reservoir's own, the laws' after Output (where Material/Model
    // always was), and the load terms' other entries last.
    const auto in_reservoir = [](const EntryDeclaration &e) { return e.subsection == "Reservoir"; };
    parameters::Geometry::declare(prm);
    parameters::Material::declare(prm);
    parameters::Loading::declare(prm);
    parameters::Electrodes::declare(prm);
    parameters::Discretization::declare(prm);
    parameters::Solver::declare(prm);
    parameters::Wrinkling::declare(prm);
    parameters::Shooting::declare(prm);
    parameters::Sweep::declare(prm);
    parameters::Reservoir::declare(prm);
    parameters::LoadTerms::declare(prm, in_reservoir);
    parameters::Optimization::declare(prm);
    parameters::Calibration::declare(prm);
    parameters::Output::declare(prm);
    parameters::MaterialLaw::declare(prm);
    parameters::Time::declare(prm);
    parameters::LoadTerms::declare(prm, [&](const EntryDeclaration &e) { return !in_reservoir(e); });
    parameters::Response::declare(prm);
    parameters::SteadyState::declare(prm);
    parameters::FrequencySweep::declare(prm);
  }

  void Parameters::parse(ParameterHandler &prm)
  {
    geometry.parse(prm);
    material.parse(prm);
    loading.parse(prm);
    electrodes.parse(prm);
    discretization.parse(prm);
    solver.parse(prm);
    wrinkling.parse(prm);
    shooting.parse(prm);
    sweep.parse(prm);
    reservoir.parse(prm);
    optimization.parse(prm);
    calibration.parse(prm);
    output.parse(prm);
    material_law.parse(prm);
    time.parse(prm);
    load_terms.parse(prm);
    response.parse(prm);
    steady_state.parse(prm);
    frequency_sweep.parse(prm);
  }

  std::string to_string(const Continuation choice)
  {
    return choice == Continuation::arc_length ? "arc length" : "load stepping";
  }

  std::string to_string(const WrinklingModel choice)
  {
    return choice == WrinklingModel::relaxed ? "relaxed" : "check";
  }

  namespace
  {
    std::string format(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    /// Sizes and constants a scene cannot be built from.
    void check_geometry_and_material(const parameters::Geometry &geometry,
                                     const parameters::Material &material,
                                     const parameters::Loading  &loading)
    {
      require_positive(geometry.disk_radius_mm, "Geometry/Disk radius (mm)");
      require_positive(geometry.frame_radius_mm, "Geometry/Frame radius (mm)");
      require_positive(geometry.film_thickness_mm, "Geometry/Film thickness (mm)");
      if (geometry.frame_radius_mm <= geometry.disk_radius_mm)
        throw InputError("Geometry/Frame radius (mm) must be larger than Geometry/Disk radius "
                         "(mm) (" + format(geometry.disk_radius_mm) + "), got " +
                         format(geometry.frame_radius_mm));
      if (!(geometry.prestretch > 1.))
        throw InputError("Geometry/Prestretch must be larger than 1 (the film has to be taut), "
                         "got " + format(geometry.prestretch));
      require_positive(material.shear_modulus_kPa, "Material/Shear modulus (kPa)");
      require_positive(material.jlim, "Material/Jlim");
      require_positive(material.permittivity, "Material/Permittivity (F/m)");
      if (loading.mass_g < 0.)
        throw InputError("Loading/Mass (g) must be zero or positive, got " +
                         format(loading.mass_g));
      require_positive(loading.gravity, "Loading/Gravity (m/s^2)");

      // The equi-biaxial pre-stretch alone must stay inside the Gent limit:
      // I - 3 = 2 lam^2 + lam^-4 - 3 < Jlim.
      const double lam = geometry.prestretch;
      const double I3  = 2. * lam * lam + 1. / (lam * lam * lam * lam) - 3.;
      if (I3 >= material.jlim)
        throw InputError("Geometry/Prestretch " + format(lam) +
                         " already exceeds the Gent limit: I1 - 3 = " + format(I3) +
                         " must be below Material/Jlim = " + format(material.jlim));
    }

    /// Electrodes/Ring edges (r/a): 1 first, b/a last, increasing, no ring
    /// narrower than 1e-6.
    std::vector<double> ring_edges(const std::string &text, const double b_over_a)
    {
      const std::string name  = "Electrodes/Ring edges (r/a)";
      auto              edges = parse_number_list(text, name);
      if (edges.size() < 2)
        throw InputError(name + ": needs at least two edges (1 and b/a = " + format(b_over_a) +
                         "), got '" + text + "'");
      if (std::abs(edges.front() - 1.) > 1e-9)
        throw InputError(name + ": the first edge must be 1 (the disk edge), got " +
                         format(edges.front()));
      if (std::abs(edges.back() - b_over_a) > 1e-6 * b_over_a)
        throw InputError(name + ": the last edge must be b/a = " + format(b_over_a) +
                         " (the frame), got " + format(edges.back()));
      for (std::size_t i = 1; i < edges.size(); ++i)
        if (!(edges[i] > edges[i - 1]))
          throw InputError(name + ": edges must increase strictly, but " + format(edges[i]) +
                           " follows " + format(edges[i - 1]));
      // A narrower ring's elements are too short for the Newton update and
      // residual criteria (relative to a) to resolve it.
      for (std::size_t i = 1; i < edges.size(); ++i)
        if (edges[i] - edges[i - 1] < 1e-6)
          throw InputError(name + ": every ring must be at least 1e-6 (r/a) wide, but the "
                           "ring from " + format(edges[i - 1]) + " to " + format(edges[i]) +
                           " is narrower");
      edges.front() = 1.;
      edges.back()  = b_over_a;
      return edges;
    }

    /// Electrodes/Voltage path (kV): waypoints separated by ';', one
    /// voltage per ring each, in V.
    VoltagePath voltage_path(const std::string &text, const unsigned int n_rings)
    {
      const std::string                name = "Electrodes/Voltage path (kV)";
      std::vector<std::vector<double>> waypoints;
      for (const std::string &item : split_list(text, ';'))
        {
          auto w = parse_number_list(item, name);
          if (w.size() != n_rings)
            throw InputError(name + ": waypoint '" + item + "' has " +
                             std::to_string(w.size()) + " voltage(s), but there are " +
                             std::to_string(n_rings) +
                             " ring(s): give one voltage per ring, waypoints separated by ';'");
          for (double &v : w)
            {
              if (v < 0.)
                throw InputError(name + ": voltages must not be negative (the energy "
                                 "depends on Phi^2 only), got " + format(v));
              v *= 1e3;
            }
          waypoints.push_back(w);
        }
      if (waypoints.empty())
        throw InputError(name + ": no waypoint given");
      if (ends_with_separator(text, ';'))
        throw InputError(name + ": empty waypoint at the end of '" + text + "'");
      return VoltagePath(waypoints);
    }

    void check_output_and_increments(const parameters::Output &output,
                                     const parameters::Solver &solver)
    {
      if (output.base_name.empty() || output.base_name.find('/') != std::string::npos)
        throw InputError("Output/Base name must be a non-empty file name without '/', got '" +
                         output.base_name + "'");
      if (output.directory.empty())
        throw InputError("Output/Directory must not be empty (use . for the working directory)");
      if (solver.min_voltage_increment_kV > solver.voltage_increment_kV)
        throw InputError("Solver/Min voltage increment (kV) must not exceed Solver/Voltage "
                         "increment (kV)");
    }
  } // namespace

  Scene Parameters::scene() const
  {
    check_geometry_and_material(geometry, material, loading);
    Scene scene;
    scene.disk_radius  = geometry.disk_radius_mm * 1e-3;
    scene.frame_radius = geometry.frame_radius_mm * 1e-3;
    scene.prestretch   = geometry.prestretch;
    scene.material     = {material.shear_modulus_kPa * 1e3, material.jlim,
                          material.permittivity, geometry.film_thickness_mm * 1e-3};
    scene.material_model = material_law.model;
    scene.law_constants  = material_law.constants;
    scene.law_texts      = material_law.texts;
    scene.mass         = loading.mass_g * 1e-3;
    scene.gravity      = loading.gravity;
    scene.ring_edges_over_a =
      ring_edges(electrodes.ring_edges_text, geometry.frame_radius_mm / geometry.disk_radius_mm);
    scene.path = voltage_path(electrodes.voltage_path_text, scene.n_rings());
    check_output_and_increments(output, solver);
    return scene;
  }

  std::string Parameters::results_path(const std::string &suffix) const
  {
    return output.directory + "/" + output.base_name + suffix + ".h5";
  }

  std::string default_parameter_file(const ParameterFormat format)
  {
    ParameterHandler prm;
    Parameters::declare(prm);
    std::ostringstream out;
    prm.print_parameters(out, format == ParameterFormat::json ? ParameterHandler::JSON :
                                                                ParameterHandler::PRM);
    return out.str();
  }
} // namespace cdea
