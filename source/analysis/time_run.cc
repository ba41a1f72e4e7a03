#include <cdea/analysis/run_output.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/analysis/time_run.h>
#include <cdea/base/format.h>
#include <cdea/model/output_fields.h>
#include <cdea/input/solver_settings.h>
#include <cdea/output/results_file.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// How the steps were sized: the fixed-step schemes take fixed steps.
    TimeStepControl step_control_of(const TimeSettings &settings)
    {
      return esdirk_tableau(settings.method) ? settings.control : TimeStepControl::fixed;
    }

    /// "ESDIRK3, error control at relative 1e-06", "ESDIRK4, fixed steps" or
    /// the fixed-step scheme's name as before ("backward Euler").
    std::string scheme_description(const TimeSettings &settings)
    {
      std::string d = to_string(settings.method);
      if (!esdirk_tableau(settings.method))
        return d;
      if (step_control_of(settings) == TimeStepControl::fixed)
        return d + ", fixed steps";
      return d + ", error control at relative " + format_number(settings.relative_tolerance, 3);
    }

    /// A postprocessor's column of @p s in the file's unit (NaN if absent).
    double column(const StepSummary &s, const Quantity &c) { return s.columns.in_file_units(c); }

    /// A length (m) in mm, as the file's displacement, stroke and radii.
    double mm(const double metres) { return units::mm.from_si(metres); }

    /// One cell of the progress table: a blank, then the value right-aligned in
    /// @p width - 1 characters ("-" if it is NaN), so that columns never run
    /// together however wide a value grows.
    std::string cell(const double value, const int decimals, const int width)
    {
      return ' ' + (std::isnan(value) ? std::string(width - 2, ' ') + "-" :
                                        format_fixed(value, decimals, width - 1));
    }

    /// A value that a run stopped early never reached prints as "-", not "nan".
    std::string number_or_dash(const double value, const int digits)
    {
      return std::isnan(value) ? std::string("-") : format_number(value, digits);
    }

    /// `cdea run` of a time run: the table of steps, the results file and
    /// the final state with its energy budget.
    class TimeRun
    {
    public:
      explicit TimeRun(const RunInput &input)
        : p(input.parameters)
        , scene(input.scene)
        , run(set_up_time_run(p, scene))
        , stepper(*run.stepper)
        , path(p.results_path())
      {
        std::vector<std::pair<std::string, std::string>> root_attributes = {
          {run_attribute::method.name, to_string(RunMethod::finite_elements_in_time)}};
        root_attributes.insert(root_attributes.end(), run.root_attributes.begin(),
                               run.root_attributes.end());
        output = RunOutput::open(path, input.text, scene.n_rings(), root_attributes);
      }

      int go()
      {
        // A first record before the run, so that an unwritable journal stops
        // it here (the attributes are those the file starts with).
        if (!output)
          return exit_input_error;
        stream.emplace(output->file(), scene.n_rings(), time_run);
        if (!output->prepare([&] { stream->start(); }))
          return exit_input_error;
        print_banner();
        connect();
        const auto      start  = std::chrono::steady_clock::now();
        const RunResult result = output->guard([&] { return stepper.run(); });
        const double    seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        print_final_state(result, seconds);
        report_a_drive_that_never_rose();
        stream->time_integration(result.time_steps, result.rejected_steps, result.error_estimate);
        return output->finish(result);
      }

    private:
      const Parameters          &p;
      const Scene               &scene;
      TimeRunSetup               run;
      TimeStepper               &stepper;
      const std::string          path;
      std::unique_ptr<RunOutput> output;
      std::optional<RunStream>   stream; ///< the file's product stream
      StepSummary                last;
      /// The largest |V| of any ring at any time step (V).
      double highest_voltage = 0.;
      unsigned int               newton_iterations_of_steps = 0;
      /// Output/Step rows = progress: the waveform time of the next row (s).
      double next_row_time = 0.;
      /// The disk's natural frequency at the first state in time (NaN before).
      double frequency_start = std::numeric_limits<double>::quiet_NaN();

      /// The disk's natural frequency sqrt(k/m) / 2 pi now (k: the condensed
      /// static tangent).
      double frequency() const
      {
        return scene.mass > 0. ? std::sqrt(std::max(run.model->disk_stiffness(), 0.) /
                                           scene.mass) /
                                   (2. * M_PI) :
                                 std::numeric_limits<double>::quiet_NaN();
      }

      void print_banner() const
      {
        const TimeSettings &settings = run.settings;
        std::cout << "FE model: " << run.model->n_elements() << " elements of degree "
                  << p.discretization.polynomial_degree << ", " << run.model->n_dofs()
                  << " unknowns\n"
                  << "Time: " << to_string(p.time.waveform) << " waveform, peak "
                  << format_kV(settings.waveform.peak()) << " over "
                  << format_number(settings.waveform.end_time()) << " s, steps up to "
                  << format_number(TimeStepper::largest_step(settings)) << " s ("
                  << scheme_description(settings) << "), material "
                  << p.material_law.model
                  << (settings.inertia ? ", disk inertia" : ", no inertia")
                  << (settings.column.present() ? " and water column" : "") << '\n'
                  << "writing " << path << '\n';
        const unsigned int n = scene.n_rings();
        if (p.output.step_rows == StepRows::none)
          return;
        std::cout << std::setw(6) << "step" << std::setw(12) << "stage" << std::setw(11)
                  << "time (s)" << std::setw(7 * n) << "V (kV)" << std::setw(12) << "disp (mm)"
                  << std::setw(12) << "stroke (mm)" << std::setw(11) << "level (mm)"
                  << std::setw(11) << "v (mm/s)" << std::setw(11) << "min s2/mu" << std::setw(5)
                  << "its" << '\n';
      }

      void connect()
      {
        stepper.on_step = [this](const StepSummary &s) {
          if (std::isnan(frequency_start) && !std::isnan(column(s, summary_column::waveform_time)))
            frequency_start = frequency();
          step(s);
        };
        stepper.on_onset = [this](const OnsetRecord &onset) {
          stream->onset(onset);
          std::cout << "      loss of tension (s2 = 0) at t = "
                    << format_number(onset.load_factor, 8) << " s, " << format_kV(onset.voltages)
                    << ", radius r = " << format_number(mm(onset.radius)) << " mm"
                    << std::endl;
        };
      }

      /// A step written, then printed as a row of the table.
      void step(const StepSummary &s)
      {
        stream->step(s, stepper.fields_wanted() ? stepper.step_fields() : StepFields());
        last = s;
        RunOutput::stop_point();
        if (s.stage == Stage::voltage)
          for (const double x : s.voltages)
            highest_voltage = std::max(highest_voltage, std::abs(x));
        newton_iterations_of_steps += s.newton_iterations;
        if (shown(s))
          print_row(s);
      }

      /// Output/Step rows: whether the row of @p s is printed. progress: the
      /// rows before the drive, then one each time t passes another
      /// twentieth of the waveform's end time.
      bool shown(const StepSummary &s)
      {
        if (p.output.step_rows != StepRows::progress)
          return p.output.step_rows == StepRows::every;
        const double t = column(s, summary_column::waveform_time);
        if (s.stage != Stage::voltage || !(t >= next_row_time))
          return s.stage != Stage::voltage;
        const double interval = run.settings.waveform.end_time() / 20.;
        next_row_time         = (std::floor(t / interval) + 1.) * interval;
        return true;
      }

      void print_row(const StepSummary &s) const
      {
        std::ostringstream v;
        for (const double x : s.voltages)
          v << cell(summary_column::voltage.in_file_units(x), 3, 7);
        std::cout << std::setw(6) << stream->n_steps() - 1 << std::setw(12)
                  << (s.stage == Stage::voltage ? "time" : stage_name(s.stage))
                  << cell(column(s, summary_column::waveform_time), 4, 11) << v.str()
                  << cell(mm(s.displacement), 5, 12) << cell(mm(s.stroke), 5, 12)
                  << cell(column(s, summary_column::level_drop), 3, 11)
                  << cell(column(s, summary_column::disk_velocity), 2, 11)
                  << cell(s.s2_min / scene.material.shear_modulus, 4, 11) << ' ' << std::setw(4)
                  << s.newton_iterations << '\n';
      }

      /// A run whose rings stayed at 0 V at every time step has shown nothing
      /// of the drive: say so rather than end with a stroke of 0 as if the
      /// film had not moved under it.
      void report_a_drive_that_never_rose() const
      {
        if (highest_voltage > 0. || stepper.time() <= 0.)
          return;
        std::cerr << "cdea: warning: the drive never rose: every ring was at 0 V at every time "
                     "step (waveform peak "
                  << format_kV(run.settings.waveform.peak()) << ")\n";
      }

      void print_final_state(const RunResult &result, const double seconds) const
      {
        std::cout << "\nFinal state: t = " << format_number(stepper.time(), 8) << " s, voltages "
                  << format_kV(last.voltages) << ", displacement "
                  << format_number(mm(last.displacement), 8) << " mm, stroke "
                  << number_or_dash(mm(last.stroke), 8) << " mm, level drop "
                  << number_or_dash(column(last, summary_column::level_drop), 6) << " mm\n"
                  << "  energy since t = 0: electrical work "
                  << number_or_dash(column(last, summary_column::electrical_work), 6) << " mJ, stored "
                  << number_or_dash(column(last, summary_column::stored_energy_change), 6)
                  << " mJ, dissipated "
                  << number_or_dash(column(last, summary_column::dissipated_energy), 6) << " mJ\n"
                  << "  disk's natural frequency sqrt(k/m) / 2 pi: "
                  << number_or_dash(frequency_start, 4) << " Hz at the start, "
                  << number_or_dash(frequency(), 4) << " Hz at the end\n"
                  << time_integration_line(result) << result.steps << " steps, "
                  << (result.completed ? result.newton_iterations : newton_iterations_of_steps)
                  << " Newton iterations, " << std::setprecision(3) << seconds << " s"
                  << std::endl;
        if (!result.warning.empty())
          std::cerr << "cdea: warning: " << result.warning << '\n';
      }

      /// The time integration's steps, rejections and error estimate (ESDIRK
      /// runs; the fixed-step schemes print as before).
      std::string time_integration_line(const RunResult &result) const
      {
        std::ostringstream line;
        if (std::isnan(result.error_estimate))
          return "";
        line << "  time integration: " << result.time_steps << " steps, "
             << result.rejected_steps << " rejected";
        line << ", estimated error of the disk's position "
               << format_number(mm(result.error_estimate), 3) << " mm (sum of the local "
               << "estimates, " << format_number(result.error_estimate / std::max(std::abs(last.displacement), 1e-300), 3)
               << " of the displacement)";
        line << '\n';
        return line.str();
      }
    };
  } // namespace

  TimeRunSetup set_up_time_run(const Parameters &p, const Scene &scene)
  {
    TimeRunSetup run;
    run.settings = time_settings(p, scene);
    run.model    = make_fe_model(p, scene);
    run.stepper =
      std::make_unique<TimeStepper>(scene, *run.model, stepping_settings(p), run.settings);
    add_run_postprocessors(*run.stepper, p, scene);
    run.root_attributes = {{run_attribute::material_model.name, p.material_law.model},
                           {run_attribute::waveform.name, to_string(p.time.waveform)},
                           {run_attribute::time_scheme.name, to_string(p.time.scheme)}};
    if (esdirk_tableau(run.settings.method))
      run.root_attributes.push_back(
        {run_attribute::time_step_control.name, to_string(step_control_of(run.settings))});
    return run;
  }

  RunRecord time_run_in_memory(const RunInput &input)
  {
    TimeRunSetup run     = set_up_time_run(input.parameters, input.scene);
    TimeStepper &stepper = *run.stepper;
    RunRecord    record;
    record.method          = RunMethod::finite_elements_in_time;
    record.root_attributes = run.root_attributes;
    record.time_run        = true;
    record.n_rings         = input.scene.n_rings();
    record.parameters      = input.text;
    record.results_path    = input.parameters.results_path();
    // The run's product stream, as the command's file gets it.
    RunStream stream(record, record.n_rings, time_run);
    stream.start();
    stepper.on_step = [&](const StepSummary &s) {
      stream.step(s, stepper.fields_wanted() ? stepper.step_fields() : StepFields());
    };
    stepper.on_onset = [&](const OnsetRecord &onset) { stream.onset(onset); };
    run_keeping_steps(record, [&] { return stepper.run(); });
    stream.time_integration(record.result.time_steps, record.result.rejected_steps,
                            record.result.error_estimate);
    return record;
  }

  int run_time(const RunInput &input)
  {
    TimeRun run(input);
    return run.go();
  }
} // namespace cdea
