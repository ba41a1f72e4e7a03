#include <cdea/app/commands.h>
#include <cdea/app/parameters.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/output/results_file.h>
#include <cdea/solver/load_stepper.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
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
           "  cdea print-parameters      print a complete, documented parameter file\n"
           "  cdea --help                this text\n"
           "\n"
           "Exit codes: 0 success; 1 bad input or output not writable; 2 the run stopped\n"
           "before the end of its voltage path (converged steps stay in the results file).\n"
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

  namespace
  {
    /// Prints one table row per converged step and writes it to the file.
    class StepRecorder
    {
    public:
      StepRecorder(ResultsFile &file, const EquilibriumModel &model, const Scene &scene)
        : file(file)
        , model(model)
        , scene(scene)
      {}

      void header() const
      {
        std::cout << std::setw(5) << "step" << std::setw(13) << "stage" << std::setw(10)
                  << "t" << "  " << std::setw(7 * scene.n_rings()) << "V (kV)"
                  << std::setw(12) << "disp (mm)" << std::setw(12) << "stroke (mm)"
                  << std::setw(12) << "min s2/mu" << std::setw(6) << "wrk" << std::setw(6)
                  << "its" << '\n';
      }

      void step(const StepSummary &s)
      {
        file.append(s, model.fields());
        last = s;
        std::ostringstream v;
        for (const double x : s.voltages)
          v << std::setw(7) << std::fixed << std::setprecision(3) << x * 1e-3;
        std::cout << std::setw(5) << file.n_steps() - 1 << std::setw(13) << stage_name(s.stage)
                  << std::setw(10) << std::fixed << std::setprecision(5) << s.load_factor
                  << "  " << v.str() << std::setw(12) << std::setprecision(6)
                  << s.displacement * 1e3 << std::setw(12)
                  << (std::isnan(s.stroke) ? std::string("-") : [&] {
                       std::ostringstream o;
                       o << std::fixed << std::setprecision(6) << s.stroke * 1e3;
                       return o.str();
                     }())
                  << std::setw(12) << std::setprecision(6)
                  << s.s2_min / scene.material.shear_modulus << std::setw(6)
                  << (s.wrinkled ? "yes" : "no") << std::setw(6) << s.newton_iterations
                  << std::endl;
      }

      StepSummary last;

    private:
      ResultsFile            &file;
      const EquilibriumModel &model;
      const Scene            &scene;
    };

    std::string kv_list(const std::vector<double> &volts)
    {
      std::ostringstream o;
      for (std::size_t i = 0; i < volts.size(); ++i)
        o << (i ? ", " : "") << std::setprecision(6) << volts[i] * 1e-3;
      return o.str() + " kV";
    }

    /// Drive @p model through the stages of @p scene, recording into @p path.
    int record_run(EquilibriumModel &model, const Parameters &p, const Scene &scene,
                   const std::string &prm_text, const std::string &path,
                   const std::string &method)
    {
      std::unique_ptr<ResultsFile> file;
      try
        {
          file = std::make_unique<ResultsFile>(path, prm_text, scene.n_rings(),
                                               std::vector<std::pair<std::string, std::string>>{
                                                 {"method", method}});
        }
      catch (const std::exception &e)
        {
          std::cerr << "cdea: cannot write results: " << e.what() << '\n';
          return exit_input_error;
        }
      file->write_onset(OnsetRecord());

      StepRecorder recorder(*file, model, scene);
      LoadStepper  stepper(scene, model, stepping_settings(p));
      stepper.on_step  = [&](const StepSummary &s) { recorder.step(s); };
      stepper.on_onset = [&](const OnsetRecord &onset) {
        file->write_onset(onset);
        std::cout << "      loss of tension (s2 = 0) at " << kv_list(onset.voltages)
                  << ", radius r = " << std::setprecision(6) << onset.radius * 1e3
                  << " mm (r/a = " << onset.radius / scene.disk_radius << ")" << std::endl;
      };

      std::cout << "cdea " << CDEA_VERSION << " (" << method << "): " << scene.n_rings()
                << " ring(s), writing " << path << '\n';
      recorder.header();
      const auto      start  = std::chrono::steady_clock::now();
      const RunResult result = stepper.run();
      const double    seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

      const StepSummary &s = recorder.last;
      std::cout << "\nFinal state: voltages " << kv_list(s.voltages) << ", displacement "
                << std::setprecision(7) << s.displacement * 1e3 << " mm, stroke "
                << s.stroke * 1e3 << " mm\n  s2/mu at the inner edge of each ring:";
      for (const double x : s.s2_ring_inner)
        std::cout << ' ' << std::setprecision(6) << x / scene.material.shear_modulus;
      std::cout << '\n';
      if (result.onset.found)
        std::cout << "Wrinkling onset (loss of tension): " << kv_list(result.onset.voltages)
                  << " at r = " << result.onset.radius * 1e3 << " mm\n";
      else
        std::cout << "Wrinkling onset: none along the path (s2 > 0 everywhere)\n";
      std::cout << result.steps << " steps, " << result.newton_iterations
                << " Newton iterations, " << std::setprecision(3) << seconds << " s\n";
      if (!result.completed)
        {
          std::cerr << "cdea: the run stopped early: " << result.message << "\n"
                    << "cdea: the " << file->n_steps() << " converged steps are in " << path
                    << '\n';
          return exit_not_complete;
        }
      return exit_success;
    }
  } // namespace

  int run_fe(const std::string &prm_file)
  {
    std::string prm_text;
    Parameters  p;
    Scene       scene;
    try
      {
        p     = read_parameters(prm_file, &prm_text);
        scene = p.scene();
      }
    catch (const InputError &e)
      {
        std::cerr << "cdea: " << e.what() << '\n';
        return exit_input_error;
      }
    MembraneModel model(scene, fe_discretization(p), newton_settings(p));
    std::cout << "FE model: " << model.n_elements() << " elements of degree "
              << p.discretization.polynomial_degree << ", " << model.n_dofs() << " unknowns\n";
    return record_run(model, p, scene, prm_text, p.results_path(), "finite elements");
  }
} // namespace cdea
