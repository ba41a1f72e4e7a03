#include <cdea/analysis/quasi_static_run.h>
#include <cdea/analysis/run_output.h>
#include <cdea/analysis/run_record.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/analysis/uncertainty_run.h>
#include <cdea/base/format.h>
#include <cdea/fe/load_term.h>
#include <cdea/model/output_fields.h>
#include <cdea/input/solver_settings.h>
#include <cdea/output/paraview_writer.h>
#include <cdea/output/results_file.h>
#include <cdea/solver/load_stepper.h>
#include <cdea/solver/state_check.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// A postprocessor's column of @p s in the file's unit (NaN if absent).
    double column(const StepSummary &s, const Quantity &c) { return s.columns.in_file_units(c); }

    /// A length (m) in mm, as the file's displacement, stroke and radii.
    double mm(const double metres) { return units::mm.from_si(metres); }

    /// "-" for NaN, else fixed-point with @p decimals.
    std::string fixed_or_dash(const double value, const int decimals)
    {
      return std::isnan(value) ? std::string("-") : format_fixed(value, decimals);
    }

    /// The table's "stable" entry: the stability check's answer, "-" when off.
    const char *stable_text(const double stable)
    {
      return std::isnan(stable) ? "-" : stable > 0. ? "yes" : "NO";
    }

    /// Why a state is not physical, from its NonPhysical bits (the /summary
    /// column nonphysical; NaN or 0: nothing to say).
    std::string nonphysical_text(const double flags)
    {
      if (!(flags > 0.))
        return "";
      const int   bits = int(flags);
      std::string text = bits & outside_frame ? "beyond the frame" : "";
      if (bits & self_intersection)
        text += std::string(text.empty() ? "" : ", ") + "crosses itself or the disk";
      return text;
    }

    /// Prints one table row per converged step and streams it to the file.
    class StepRecorder
    {
    public:
      StepRecorder(RunStream &stream, LoadStepper &stepper, const Scene &scene)
        : stream(stream)
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
        stream.step(s, stepper.step_fields());
        last = s;
        std::ostringstream v;
        for (const double x : s.voltages)
          v << ' ' << std::setw(6) << format_fixed(summary_column::voltage.in_file_units(x), 3);
        // Fixed-point from the first row on, for the rows and the lines after them.
        // Every column keeps a blank before it, also for t >= 1000 or s2 < -1000 mu.
        std::cout << std::fixed;
        std::cout << std::setw(5) << stream.n_steps() - 1 << std::setw(13) << stage_name(s.stage)
                  << ' ' << std::setw(9) << format_fixed(s.load_factor, 5) << "  " << v.str()
                  << ' ' << std::setw(11) << format_fixed(mm(s.displacement), 6) << ' '
                  << std::setw(11) << fixed_or_dash(mm(s.stroke), 6) << ' ' << std::setw(11)
                  << fixed_or_dash(column(s, summary_column::volume_change), 3) << ' ' << std::setw(11)
                  << format_fixed(s.s2_min / scene.material.shear_modulus, 6) << std::setw(6)
                  << (s.wrinkled ? "yes" : "no") << std::setw(7)
                  << stable_text(column(s, summary_column::stable))
                  << std::setw(6) << s.newton_iterations;
        // A state the film cannot take is marked where the eye is (the
        // stability column can still say yes: the model's equations hold).
        const std::string why = nonphysical_text(column(s, summary_column::nonphysical));
        if (!why.empty())
          {
            std::cout << "  ! not physical: " << why;
            ++n_nonphysical;
          }
        std::cout << std::endl;
      }

      StepSummary  last;
      unsigned int n_nonphysical = 0; ///< rows marked "! not physical"

    private:
      RunStream         &stream;
      LoadStepper       &stepper;
      const Scene       &scene;
    };

    /// One run: its results file, stepper, table and ParaView output.
    class QuasiStaticRun
    {
    public:
      QuasiStaticRun(EquilibriumModel &model, const RunInput &input, const RunMethod method)
        : p(input.parameters)
        , scene(input.scene)
        , method(method)
        , path(results_path(p, method))
        , output(RunOutput::open(path, input.text, scene.n_rings(),
                                 {{run_attribute::method.name, to_string(method)}}))
        , model(model)
        , stepper(scene, model, stepping_settings(p))
        , input(input)
        , fe_model(dynamic_cast<MembraneModel *>(&model))
      {
        add_run_postprocessors(stepper, p, scene);
        if (input.uncertainty.mode == UncertaintyMode::linear && fe_model)
          linear.emplace(input.uncertainty, scene);
        estimate = make_error_estimate(p, scene, method);
      }

      int run()
      {
        if (!output || !prepare())
          return exit_input_error;
        connect();
        if (linear)
          linear->follow(stepper, *fe_model);
        std::cout << "cdea " << CDEA_VERSION << " (" << to_string(method)
                  << "): " << scene.n_rings() << " ring(s), writing " << path << '\n';
        recorder->header();
        const auto start = std::chrono::steady_clock::now();
        // ---- the run: a signal, an output failure or an error stops it ----
        RunResult    result = output->guard([&] {
          RunResult r = stepper.run();
          if (r.completed)
            uncertainty_rows();
          return r;
        });
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        finish_paraview(result);
        print_final_state();
        if (uncertainty)
          std::cout << uncertainty_report(input.uncertainty, *uncertainty);
        estimate_errors(result);
        print_outcome(result, seconds);
        return output->finish(result);
      }

    private:
      const Parameters               &p;
      const Scene                    &scene;
      const RunMethod                 method;
      const std::string               path;
      std::unique_ptr<RunOutput>      output;
      EquilibriumModel               &model;
      LoadStepper                     stepper;
      std::unique_ptr<RunErrorEstimate> estimate; ///< Discretization/Error estimate
      std::unique_ptr<ParaViewWriter> paraview;
      std::optional<RunStream>        stream; ///< the file's product stream
      std::optional<StepRecorder>     recorder;
      const RunInput                 &input;
      MembraneModel                  *fe_model; ///< null for the shooting model
      std::optional<LinearRunUncertainty> linear;
      std::optional<ProductGroup>         uncertainty; ///< its rows, once taken

      /// The answers' uncertainty at the end of a complete run, streamed.
      void uncertainty_rows()
      {
        if (linear)
          uncertainty = linear->finish(*fe_model);
        else if (input.uncertainty.mode == UncertaintyMode::monte_carlo)
          {
            std::cout << "Monte-Carlo: " << input.uncertainty.samples
                      << " runs with sampled constants" << std::endl;
            uncertainty = monte_carlo_run(input, input.uncertainty, true);
          }
        if (uncertainty)
          stream->attributes(*uncertainty);
      }

      /// The writes before the first step: false (the output given up) if one fails.
      bool prepare()
      {
        // Limit points: /summary attributes limit_point_voltage_kV (k x rings)
        // and limit_point_displacement_mm (k), rewritten as each is found.
        stream.emplace(output->file(), scene.n_rings(),
                       method == RunMethod::shooting ? shooting_run : quasi_static_run);
        return output->prepare([&] {
          stream->start();
          recorder.emplace(*stream, stepper, scene);
          // ParaView output (Output/ParaView): a VTU per step, moved in place at the end.
          if (p.output.paraview)
            paraview = std::make_unique<ParaViewWriter>(path.substr(0, path.size() - 3),
                                                        p.output.paraview_segments);
        });
      }

      /// What the stepper reports is printed and written as it comes.
      void connect()
      {
        stepper.on_step = [this](const StepSummary &s) {
          if (estimate)
            estimate->step(s, model);
          recorder->step(s);
          if (paraview)
            paraview->write_step(s, stepper.step_fields());
          RunOutput::stop_point();
        };
        stepper.on_onset = [this](const OnsetRecord &onset) {
          if (estimate)
            estimate->onset(model);
          stream->onset(onset);
          std::cout << "      loss of tension (s2 = 0) at " << format_kV(onset.voltages)
                    << ", radius r = " << std::setprecision(6) << mm(onset.radius)
                    << " mm (r/a = " << onset.radius / scene.disk_radius << ")" << std::endl;
        };
        stepper.on_limit_point = [this](const LimitPoint &limit) {
          stream->limit_point(limit);
          std::cout << "      limit point (fold) at " << format_kV(limit.voltages)
                    << ", displacement " << std::setprecision(7) << mm(limit.displacement)
                    << " mm" << std::endl;
        };
        stepper.on_breakdown = [this](const OnsetRecord &breakdown) {
          stream->breakdown(breakdown);
          std::cout << "      breakdown field " << p.solver.breakdown_field_MV_per_m
                    << " MV/m reached at " << format_kV(breakdown.voltages) << ", r = "
                    << std::setprecision(6) << mm(breakdown.radius) << " mm" << std::endl;
        };
      }

      /// The ParaView collection moved in place; a failure makes the run incomplete.
      void finish_paraview(RunResult &result)
      {
        if (!paraview)
          return;
        if (output->cut_short() && paraview->older_output_exists())
          {
            // As the HDF5 results: the older output stays, this run's is beside it.
            std::cout << "ParaView: " << paraview->n_steps() << " steps in "
                      << path.substr(0, path.size() - 3) << ".partial.pvd (the older output "
                      << "of this name is kept)\n";
            return;
          }
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
      }

      void print_final_state() const
      {
        const StepSummary &s = recorder->last;
        std::cout << "\nFinal state: voltages " << format_kV(s.voltages) << ", displacement "
                  << std::setprecision(7) << mm(s.displacement) << " mm, stroke "
                  << mm(s.stroke) << " mm\n";
        const double       volume_mm3 = column(s, summary_column::volume);
        std::ostringstream o;
        o << std::setprecision(7) << "  enclosed volume " << volume_mm3 << " mm^3, change "
          << column(s, summary_column::volume_change) << " mm^3, level drop "
          << column(s, summary_column::level_drop) << " mm (tube " << p.reservoir.width_mm << " mm x "
          << p.reservoir.depth_mm << " mm)\n";
        for (const auto &term : make_load_terms(p.load_terms.values))
          o << term->describe_state(s);
        std::cout << o.str();
        std::cout << "  s2/mu at the inner edge of each ring:";
        for (const double x : s.s2_ring_inner)
          std::cout << ' ' << std::setprecision(6) << x / scene.material.shear_modulus;
        std::cout << '\n';
        const std::string why = nonphysical_text(column(s, summary_column::nonphysical));
        if (!why.empty())
          std::cout << "  not physical: " << why
                    << " (a state of the model's equations that the actuator cannot take)\n";
      }

      /// The final state's estimated errors, printed and written (not after
      /// a stop: the results so far go to the file at once). A failure
      /// leaves the run's results as they are.
      void estimate_errors(const RunResult &result)
      {
        if (!estimate || output->cut_short() || stream->n_steps() == 0)
          return;
        try
          {
            const auto         start  = std::chrono::steady_clock::now();
            const OutputErrors errors = estimate->estimate();
            stream->error_estimate(errors);
            std::cout << "Estimated numerical error ("
                      << format_number(std::chrono::duration<double>(
                                         std::chrono::steady_clock::now() - start)
                                         .count(),
                                       2)
                      << " s; doc/accuracy.md):\n"
                      << describe_errors(errors, recorder->last, result.onset.voltages,
                                         scene.material.shear_modulus);
          }
        catch (const std::exception &e)
          {
            std::cerr << "cdea: no error estimate: " << e.what() << '\n';
          }
      }

      /// Onset, limit points, breakdown, how arc length ended, and the counts.
      void print_outcome(const RunResult &result, const double seconds) const
      {
        if (result.onset.found)
          std::cout << "Wrinkling onset (loss of tension): " << format_kV(result.onset.voltages)
                    << " at r = " << mm(result.onset.radius) << " mm\n";
        else
          std::cout << "Wrinkling onset: none along the path (s2 > 0 everywhere)\n";
        for (const LimitPoint &limit : result.limit_points)
          std::cout << "Limit point (fold): " << format_kV(limit.voltages) << ", displacement "
                    << std::setprecision(7) << mm(limit.displacement) << " mm\n";
        if (p.solver.breakdown_field_MV_per_m > 0.)
          std::cout << "Breakdown field " << p.solver.breakdown_field_MV_per_m << " MV/m: "
                    << (result.breakdown.found ?
                          "first reached at " + format_kV(result.breakdown.voltages) :
                          std::string("not reached"))
                    << '\n';
        if (!result.end.empty())
          std::cout << "Arc-length continuation ended: " << result.end << '\n';
        if (recorder->n_nonphysical > 0)
          std::cout << recorder->n_nonphysical << " of " << result.steps
                    << " states are not physical (marked '! not physical' above; the "
                       "/summary column nonphysical)\n";
        std::cout << result.steps << " steps, " << result.newton_iterations
                  << " Newton iterations, " << std::setprecision(3) << seconds << " s\n";
      }
    };
  } // namespace

  int run_quasi_static(EquilibriumModel &model, const RunInput &input, const RunMethod method)
  {
    QuasiStaticRun run(model, input, method);
    return run.run();
  }
} // namespace cdea
