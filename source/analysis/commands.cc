#include <cdea/analysis/commands.h>
#include <cdea/input/parameters.h>
#include <cdea/input/pump.h>
#include <cdea/base/run_control.h>
#include <cdea/analysis/run_output.h>
#include <cdea/analysis/session.h>
#include <cdea/analysis/time_run.h>
#include <cdea/base/format.h>
#include <cdea/model/output_fields.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/output/paraview_writer.h>
#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>
#include <cdea/shooting/shooting_model.h>
#include <cdea/solver/load_stepper.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace cdea
{
  std::string usage()
  {
    return "cdea: finite-element model of a cone dielectric elastomer actuator with a\n"
           "partitioned ring electrode (axisymmetric Gent membrane, ideal dielectric).\n"
           "\n"
           "Usage:\n"
           "  cdea run FILE.prm          solve the scene of FILE.prm along its load stages\n"
           "                             and write <Directory>/<Base name>.h5\n"
           "  cdea shoot FILE.prm        the same with the independent shooting solver,\n"
           "                             written to <Directory>/<Base name>_shooting.h5\n"
           "  cdea compare FILE.prm      run both solvers and print their differences\n"
           "  cdea sweep FILE.prm        design map over two-ring layouts and outer voltages\n"
           "                             (subsection Sweep), <Base name>_map.h5; runs under\n"
           "                             mpirun -np N as well\n"
           "  cdea recover FILE.h5       rebuild the results of a killed run from its\n"
           "                             journal FILE.h5.journal\n"
           "  cdea optimize FILE.prm     electrode layout with the largest stroke without\n"
           "                             wrinkling (subsection Optimization), <Base name>_optimum.h5\n"
           "  cdea fit FILE.prm DATA.csv calibrate material constants to measured displacements\n"
           "                             (subsection Calibration), <Base name>_fit.h5\n"
           "  cdea print-parameters      print a complete, documented parameter file\n"
           "  cdea print-parameters --json\n"
           "                             the same parameters and defaults as JSON\n"
           "  cdea --version             the version of cdea and of deal.II\n"
           "  cdea --help                this text\n"
           "\n"
           "Exit codes: 0 success; 1 bad input or output not writable (nothing written);\n"
           "2 the run stopped before the end of its voltage path, was interrupted\n"
           "(SIGINT, SIGTERM) or could not write all its steps (the messages say where\n"
           "the converged steps are).\n"
           "See doc/usage.md for every parameter and the output layout.\n";
  }

  SteppingSettings stepping_settings(const Parameters &p)
  {
    SteppingSettings s;
    s.prestretch_steps      = p.solver.prestretch_steps;
    s.load_increment        = p.solver.load_increment;
    s.voltage_increment     = p.solver.voltage_increment_kV * 1e3;
    s.min_voltage_increment = p.solver.min_voltage_increment_kV * 1e3;
    s.max_cutbacks          = p.solver.max_cutbacks;
    s.onset_tolerance       = p.wrinkling.onset_tolerance_V;
    s.arc_length            = p.solver.continuation == Continuation::arc_length;
    s.max_arc_length_steps  = p.solver.max_arc_length_steps;
    s.max_displacement      = p.solver.max_displacement_mm * 1e-3;
    s.stability_check       = p.solver.stability_check;
    s.breakdown_field       = p.solver.breakdown_field_MV_per_m * 1e6;
    s.residual_tolerance    = p.solver.residual_tolerance;
    s.update_tolerance      = p.solver.update_tolerance;
    return s;
  }

  FeDiscretization fe_discretization(const Parameters &p)
  {
    FeDiscretization d;
    d.degree              = p.discretization.polynomial_degree;
    d.elements_per_ring   = p.discretization.elements_per_ring;
    d.grading             = p.discretization.grading;
    d.refinements         = p.discretization.refinements;
    d.samples_per_element = p.discretization.samples_per_element;
    return d;
  }

  NewtonSettings newton_settings(const Parameters &p)
  {
    NewtonSettings n;
    n.residual_tolerance = p.solver.residual_tolerance;
    n.update_tolerance   = p.solver.update_tolerance;
    n.max_iterations     = p.solver.max_newton_iterations;
    return n;
  }

  std::unique_ptr<MembraneModel> make_fe_model(const Parameters &p, const Scene &scene)
  {
    auto model = std::make_unique<MembraneModel>(scene, fe_discretization(p), newton_settings(p));
    model->set_linear_solver(p.solver.linear_solver);
    model->set_relaxed(p.wrinkling.model == WrinklingModel::relaxed);
    model->set_water_load(water_load(p));
    return model;
  }

  namespace
  {
    /// A postprocessor's column of @p s in the file's unit (NaN if absent).
    double column(const StepSummary &s, const OutputField &c) { return s.columns.in_file_units(c); }

    /// "-" for NaN, else fixed-point with @p decimals.
    std::string fixed_or_dash(const double value, const int decimals)
    {
      return std::isnan(value) ? std::string("-") : format_fixed(value, decimals);
    }

    /// Prints one table row per converged step and writes it to the file.
    class StepRecorder
    {
    public:
      StepRecorder(ResultsFile &file, LoadStepper &stepper, const Scene &scene)
        : file(file)
        , stepper(stepper)
        , scene(scene)
      {}

      void header() const
      {
        std::cout << std::setw(5) << "step" << std::setw(13) << "stage" << std::setw(10)
                  << "t" << "  " << std::setw(7 * scene.n_rings()) << "V (kV)"
                  << std::setw(12) << "disp (mm)" << std::setw(12) << "stroke (mm)"
                  << std::setw(12) << "dV (mm3)" << std::setw(12) << "min s2/mu" << std::setw(6)
                  << "wrk" << std::setw(7) << "stable" << std::setw(6) << "its" << '\n';
      }

      void step(const StepSummary &s)
      {
        file.append(s, stepper.step_fields());
        last = s;
        std::ostringstream v;
        for (const double x : s.voltages)
          v << ' ' << std::setw(6) << format_fixed(x * 1e-3, 3);
        // Fixed-point from the first row on, for the rows and the lines after them.
        // Every column keeps a blank before it, also for t >= 1000 or s2 < -1000 mu.
        std::cout << std::fixed;
        std::cout << std::setw(5) << file.n_steps() - 1 << std::setw(13) << stage_name(s.stage)
                  << ' ' << std::setw(9) << format_fixed(s.load_factor, 5) << "  " << v.str()
                  << ' ' << std::setw(11) << format_fixed(s.displacement * 1e3, 6) << ' '
                  << std::setw(11) << fixed_or_dash(s.stroke * 1e3, 6) << ' ' << std::setw(11)
                  << fixed_or_dash(column(s, summary_column::volume_change), 3) << ' ' << std::setw(11)
                  << format_fixed(s.s2_min / scene.material.shear_modulus, 6) << std::setw(6)
                  << (s.wrinkled ? "yes" : "no") << std::setw(7)
                  << (std::isnan(s.min_eigenvalue) ? "-" : s.min_eigenvalue > 0. ? "yes" : "NO")
                  << std::setw(6) << s.newton_iterations << std::endl;
      }

      StepSummary last;

    private:
      ResultsFile       &file;
      LoadStepper       &stepper;
      const Scene       &scene;
    };


    /// Drive @p model through the stages of @p scene, recording into @p path.
    int record_run(EquilibriumModel &model, const Parameters &p, const Scene &scene,
                   const std::string &prm_text, const std::string &path,
                   const std::string &method)
    {
      // ---- results file: claimed now, written whole at the end ----
      const auto output = RunOutput::open(path, prm_text, scene.n_rings(), {{"method", method}});
      if (!output)
        return exit_input_error;
      ResultsFile *const file = &output->file();
      LoadStepper        stepper(scene, model, stepping_settings(p));
      add_run_postprocessors(stepper, p, scene);
      // ParaView output (Output/ParaView): a VTU per step, moved in place at the end.
      std::unique_ptr<ParaViewWriter> paraview;
      std::optional<StepRecorder>     recorder_slot;
      std::vector<LimitPoint>         limits;
      // Limit points: /summary attributes limit_point_voltage_kV (k x rings)
      // and limit_point_displacement_mm (k), rewritten as each is found.
      if (!output->prepare([&] {
            file->write_onset(OnsetRecord());
            recorder_slot.emplace(*file, stepper, scene);
            write_summary_attributes(*file, limit_point_attributes(limits, scene.n_rings()));
            if (p.output.paraview)
              paraview = std::make_unique<ParaViewWriter>(path.substr(0, path.size() - 3),
                                                          p.output.paraview_segments);
          }))
        return exit_input_error;
      StepRecorder &recorder = *recorder_slot;
      stepper.on_step = [&](const StepSummary &s) {
        recorder.step(s);
        if (paraview)
          paraview->write_step(s, stepper.step_fields());
        RunOutput::stop_point();
      };
      stepper.on_onset = [&](const OnsetRecord &onset) {
        file->write_onset(onset);
        std::cout << "      loss of tension (s2 = 0) at " << format_kV(onset.voltages)
                  << ", radius r = " << std::setprecision(6) << onset.radius * 1e3
                  << " mm (r/a = " << onset.radius / scene.disk_radius << ")" << std::endl;
      };
      stepper.on_limit_point = [&](const LimitPoint &limit) {
        limits.push_back(limit);
        write_summary_attributes(*file, limit_point_attributes(limits, scene.n_rings()));
        std::cout << "      limit point (fold) at " << format_kV(limit.voltages)
                  << ", displacement " << std::setprecision(7) << limit.displacement * 1e3
                  << " mm" << std::endl;
      };
      stepper.on_breakdown = [&](const OnsetRecord &breakdown) {
        write_summary_attributes(*file, breakdown_attributes(breakdown));
        std::cout << "      breakdown field " << p.solver.breakdown_field_MV_per_m
                  << " MV/m reached at " << format_kV(breakdown.voltages) << ", r = "
                  << std::setprecision(6) << breakdown.radius * 1e3 << " mm" << std::endl;
      };

      std::cout << "cdea " << CDEA_VERSION << " (" << method << "): " << scene.n_rings()
                << " ring(s), writing " << path << '\n';
      recorder.header();
      const auto start = std::chrono::steady_clock::now();
      // ---- the run: a signal, an output failure or an error stops it ----
      RunResult    result = output->guard([&] { return stepper.run(); });
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

      if (paraview)
        try
          {
            paraview->finish();
            std::cout << "ParaView: " << paraview->n_steps() << " steps in "
                      << path.substr(0, path.size() - 3) << ".pvd\n";
          }
        catch (const std::exception &e)
          {
            // The HDF5 results do not depend on it: the run ends as incomplete.
            std::cerr << "cdea: the ParaView output is incomplete: " << e.what() << '\n';
            if (result.completed)
              {
                result.completed = false;
                result.message   = std::string("the ParaView output failed: ") + e.what();
              }
          }

      const StepSummary &s = recorder.last;
      std::cout << "\nFinal state: voltages " << format_kV(s.voltages) << ", displacement "
                << std::setprecision(7) << s.displacement * 1e3 << " mm, stroke "
                << s.stroke * 1e3 << " mm\n";
      {
        const double       volume_mm3 = column(s, summary_column::volume);
        std::ostringstream o;
        o << std::setprecision(7) << "  enclosed volume " << volume_mm3 << " mm^3, change "
          << column(s, summary_column::volume_change) << " mm^3, level drop "
          << column(s, summary_column::level_drop) << " mm (tube " << p.reservoir.width_mm << " mm x "
          << p.reservoir.depth_mm << " mm)\n";
        if (p.reservoir.water_load)
          o << "  water: free surface "
            << (p.reservoir.water_volume_ml * 1e-6 - volume_mm3 * 1e-9) / tube_area(p) * 1e3
            << " mm above the frame plane\n";
        std::cout << o.str();
      }
      std::cout << "  s2/mu at the inner edge of each ring:";
      for (const double x : s.s2_ring_inner)
        std::cout << ' ' << std::setprecision(6) << x / scene.material.shear_modulus;
      std::cout << '\n';
      if (result.onset.found)
        std::cout << "Wrinkling onset (loss of tension): " << format_kV(result.onset.voltages)
                  << " at r = " << result.onset.radius * 1e3 << " mm\n";
      else
        std::cout << "Wrinkling onset: none along the path (s2 > 0 everywhere)\n";
      for (const LimitPoint &limit : result.limit_points)
        std::cout << "Limit point (fold): " << format_kV(limit.voltages) << ", displacement "
                  << std::setprecision(7) << limit.displacement * 1e3 << " mm\n";
      if (p.solver.breakdown_field_MV_per_m > 0.)
        std::cout << "Breakdown field " << p.solver.breakdown_field_MV_per_m << " MV/m: "
                  << (result.breakdown.found ?
                        "first reached at " + format_kV(result.breakdown.voltages) :
                        std::string("not reached"))
                  << '\n';
      if (!result.end.empty())
        std::cout << "Arc-length continuation ended: " << result.end << '\n';
      std::cout << result.steps << " steps, " << result.newton_iterations
                << " Newton iterations, " << std::setprecision(3) << seconds << " s\n";
      return output->finish(result);
    }
  } // namespace

  shooting::ShootingOptions shooting_options(const Parameters &p)
  {
    shooting::ShootingOptions o;
    o.tolerance        = p.shooting.tolerance;
    o.samples_per_ring = p.shooting.samples_per_ring;
    return o;
  }

  namespace
  {
    using Input = RunInput;

    /// Read and validate; on bad input print the message and return nothing.
    std::optional<Input> load_input(const std::string &prm_file)
    {
      try
        {
          RunInput in = read_run_input(ParameterInput::file(prm_file), RunMethod::finite_elements);
          for (const std::string &warning : in.parameters.input_warnings)
            std::cerr << "cdea: warning: " << warning << '\n';
          return in;
        }
      catch (const InputError &e)
        {
          std::cerr << "cdea: " << e.what() << '\n';
          return std::nullopt;
        }
    }

    /// The water load exists in the FE model only: refuse it elsewhere.
    bool fe_only_check(const Parameters &p, const std::string &command)
    {
      try
        {
          require_shooting_options(p, command);
          return true;
        }
      catch (const InputError &e)
        {
          std::cerr << "cdea: " << e.what() << '\n';
          return false;
        }
    }

    /// The shooting model follows the voltage path by load stepping only.
    Parameters with_load_stepping(const Parameters &p, const std::string &command)
    {
      std::string      note;
      const Parameters q = load_stepping_parameters(p, command, note);
      if (!note.empty())
        std::cout << note << '\n';
      return q;
    }

    /// A run of @p model without output: its last step and result.
    struct QuietRun
    {
      RunResult   result;
      StepSummary last;
      double      seconds = 0.;
    };

    QuietRun quiet_run(EquilibriumModel &model, const Input &in)
    {
      QuietRun    run;
      LoadStepper stepper(in.scene, model, stepping_settings(in.parameters));
      stepper.on_step  = [&](const StepSummary &s) { run.last = s; };
      const auto start = std::chrono::steady_clock::now();
      run.result       = stepper.run();
      run.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return run;
    }
  } // namespace

  int run_fe(const std::string &prm_file)
  {
    const auto in = load_input(prm_file);
    if (!in)
      return exit_input_error;
    const Parameters &p = in->parameters;
    if (p.time.enabled)
      return run_time(p, in->scene, in->text);
    const auto        model_ptr = make_fe_model(p, in->scene);
    MembraneModel    &model     = *model_ptr;
    std::cout << "FE model: " << model.n_elements() << " elements of degree "
              << p.discretization.polynomial_degree << ", " << model.n_dofs() << " unknowns\n";
    if (p.reservoir.water_load)
      std::cout << "Water load: " << p.reservoir.water_volume_ml << " ml of density "
                << p.reservoir.water_density << " kg/m^3 above the membrane, level tube "
                << p.reservoir.width_mm << " x " << p.reservoir.depth_mm << " mm\n";
    return record_run(model, p, in->scene, in->text, p.results_path(), "finite elements");
  }

  int run_shooting(const std::string &prm_file)
  {
    const auto in = load_input(prm_file);
    if (!in)
      return exit_input_error;
    if (!fe_only_check(in->parameters, "shoot"))
      return exit_input_error;
    const Parameters        p = with_load_stepping(in->parameters, "shoot");
    shooting::ShootingModel model(in->scene, shooting_options(p));
    std::cout << "Shooting model: Dormand-Prince 5(4), tolerance " << p.shooting.tolerance
              << '\n';
    return record_run(model, p, in->scene, in->text, p.results_path("_shooting"), "shooting");
  }

  int compare(const std::string &prm_file)
  {
    const auto in = load_input(prm_file);
    if (!in)
      return exit_input_error;
    if (!fe_only_check(in->parameters, "compare"))
      return exit_input_error;
    Input                   input = *in;
    input.parameters              = with_load_stepping(in->parameters, "compare");
    const Parameters       &p     = input.parameters;
    const Scene            &scene = input.scene;
    const auto              fe_ptr = make_fe_model(p, scene);
    MembraneModel          &fe     = *fe_ptr;
    shooting::ShootingModel sh(scene, shooting_options(p));
    const QuietRun          a = quiet_run(fe, input);
    const QuietRun          b = quiet_run(sh, input);

    const double mu = scene.material.shear_modulus;
    std::cout << "cdea compare: FE (" << fe.n_elements() << " elements, p = "
              << p.discretization.polynomial_degree << ", " << fe.n_dofs()
              << " unknowns) vs shooting (tolerance " << p.shooting.tolerance << ")\n";
    for (const auto *r : {&a, &b})
      if (!r->result.completed)
        std::cout << (r == &a ? "FE" : "shooting") << " run stopped early: "
                  << r->result.message << '\n';
    std::cout << "state compared: the last converged step of each run, voltages FE "
              << format_kV(a.last.voltages) << ", shooting " << format_kV(b.last.voltages) << "\n\n";

    const auto row = [](const std::string &what, const double x, const double y,
                        const std::string &unit) {
      std::cout << std::left << std::setw(34) << what << std::right << std::setw(16)
                << std::setprecision(10) << x << std::setw(16) << y << std::setw(13)
                << std::setprecision(3) << std::scientific << x - y << std::setw(11)
                << std::abs(x - y) / std::max(std::abs(y), 1e-300) << std::defaultfloat
                << "  " << unit << '\n';
    };
    std::cout << std::left << std::setw(34) << "quantity" << std::right << std::setw(16)
              << "FE" << std::setw(16) << "shooting" << std::setw(13) << "FE - sh."
              << std::setw(11) << "relative" << '\n';
    row("displacement", a.last.displacement * 1e3, b.last.displacement * 1e3, "mm");
    row("stroke", a.last.stroke * 1e3, b.last.stroke * 1e3, "mm");
    row("enclosed volume", fe.enclosed_volume() * 1e9, sh.enclosed_volume() * 1e9, "mm^3");
    for (unsigned int k = 0; k < scene.n_rings(); ++k)
      row("s2/mu, inner edge of ring " + std::to_string(k + 1), a.last.s2_ring_inner[k] / mu,
          b.last.s2_ring_inner[k] / mu, "-");

    // Profiles: the FE solution at the shooting solver's sample radii.
    const StepFields    ref = sh.fields();
    std::vector<double> r, z;
    fe.profile_at(ref.R, r, z);
    double dr = 0., dz = 0.;
    for (std::size_t i = 0; i < ref.R.size(); ++i)
      {
        dr = std::max(dr, std::abs(r[i] - ref.r[i]));
        dz = std::max(dz, std::abs(z[i] - ref.z[i]));
      }
    std::cout << std::left << std::setw(34) << "max |r_FE - r_sh| over the meridian"
              << std::right << std::setw(16) << std::setprecision(3) << std::scientific
              << dr * 1e3 << " mm (" << dr / scene.disk_radius << " a)\n"
              << std::left << std::setw(34) << "max |z_FE - z_sh| over the meridian"
              << std::right << std::setw(16) << dz * 1e3 << " mm (" << dz / scene.disk_radius
              << " a)\n"
              << std::defaultfloat;

    if (a.result.onset.found && b.result.onset.found)
      {
        for (unsigned int k = 0; k < scene.n_rings(); ++k)
          row("onset voltage, ring " + std::to_string(k + 1) + " (kV)",
              a.result.onset.voltages[k] * 1e-3, b.result.onset.voltages[k] * 1e-3, "kV");
        row("onset radius r", a.result.onset.radius * 1e3, b.result.onset.radius * 1e3, "mm");
      }
    else
      std::cout << "onset: FE " << (a.result.onset.found ? "found" : "none") << ", shooting "
                << (b.result.onset.found ? "found" : "none") << '\n';
    std::cout << "\nwall time: FE " << std::setprecision(3) << a.seconds * 1e3
              << " ms, shooting " << b.seconds * 1e3 << " ms\n";
    return a.result.completed && b.result.completed ? exit_success : exit_not_complete;
  }
} // namespace cdea
