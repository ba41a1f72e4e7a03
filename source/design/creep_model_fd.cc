// TEMPORARY: creep_with_sensitivities() (analysis/creep_sensitivity.h) with a
// finite-difference Jacobian, so that the creep fit runs until the engine of
// exact forward sensitivities through time (branch creepsens) is merged;
// drop this file then. Each column is a forward difference of the whole time
// run with a relative step of 1e-6 (the runs take the same steps when the
// waveform's knots and Time/Step control = fixed set them), and the
// displacement at a sample time is interpolated linearly between the steps
// around it.

#include <cdea/analysis/creep_sensitivity.h>
#include <cdea/analysis/time_run.h>
#include <cdea/design/viscous_fit.h>

#include <algorithm>
#include <cmath>

namespace cdea
{
  namespace
  {
    constexpr double relative_step = 1e-6;

    /// The displacements of the time model of @p p at @p times; false with
    /// why in @p message.
    bool displacements_at(const Parameters &p, const std::vector<double> &times,
                          std::vector<double> &d, std::string &message)
    {
      const Scene         scene = p.scene();
      TimeRunSetup        run   = set_up_time_run(p, scene);
      std::vector<double> t_steps, d_steps;
      run.stepper->on_step = [&](const StepSummary &s) {
        if (s.stage != Stage::voltage)
          return;
        t_steps.push_back(s.load_factor);
        d_steps.push_back(s.displacement);
      };
      const RunResult result = run.stepper->run();
      if (!result.completed)
        {
          message = "the time run stops: " + result.message;
          return false;
        }
      d.clear();
      for (const double t : times)
        {
          if (t_steps.empty() || t > t_steps.back() * (1. + 1e-12) + 1e-12)
            {
              message = "the sample time " + std::to_string(t) +
                        " s is after the end of the waveform (Time subsection)";
              return false;
            }
          const auto   after = std::lower_bound(t_steps.begin(), t_steps.end(), t);
          const auto   k     = std::size_t(std::max<std::ptrdiff_t>(after - t_steps.begin(), 1));
          const double t0 = t_steps[k - 1], t1 = t_steps[std::min(k, t_steps.size() - 1)];
          const double d0 = d_steps[k - 1], d1 = d_steps[std::min(k, t_steps.size() - 1)];
          const double f  = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0., 1.) : 1.;
          d.push_back(t <= t0 ? d0 : d0 + f * (d1 - d0));
        }
      return true;
    }
  } // namespace

  bool creep_with_sensitivities(const Parameters &p, const std::vector<LawParameter> &parameters,
                                const std::vector<double> &sample_times, CreepSensitivity &out,
                                std::string &message)
  {
    out.times = sample_times;
    if (!displacements_at(p, sample_times, out.displacement, message))
      return false;
    out.jacobian.resize(Eigen::Index(sample_times.size()), Eigen::Index(parameters.size()));
    for (std::size_t j = 0; j < parameters.size(); ++j)
      {
        Parameters   shifted = p;
        const double value   = law_parameter_value(p, parameters[j]);
        const double h       = relative_step * (value != 0. ? std::abs(value) : 1.);
        set_law_parameter(shifted, parameters[j], value + h);
        std::vector<double> d;
        if (!displacements_at(shifted, sample_times, d, message))
          return false;
        for (std::size_t i = 0; i < d.size(); ++i)
          out.jacobian(Eigen::Index(i), Eigen::Index(j)) = (d[i] - out.displacement[i]) / h;
      }
    return true;
  }
} // namespace cdea
