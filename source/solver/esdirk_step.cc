#include <cdea/solver/esdirk_step.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cdea
{
  EsdirkStep::EsdirkStep(TransientModel &model, const EsdirkStepSettings &settings,
                         std::function<LoadState(double, double)>           load_at,
                         std::function<std::vector<double>(double, double)> voltage_rates)
    : model(model)
    , settings(settings)
    , load_at(std::move(load_at))
    , voltage_rates(std::move(voltage_rates))
  {}

  SolveReport EsdirkStep::take(const TimePoint &start, const double h)
  {
    return take_stages(start, h);
  }

  SolveReport EsdirkStep::take_stages(const TimePoint &start, const double h)
  {
    // The last accepted step's stages predict this one's.
    if (!stages.empty() && stages.front().t != start.t)
      previous = std::move(stages);
    stages.assign(1, start);
    newton_iterations = stage_solves = 0;
    ratio = z_error = step_work = step_dissipated = 0.;
    for (unsigned int i = 1; i < settings.tableau->stages(); ++i)
      {
        const SolveReport report = solve_stage(i, h);
        if (!report.converged)
          return report;
      }
    estimate_error(h);
    energy(h);
    SolveReport done;
    done.converged  = true;
    done.iterations = newton_iterations;
    return done;
  }

  // The unknowns at time t by Lagrange extrapolation through the three
  // stages nearest to it (of this step and the last), as Newton's guess.
  void EsdirkStep::predict(const double t) const
  {
    std::vector<const TimePoint *> points;
    for (const auto *list : {&previous, &stages})
      for (const TimePoint &p : *list)
        if (std::none_of(points.begin(), points.end(),
                         [&](const TimePoint *q) { return q->t == p.t; }))
          points.push_back(&p);
    std::sort(points.begin(), points.end(), [&](const TimePoint *a, const TimePoint *b) {
      return std::abs(a->t - t) < std::abs(b->t - t);
    });
    points.resize(std::min<std::size_t>(points.size(), 3));
    ModelState guess = stages.front().state;
    std::fill(guess.unknowns.begin(), guess.unknowns.end(), 0.);
    for (std::size_t k = 0; k < points.size(); ++k)
      {
        double weight = 1.;
        for (std::size_t l = 0; l < points.size(); ++l)
          if (l != k)
            weight *= (t - points[l]->t) / (points[k]->t - points[l]->t);
        for (std::size_t i = 0; i < guess.unknowns.size(); ++i)
          guess.unknowns[i] += weight * points[k]->state.unknowns[i];
      }
    model.set_state(guess);
  }

  // The differential variables' stage start (zhat, vhat, Vhat, V'hat) into
  // @p hat and the inertia term that makes the stage solve m a_i = forces.
  InertiaStep EsdirkStep::stage_inertia(const unsigned int i, const double h,
                                        InertiaState &hat) const
  {
    const EsdirkTableau &T = *settings.tableau;
    hat                    = stages.front().motion;
    for (unsigned int j = 0; j < i; ++j)
      {
        const double       w = h * T.a[i][j];
        const InertiaState &m = stages[j].motion;
        hat.z += w * m.v;
        hat.v += w * m.a;
        hat.V += w * m.V_dot;
        hat.V_dot += w * m.V_ddot;
      }
    const double gh = T.gamma * h;
    InertiaStep  s;
    if (settings.disk_mass > 0.)
      {
        s.dt          = gh;
        s.beta        = 1.;
        s.disk_mass   = settings.disk_mass;
        s.disk_target = hat.z + gh * hat.v;
      }
    // The round-off of m (z - z_target) / (gamma h)^2 in z, 4 eps k |z|, ten
    // times below Newton's residual tolerance of 1e-10 (its default) times
    // the scale.
    if (s.dt > 0.)
      s.residual_scale = 40. * std::numeric_limits<double>::epsilon() / 1e-10 *
                         (settings.disk_mass * std::abs(s.disk_target)) / (gh * gh);
    if (settings.column.mass_per_volume() > 0. && column_mass(hat.V) > 0.)
      {
        s.dt                = gh;
        s.beta              = 1.;
        s.volume_mass       = column_mass(hat.V);
        s.volume_reference  = hat.V;
        s.volume_mass_slope = -settings.column.mass_per_volume();
        s.volume_target     = hat.V + gh * hat.V_dot;
        s.volume_start      = hat.V;
      }
    return s;
  }

  SolveReport EsdirkStep::solve_stage(const unsigned int i, const double h)
  {
    const EsdirkTableau &T     = *settings.tableau;
    const TimePoint     &start = stages.front();
    const double         t = start.t + T.c[i] * h, gh = T.gamma * h;
    std::vector<const std::vector<double> *> earlier;
    for (unsigned int j = 0; j < i; ++j)
      earlier.push_back(&stages[j].state.internal);
    InertiaState      hat;
    const InertiaStep inertia = stage_inertia(i, h, hat);
    predict(t);
    model.set_internal_start(start.state.internal, earlier, T.a[i], h);
    model.set_time_step(gh, TimeScheme::backward_euler);
    model.set_inertia(inertia);
    const SolveReport report = model.solve(load_at(t, start.t + 0.5 * h));
    newton_iterations += report.iterations;
    ++stage_solves;
    if (!report.converged)
      return report;

    TimePoint p;
    p.t              = t;
    p.state          = model.state();
    p.state.internal = model.internal_now();
    p.motion         = start.motion;
    p.motion.z       = model.disk_position();
    if (settings.disk_mass > 0.)
      {
        p.motion.v = (p.motion.z - hat.z) / gh;
        p.motion.a = (p.motion.v - hat.v) / gh;
      }
    if (inertia.volume_mass > 0.)
      {
        p.motion.V      = model.enclosed_volume();
        p.motion.V_dot  = (p.motion.V - hat.V) / gh;
        p.motion.V_ddot = (p.motion.V_dot - hat.V_dot) / gh;
      }
    p.dissipation_rate = model.dissipation_rate();
    p.charges          = model.charges();
    stages.push_back(std::move(p));
    if (on_stage)
      on_stage(i, h);
    return report;
  }

  void EsdirkStep::estimate_error(const double h)
  {
    const EsdirkTableau &T   = *settings.tableau;
    const TimePoint     &end = stages.back();
    std::vector<double>  d(T.stages());
    std::vector<const std::vector<double> *> internals;
    InertiaState estimate;
    for (unsigned int j = 0; j < T.stages(); ++j)
      {
        d[j] = T.error_weight(j);
        internals.push_back(&stages[j].state.internal);
        const InertiaState &m = stages[j].motion;
        estimate.z += h * d[j] * m.v;
        estimate.v += h * d[j] * m.a;
        estimate.V += h * d[j] * m.V_dot;
        estimate.V_dot += h * d[j] * m.V_ddot;
      }
    const bool          inertia = settings.disk_mass > 0.;
    std::vector<double> shifted;
    ratio = model.internal_error(internals, d, h, end.state.internal, settings.internal_tolerance,
                                 settings.relative_tolerance, inertia ? nullptr : &shifted);
    const double rtol    = settings.relative_tolerance;
    const double z_scale = settings.displacement_tolerance + rtol * std::abs(end.motion.z);
    const double omega   = settings.angular_frequency;
    if (inertia)
      {
        z_error = estimate.z;
        ratio   = std::max({ratio, std::abs(estimate.z) / z_scale,
                            std::abs(estimate.v) / (z_scale * omega)});
      }
    else if (ratio > 0.)
      {
        z_error = model.disk_position_change(shifted);
        ratio   = std::isfinite(z_error) ? std::max(ratio, std::abs(z_error) / z_scale) :
                                           std::numeric_limits<double>::infinity();
      }
    if (settings.column.mass_per_volume() > 0.)
      {
        const double V_scale =
          settings.displacement_tolerance * settings.column.area + rtol * std::abs(end.motion.V);
        ratio = std::max({ratio, std::abs(estimate.V) / V_scale,
                          std::abs(estimate.V_dot) / (V_scale * omega)});
      }
  }

  void EsdirkStep::energy(const double h)
  {
    const EsdirkTableau &T = *settings.tableau;
    const TimePoint &start = stages.front(), &end = stages.back();
    const double     inside = start.t + 0.5 * h;
    step_work = step_dissipated = 0.;
    for (std::size_t k = 0; k < end.charges.size(); ++k)
      step_work += end.state.load.voltages[k] * end.charges[k] -
                   start.state.load.voltages[k] * start.charges[k];
    for (unsigned int j = 0; j < T.stages(); ++j)
      {
        const TimePoint          &p     = stages[j];
        const std::vector<double> rates = voltage_rates(p.t, inside);
        double                    power = 0.;
        for (std::size_t k = 0; k < p.charges.size(); ++k)
          power += p.charges[k] * rates[k];
        step_work -= h * T.b(j) * power;
        step_dissipated += h * T.b(j) * p.dissipation_rate;
      }
  }
} // namespace cdea
