// The creep run with forward sensitivities (creep_sensitivity.h): the
// quasi-static start as the time stepper makes it (pre-stretch and weight
// with the film relaxed), then the time steps of the run's scheme with its
// step control, each stage differentiated (fe/time_sensitivity.h).

#include <cdea/analysis/creep_sensitivity.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/base/format.h>
#include <cdea/base/run_control.h>
#include <cdea/fe/time_sensitivity.h>
#include <cdea/input/solver_settings.h>
#include <cdea/model/load_state.h>
#include <cdea/numerics/step_control.h>
#include <cdea/solver/esdirk_step.h>
#include <cdea/solver/load_stepper.h>
#include <cdea/solver/time_stepper.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace cdea
{
  namespace
  {
    /// The stage weights of a fixed-step scheme as one implicit stage:
    /// backward Euler Y = y_n + h f(Y); the trapezoidal rule
    /// Y = y_n + (h/2) K_n + (h/2) f(Y).
    struct FixedStage
    {
      std::vector<double> a_row;
      double              gamma = 1.;
    };

    FixedStage fixed_stage(const TimeMethod method)
    {
      return method == TimeMethod::trapezoidal ? FixedStage{{0.5}, 0.5} : FixedStage{{0.}, 1.};
    }

    TimeScheme dashpot_scheme(const TimeMethod method)
    {
      return method == TimeMethod::trapezoidal ? TimeScheme::trapezoidal :
                                                 TimeScheme::backward_euler;
    }

    /// What the run refuses, as a message (empty: none).
    std::string refusal(const Parameters &p, const TimeSettings &settings,
                        const std::vector<double> &times)
    {
      if (!p.time.enabled)
        return "Time/Enabled must be true for a creep run";
      if (!std::isinf(settings.rest_time))
        return "Time/Rest time before voltage (s) must be 'relaxed' for a creep run with sensitivities (the "
               "film starts relaxed)";
      const double end = settings.waveform.end_time();
      for (std::size_t k = 0; k < times.size(); ++k)
        if (!(times[k] >= 0. && times[k] <= end * (1. + 1e-12)) ||
            (k > 0 && !(times[k] > times[k - 1])))
          return "sample time " + std::to_string(k + 1) + " (" + format_number(times[k]) +
                 " s) must be above the one before and within the waveform's 0 to " +
                 format_number(end) + " s";
      return {};
    }

    class CreepRun
    {
    public:
      CreepRun(const Parameters &p, const std::vector<LawParameter> &parameters,
               const std::vector<double> &times, CreepSensitivity &out)
        : p(p)
        , scene(p.scene())
        , settings(time_settings(p, scene))
        , model(make_fe_model(p, scene))
        , tableau(esdirk_tableau(settings.method))
        , parameters(parameters)
        , times(times)
        , out(out)
      {
        settings.inertia = false;
        settings.column  = LiquidColumn();
      }

      bool run(std::string &message)
      {
        if (!(message = refusal(p, settings, times)).empty() || !start(message))
          return false;
        out.times = times;
        out.displacement.clear();
        out.jacobian.resize(times.size(), parameters.size());
        record(0.);
        const double   t_end = settings.waveform.end_time();
        StepController control(step_control(), initial_step());
        while (next_sample < times.size() && t_now < t_end * (1. - 1e-14) - 1e-14)
          {
            const double breakpoint = std::min({settings.waveform.next_breakpoint(t_now), t_end,
                                                times[next_sample]});
            const double to_go      = breakpoint - t_now;
            const double step       = control.step_towards(to_go);
            const double t_next     = step == to_go ? breakpoint : t_now + step;
            // A stop asked for (SIGINT, SIGTERM, SIGHUP) ends this run at once,
            // so that a fit stops within one step, not one whole evaluation.
            if (const int signal = StopOnSignals::requested())
              return fail(message, "stopped by " + signal_name(signal));
            if (!(t_next - t_now > 0.))
              return fail(message, "the time step is below the resolution of t");
            if (!(tableau ? esdirk_step(control, t_next, message) :
                            fixed_step(control, t_next, message)))
              return false;
          }
        if (next_sample < times.size())
          return fail(message, "the run ended before the last sample time");
        return true;
      }

    private:
      const Parameters                &p;
      const Scene                      scene;
      TimeSettings                     settings;
      std::unique_ptr<MembraneModel>   model;
      const EsdirkTableau             *tableau;
      const std::vector<LawParameter> &parameters;
      const std::vector<double>       &times;
      CreepSensitivity                &out;
      std::unique_ptr<TimeSensitivity> sensitivity;
      std::unique_ptr<EsdirkStep>      esdirk;
      std::unique_ptr<StepAcceptance>  acceptance;
      TimePoint                        point;
      double                           t_now       = 0.;
      std::size_t                      next_sample = 0;
      std::string                      stage_message;
      bool                             stages_ok = true;

      bool fail(std::string &message, const std::string &why) const
      {
        message = "creep run at " + format_number(t_now, 10) + " s: " + why;
        return false;
      }

      StepControlSettings step_control() const
      {
        StepControlSettings s;
        s.max_step     = TimeStepper::largest_step(settings);
        s.min_step     = settings.min_step;
        s.max_cutbacks = settings.max_cutbacks;
        s.after_reject = StepBase::attempted;
        s.after_accept = StepBase::attempted;
        return s;
      }

      double initial_step() const
      {
        return tableau && settings.control == TimeStepControl::error ?
                 0.1 * TimeStepper::largest_step(settings) :
                 TimeStepper::largest_step(settings);
      }

      bool start(std::string &message);
      void set_up_esdirk();
      bool esdirk_step(StepController &control, double t_next, std::string &message);
      bool fixed_step(StepController &control, double t_next, std::string &message);
      void accepted(double t_next);

      /// The displacement and its gradient at every sample time at t.
      void record(const double t)
      {
        while (next_sample < times.size() && times[next_sample] <= t * (1. + 1e-12) + 1e-300)
          {
            Eigen::VectorXd gradient;
            out.displacement.push_back(sensitivity ? sensitivity->displacement(gradient) :
                                                     model->displacement());
            if (sensitivity)
              out.jacobian.row(out.displacement.size() - 1) = gradient.transpose();
            ++next_sample;
          }
      }
    };

    // Pre-stretch and weight at zero voltage with the film relaxed (as
    // TimeStepper::run_quasi_static), then the sensitivities of that start.
    bool CreepRun::start(std::string &message)
    {
      Scene still = scene;
      still.path  = VoltagePath({std::vector<double>(scene.n_rings(), 0.)});
      LoadStepper  stepper(still, *model, stepping_settings(p));
      const TimeScheme scheme = dashpot_scheme(settings.method);
      model->set_inertia(InertiaStep());
      model->set_time_step(std::numeric_limits<double>::infinity(), scheme);
      const RunResult stage = stepper.run();
      if (!stage.completed)
        return fail(message, "the quasi-static start failed: " + stage.message);
      model->relax_internal_variables();
      model->set_time_step(0., scheme);
      if (!model->solve(model->load()).converged)
        return fail(message, "the state at the end of the dead-load stage is no equilibrium");
      model->accept_time_step();
      double peak = 0.;
      for (const double v : settings.waveform.peak())
        peak = std::max(peak, std::abs(v));
      if (!(peak > 0.) &&
          std::find(parameters.begin(), parameters.end(), LawParameter::voltage) != parameters.end())
        return fail(message, "the voltage as a parameter needs a waveform with a peak above 0 V");
      // The sensitivity systems use the stage's tangent, which must be exact
      // (the shear-thinning viscosity's holds eta fixed).
      if (!parameters.empty() && !model->material_law().tangent_is_exact())
        return fail(message, "the sensitivities through time need the material's exact tangent; "
                             "with Material/Viscosity = shear thinning it is not (set it to newtonian to fit)");
      // No parameters: the run alone, with the same steps.
      if (!parameters.empty())
        sensitivity = std::make_unique<TimeSensitivity>(*model, parameters,
                                                        tableau ? tableau->stages() : 2, peak);
      std::string why;
      if (sensitivity && !sensitivity->start_relaxed(why))
        return fail(message, why);
      if (tableau)
        set_up_esdirk();
      return true;
    }

    void CreepRun::set_up_esdirk()
    {
      esdirk     = make_esdirk_step(*model, scene, settings, settings.waveform);
      acceptance = std::make_unique<StepAcceptance>(tableau->embedded_order,
                                                    settings.control == TimeStepControl::error,
                                                    ErrorController::elementary());
      esdirk->on_stage = [this](const unsigned int i, const double h) {
        if (stages_ok && sensitivity)
          stages_ok = sensitivity->stage(i, tableau->a[i], h, tableau->gamma * h, stage_message);
      };
      point                  = TimePoint();
      point.state            = model->state();
      point.motion.z         = model->disk_position();
      point.dissipation_rate = model->dissipation_rate();
      point.charges          = model->charges();
    }

    // An ESDIRK step to t_next, accepted or cut back by its error estimate
    // (StepAcceptance with the elementary controller).
    bool CreepRun::esdirk_step(StepController &control, const double t_next,
                               std::string &message)
    {
      const double      h      = t_next - t_now;
      const SolveReport solved = esdirk->take(point, h);
      if (!stages_ok)
        return fail(message, stage_message);
      if (!acceptance->accepts(solved.converged, esdirk->error_ratio()))
        {
          model->set_state(point.state);
          if (acceptance->reject(control, h, solved.converged, esdirk->error_ratio()))
            return true;
          return fail(message, solved.converged ? "the error control cut the step below its minimum" :
                                                  "no equilibrium: " + solved.message);
        }
      model->accept_time_step();
      model->set_time_step(0., TimeScheme::backward_euler);
      point       = esdirk->end();
      point.state = model->state();
      if (sensitivity)
        sensitivity->accept(tableau->stages() - 1);
      acceptance->accept(control, h, esdirk->error_ratio(), solved.iterations);
      accepted(t_next);
      return true;
    }

    // A step of backward Euler or the trapezoidal rule to t_next.
    bool CreepRun::fixed_step(StepController &control, const double t_next, std::string &message)
    {
      const double     h     = t_next - t_now;
      const ModelState start = model->state();
      model->set_time_step(h, dashpot_scheme(settings.method));
      LoadState load = full_load(scene, settings.waveform.voltages(t_next), t_next);
      load.time      = t_next;
      const SolveReport solved = model->solve(load);
      if (!solved.converged)
        {
          model->set_state(start);
          if (control.reject(h))
            return true;
          return fail(message, "no equilibrium: " + solved.message);
        }
      const FixedStage s = fixed_stage(settings.method);
      std::string      why;
      if (sensitivity && !sensitivity->stage(1, s.a_row, h, s.gamma * h, why))
        return fail(message, why);
      model->accept_time_step();
      model->set_time_step(0., dashpot_scheme(settings.method));
      if (sensitivity)
        sensitivity->accept(1);
      control.accept(h, solved.iterations);
      accepted(t_next);
      return true;
    }

    void CreepRun::accepted(const double t_next)
    {
      t_now = t_next;
      record(t_now);
    }
  } // namespace

  bool creep_with_sensitivities(const Parameters &p, const std::vector<LawParameter> &parameters,
                                const std::vector<double> &sample_times, CreepSensitivity &out,
                                std::string &message)
  {
    try
      {
        CreepRun run(p, parameters, sample_times, out);
        return run.run(message);
      }
    catch (const std::exception &e)
      {
        message = std::string("creep run: ") + e.what();
        return false;
      }
  }
} // namespace cdea
