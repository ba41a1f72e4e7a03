#include <cdea/analysis/periodic_steady_state.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/input/solver_settings.h>
#include <cdea/model/load_state.h>
#include <cdea/numerics/periodic_signal.h>
#include <cdea/numerics/step_control.h>
#include <cdea/solver/esdirk_step.h>
#include <cdea/solver/load_stepper.h>
#include <cdea/solver/time_stepper.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cdea
{
  double SteadyPeriod::energy_defect() const
  {
    return std::abs(electrical_work - dissipated - stored_change) / std::abs(dissipated);
  }

  Waveform periodic_waveform(const Parameters &p, const Scene &scene, const double frequency,
                             const double low_fraction)
  {
    const std::vector<double> peak = scene.path.voltages(scene.path.n_segments());
    if (p.time.waveform == WaveformKind::sine)
      return Waveform::sine(peak, frequency, 1, low_fraction);
    if (p.time.waveform == WaveformKind::square)
      {
        if (!(p.time.rise_time_s < 0.5 / frequency))
          throw InputError("Time/Rise time (s) (" + format_number(p.time.rise_time_s) +
                           ") must be below half the period at " + format_number(frequency) +
                           " Hz for a square wave");
        return Waveform::square(peak, frequency, 1, p.time.rise_time_s, low_fraction);
      }
    throw InputError("Time/Waveform must be sine or square (periodic) for a periodic steady "
                     "state, got " + to_string(p.time.waveform));
  }

  namespace
  {
    using Vec = Eigen::VectorXd;

    /// The states of one period at the step ends (the first is t = 0).
    struct PeriodRecord
    {
      std::vector<double> t, z, v, V, s2;
      Vec                 y_lo, y_hi; ///< the state vector's extremes over the period
      double              work = 0., dissipated = 0., stored_start = 0., stored_end = 0.;
    };

  } // namespace

  class PeriodicSteadyState::Impl
  {
  public:
    Impl(const Parameters &p, const Scene &scene, const SteadyStateSettings &s)
      : p(p)
      , scene(scene)
      , settings(s)
      , time(time_settings(p, scene))
    {
      if (!esdirk_tableau(time.method))
        time.method = TimeMethod::esdirk4;
      time.rest_time = std::numeric_limits<double>::infinity();
    }

    SteadyPeriod solve(double frequency);
    double       quasi_static_amplitude();

  private:
    const Parameters                  p;
    const Scene                       scene;
    const SteadyStateSettings         settings;
    TimeSettings                      time;
    Waveform                          waveform;
    double                            period = 0.;
    std::unique_ptr<MembraneModel>    model;
    std::unique_ptr<EsdirkStep>       step;
    TimePoint                         base; ///< the template of lifted states
    std::vector<double>               steps; ///< the frozen step sequence
    Vec                               scale;
    unsigned int                      maps = 0;
    double qs_amplitude = std::numeric_limits<double>::quiet_NaN();

    bool   inertia() const { return time.inertia; }
    bool   water() const { return time.inertia && time.column.present(); }
    unsigned int n_motion() const { return (inertia() ? 2 : 0) + (water() ? 2 : 0); }
    void   start(double frequency);
    void   relaxed_equilibrium(MembraneModel &m, const std::vector<double> &voltages) const;
    Vec    pack(const TimePoint &point) const;
    void   set_evolving(const Vec &x, std::vector<double> &internal) const;
    TimePoint lift(const Vec &x);
    Vec    map(const Vec &x, bool adapt, PeriodRecord *record);
    double stored_energy(const TimePoint &point) const;
    void   set_scale(const PeriodRecord &record, const Vec &x);
    double defect(const Vec &d) const { return (d.array() / scale.array()).abs().maxCoeff(); }
    bool   krylov(const Vec &x, const Vec &fx, const Vec &b, Vec &dx, unsigned int &its);
    void   evaluate(const PeriodRecord &record, SteadyPeriod &out) const;
    bool   newton(Vec &x, SteadyPeriod &out, PeriodRecord &record);
  };

  // The relaxed equilibrium (film relaxed: network B carries nothing) at
  // the voltages of the waveform's start, reached along the voltage path to
  // its peak and from there in 20 steps; the ESDIRK step of the period maps.
  void PeriodicSteadyState::Impl::start(const double frequency)
  {
    waveform = periodic_waveform(p, scene, frequency, settings.low_fraction);
    period   = 1. / frequency;
    model    = make_fe_model(p, scene);
    relaxed_equilibrium(*model, waveform.voltages(0.));
    if (model->has_internal_variables())
      model->relax_internal_variables();
    model->set_time_step(0., TimeScheme::backward_euler);
    step = make_esdirk_step(*model, scene, time, waveform);
    base          = TimePoint();
    base.state    = model->state();
    base.motion.z = model->disk_position();
    base.motion.V = model->enclosed_volume();
    steps.clear();
  }

  // The voltage path followed quasi-statically with the material relaxed,
  // then the voltages moved to @p voltages in 20 steps.
  void PeriodicSteadyState::Impl::relaxed_equilibrium(MembraneModel             &m,
                                                      const std::vector<double> &voltages) const
  {
    const double relaxed = std::numeric_limits<double>::infinity();
    m.set_time_step(relaxed, TimeScheme::backward_euler);
    LoadStepper     stepper(scene, m, study_stepping_settings(p));
    const RunResult run = stepper.run();
    if (!run.completed)
      throw std::runtime_error("no equilibrium at the end of the voltage path: " + run.message);
    const std::vector<double> peak = scene.path.voltages(scene.path.n_segments());
    if (voltages == peak)
      return;
    for (unsigned int k = 1; k <= 20; ++k)
      {
        std::vector<double> v = peak;
        for (std::size_t i = 0; i < v.size(); ++i)
          v[i] += (voltages[i] - peak[i]) * k / 20.;
        m.set_time_step(relaxed, TimeScheme::backward_euler);
        if (!m.solve(full_load(scene, v)).converged)
          throw std::runtime_error("no relaxed equilibrium at the voltages " + format_kV(v));
      }
  }

  Vec PeriodicSteadyState::Impl::pack(const TimePoint &point) const
  {
    const MembraneLaw &law = model->material_law();
    const unsigned int n = law.n_internal_variables(), ne = law.n_evolving();
    const std::size_t  points = (n == 0 || ne == 0) ? 0 : point.state.internal.size() / n;
    Vec                x(n_motion() + points * ne);
    unsigned int       i = 0;
    if (inertia())
      {
        x[i++] = point.motion.z;
        x[i++] = point.motion.v;
      }
    if (water())
      {
        x[i++] = point.motion.V;
        x[i++] = point.motion.V_dot;
      }
    std::vector<double> rate(ne);
    for (std::size_t k = 0; k < points; ++k, i += ne)
      law.evolving_state(point.state.internal.data() + k * n, x.data() + i, rate.data());
    return x;
  }

  void PeriodicSteadyState::Impl::set_evolving(const Vec &x, std::vector<double> &internal) const
  {
    const MembraneLaw &law = model->material_law();
    const unsigned int n = law.n_internal_variables(), ne = law.n_evolving();
    if (n == 0 || ne == 0)
      return;
    for (std::size_t k = 0, i = n_motion(); k * n + n <= internal.size(); ++k, i += ne)
      law.set_evolving_state(x.data() + i, internal.data() + k * n);
  }

  // A consistent start at t = 0 for x: the internal variables set and held,
  // the membrane solved with z (and V) pinned by a stiff inertia term of
  // time delta, whose target is corrected until z equals x's; the pin's force
  // m (z - target) / delta^2 is the disk's m a.
  TimePoint PeriodicSteadyState::Impl::lift(const Vec &x)
  {
    ModelState s = base.state;
    set_evolving(x, s.internal);
    s.load      = full_load(scene, waveform.voltages_on_piece(0., 0.), 0.);
    s.load.time = 0.;
    model->set_state(s);
    model->set_internal_start(s.internal, {}, {}, 0.);
    model->set_time_step(0., TimeScheme::backward_euler);
    const double delta = 1e-4;
    InertiaStep  pin;
    if (inertia())
      {
        pin.dt          = delta;
        pin.beta        = 1.;
        pin.disk_mass   = scene.mass;
        pin.disk_target = x[0];
        pin.residual_scale = 40. * std::numeric_limits<double>::epsilon() / 1e-10 *
                             scene.mass * std::abs(x[0]) / (delta * delta);
      }
    if (water())
      {
        pin.volume_mass   = step->column_mass(x[2]);
        pin.volume_target = x[2];
        pin.volume_start  = x[2];
        pin.volume_reference = x[2];
      }
    for (unsigned int k = 0; k < 6; ++k)
      {
        model->set_inertia(pin);
        const SolveReport solved = model->solve(s.load);
        if (!solved.converged)
          throw std::runtime_error("no equilibrium at the start of the period: " + solved.message);
        if (!inertia())
          break;
        const double dz = x[0] - model->disk_position();
        const double dV = water() ? x[2] - model->enclosed_volume() : 0.;
        if (std::abs(dz) <= 1e-15 * std::abs(x[0]) &&
            std::abs(dV) <= 1e-15 * std::abs(x[2]))
          break;
        pin.disk_target += dz;
        pin.volume_target += dV;
      }
    TimePoint point;
    point.t              = 0.;
    point.state          = model->state();
    point.state.internal = model->internal_now();
    point.motion.z       = model->disk_position();
    if (inertia())
      {
        point.motion.v = x[1];
        point.motion.a = (point.motion.z - pin.disk_target) / (delta * delta);
      }
    if (water())
      {
        point.motion.V      = model->enclosed_volume();
        point.motion.V_dot  = x[3];
        point.motion.V_ddot = (point.motion.V - pin.volume_target) / (delta * delta);
      }
    point.dissipation_rate = model->dissipation_rate();
    point.charges          = model->charges();
    model->accept_time_step();
    model->set_inertia(InertiaStep());
    return point;
  }

  double PeriodicSteadyState::Impl::stored_energy(const TimePoint &point) const
  {
    const EnergyBudget e = model->energy_budget();
    double kinetic       = 0.;
    if (inertia())
      kinetic += 0.5 * scene.mass * point.motion.v * point.motion.v;
    if (water())
      kinetic += 0.5 * step->column_mass(point.motion.V) * point.motion.V_dot * point.motion.V_dot;
    return e.mechanical + e.electrostatic + kinetic;
  }

  // One period from lift(x): with error control (adapt; the steps become
  // the frozen sequence) or on the frozen sequence.
  Vec PeriodicSteadyState::Impl::map(const Vec &x, const bool adapt, PeriodRecord *record)
  {
    ++maps;
    TimePoint point = lift(x);
    step->clear_history();
    StepAcceptance acceptance(esdirk_tableau(time.method)->embedded_order,
                              time.control == TimeStepControl::error,
                              ErrorController::elementary());
    // Error control: steps at most T/32 (Time/Time step (s) is the time
    // runs' cap, below a slow drive's needs); fixed steps: Time/Time step (s).
    const double cap = acceptance.error_control() ? period / 32. :
                                                    std::min(time.max_step, period / 32.);
    auto keep = [&](PeriodRecord &r) {
      r.t.push_back(point.t);
      r.z.push_back(point.motion.z);
      r.v.push_back(point.motion.v);
      r.V.push_back(model->enclosed_volume());
      r.s2.push_back(model->hoop_stresses().s2_min);
      const Vec y = pack(point);
      r.y_lo      = r.y_lo.size() ? Vec(r.y_lo.cwiseMin(y)) : y;
      r.y_hi      = r.y_hi.size() ? Vec(r.y_hi.cwiseMax(y)) : y;
    };
    if (record)
      {
        *record              = PeriodRecord();
        record->stored_start = stored_energy(point);
        keep(*record);
      }
    std::vector<double> chosen;
    double              h = steps.empty() ? cap / 4. : steps.front();
    for (std::size_t i = 0; point.t < period;)
      {
        const double bp = std::min(waveform.next_breakpoint(point.t * (1. + 1e-14)), period);
        if (!adapt)
          h = steps.at(i++);
        else
          {
            h              = std::min(h, cap);
            const double r = bp - point.t;
            h              = r <= h * 1.0001 ? r : (r < 2. * h ? 0.5 * r : h);
          }
        const SolveReport solved = step->take(point, h);
        const double      ratio  = step->error_ratio();
        // The frozen sequence takes every step that converges.
        if (!(adapt ? acceptance.accepts(solved.converged, ratio) : solved.converged))
          {
            if (!adapt || h < time.min_step)
              throw std::runtime_error("the period map failed at t = " + format_number(point.t) +
                                       " s: " + solved.message);
            h *= acceptance.rejected(solved.converged, ratio);
            continue;
          }
        model->accept_time_step();
        model->set_time_step(0., TimeScheme::backward_euler);
        model->set_inertia(InertiaStep());
        const TimePoint from = point;
        point                = step->end();
        point.state          = model->state();
        if (std::abs(point.t - bp) < 1e-12 * period)
          point.t = bp;
        if (!inertia())
          point.motion.v = (point.motion.z - from.motion.z) / h;
        if (record)
          {
            record->work += step->work();
            record->dissipated += step->dissipated();
            keep(*record);
          }
        if (adapt)
          {
            chosen.push_back(h);
            h = acceptance.error_control() ? h * acceptance.accepted(ratio) : cap;
          }
      }
    if (adapt)
      steps = chosen;
    if (record)
      record->stored_end = stored_energy(point);
    return pack(point);
  }

  void PeriodicSteadyState::Impl::set_scale(const PeriodRecord &r, const Vec &x)
  {
    const double w = 2. * M_PI / period;
    scale          = Vec::Constant(x.size(), time.internal_tolerance);
    const auto [z_lo, z_hi] = std::minmax_element(r.z.begin(), r.z.end());
    const double sz = std::max(0.5 * (*z_hi - *z_lo), 1e-12);
    unsigned int i  = 0;
    if (inertia())
      {
        scale[i++] = sz;
        scale[i++] = sz * w;
      }
    if (water())
      {
        const auto [lo, hi] = std::minmax_element(r.V.begin(), r.V.end());
        const double sV     = std::max(0.5 * (*hi - *lo), 1e-18);
        scale[i++]          = sV;
        scale[i++]          = sV * w;
      }
    // The internal variables: the largest half swing of any of them.
    if (i < x.size())
      {
        const double sy = 0.5 * (r.y_hi.tail(x.size() - i) - r.y_lo.tail(x.size() - i)).maxCoeff();
        scale.tail(x.size() - i).setConstant(std::max(sy, time.internal_tolerance));
      }
  }

  // GMRES on (I - dP/dx) dx = b in the scaled variables u = dx / scale,
  // (dP/dx) d by the difference of period maps on the frozen steps.
  bool PeriodicSteadyState::Impl::krylov(const Vec &x, const Vec &fx, const Vec &b, Vec &dx,
                                         unsigned int &its)
  {
    const unsigned int m = settings.max_krylov;
    const double       eps = 1e-6, beta = (b.array() / scale.array()).matrix().norm();
    dx = Vec::Zero(x.size());
    if (!(beta > 0.))
      return true;
    std::vector<Vec> V{(b.array() / scale.array()).matrix() / beta};
    Eigen::MatrixXd  H = Eigen::MatrixXd::Zero(m + 1, m);
    Vec              g = Vec::Zero(m + 1), cs = Vec::Zero(m), sn = Vec::Zero(m);
    g[0]               = beta;
    unsigned int j     = 0;
    bool         done  = false;
    for (; j < m && !done; ++its)
      {
        const Vec d = (V[j].array() * scale.array()).matrix();
        const Vec Jd = (map(x + eps * d, false, nullptr) - fx) / eps;
        Vec       w  = V[j] - (Jd.array() / scale.array()).matrix();
        for (unsigned int pass = 0; pass < 2; ++pass)
          for (unsigned int i = 0; i <= j; ++i)
            {
              const double hij = V[i].dot(w);
              H(i, j) += hij;
              w -= hij * V[i];
            }
        H(j + 1, j) = w.norm();
        V.push_back(H(j + 1, j) > 0. ? Vec(w / H(j + 1, j)) : w);
        for (unsigned int i = 0; i < j; ++i)
          {
            const double a = H(i, j), c = H(i + 1, j);
            H(i, j)        = cs[i] * a + sn[i] * c;
            H(i + 1, j)    = -sn[i] * a + cs[i] * c;
          }
        const double r = std::hypot(H(j, j), H(j + 1, j));
        cs[j]          = H(j, j) / r;
        sn[j]          = H(j + 1, j) / r;
        H(j, j)        = r;
        H(j + 1, j)    = 0.;
        g[j + 1]       = -sn[j] * g[j];
        g[j]           = cs[j] * g[j];
        ++j;
        done = std::abs(g[j]) <= 1e-3 * beta || std::abs(g[j]) <= 0.01 * settings.tolerance;
      }
    const Vec y = H.topLeftCorner(j, j).triangularView<Eigen::Upper>().solve(g.head(j));
    for (unsigned int i = 0; i < j; ++i)
      dx += y[i] * V[i];
    dx = (dx.array() * scale.array()).matrix();
    return done;
  }

  // Newton on P(x) - x on the frozen steps, then the check period with
  // error control; if that moves x by more than the tolerance, Newton goes
  // on with the check's steps.
  bool PeriodicSteadyState::Impl::newton(Vec &x, SteadyPeriod &out, PeriodRecord &record)
  {
    Vec fx = map(x, true, &record);
    set_scale(record, x);
    for (unsigned int it = 0;; ++it)
      {
        out.defect = defect(fx - x);
        if (out.defect <= settings.tolerance)
          {
            const Vec check = map(x, true, &record);
            out.check_move  = defect(check - x);
            if (out.check_move <= settings.tolerance)
              return true;
            fx         = map(x, false, nullptr);
            out.defect = defect(fx - x);
          }
        if (it >= settings.max_newton)
          return false;
        Vec dx;
        krylov(x, fx, fx - x, dx, out.krylov_iterations);
        ++out.newton_iterations;
        // Halve the step while the defect grows (at most three times).
        double lambda = 1.;
        Vec    x_new = x + dx, f_new = map(x_new, false, nullptr);
        for (unsigned int k = 0; k < 3 && defect(f_new - x_new) > out.defect; ++k)
          {
            lambda *= 0.5;
            x_new = x + lambda * dx;
            f_new = map(x_new, false, nullptr);
          }
        x  = x_new;
        fx = f_new;
      }
  }

  // The numbers of the steady period from its record.
  void PeriodicSteadyState::Impl::evaluate(const PeriodRecord &r, SteadyPeriod &out) const
  {
    const std::vector<double> dz = inertia() ? r.v : periodic_derivative(r.t, r.z);
    const auto [z_lo, z_hi]      = extremes(r.t, r.z, dz);
    out.stroke_amplitude         = 0.5 * (z_hi - z_lo);
    const auto [mean, harmonic]  = mean_and_harmonic(r.t, r.z, dz);
    out.mean_displacement        = mean;
    out.first_harmonic           = harmonic;
    const auto [V_lo, V_hi]      = extremes(r.t, r.V, periodic_derivative(r.t, r.V));
    out.volume_swing             = V_hi - V_lo;
    out.electrical_work          = r.work;
    out.dissipated               = r.dissipated;
    out.weight_work              = scene.dead_load() * (r.z.back() - r.z.front());
    out.stored_change            = r.stored_end - r.stored_start;
    out.s2_min                   = *std::min_element(r.s2.begin(), r.s2.end());
    out.loss_of_tension          = out.s2_min < 0.;
    out.steps_per_period         = r.t.size() - 1;
  }

  SteadyPeriod PeriodicSteadyState::Impl::solve(const double frequency)
  {
    const auto   clock_start = std::chrono::steady_clock::now();
    SteadyPeriod out;
    out.frequency = frequency;
    maps          = 0;
    try
      {
        start(frequency);
        Vec x = pack(base);
        for (unsigned int k = 0; k < settings.start_periods; ++k)
          x = map(x, true, nullptr);
        PeriodRecord record;
        out.converged = newton(x, out, record);
        if (!out.converged)
          map(x, true, &record);
        evaluate(record, out);
        if (!out.converged)
          out.message = "no periodic steady state at " + format_number(frequency) +
                        " Hz: the periodicity defect is " + format_number(out.defect, 3) +
                        " (check period " + format_number(out.check_move, 3) +
                        ") after " + std::to_string(out.newton_iterations) +
                        " Newton iterations, above Steady state/Tolerance = " +
                        format_number(settings.tolerance, 3);
      }
    catch (const std::runtime_error &e)
      {
        out.converged = false;
        out.message   = "no periodic steady state at " + format_number(frequency) + " Hz: " +
                      e.what();
      }
    out.period_maps = maps;
    out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    return out;
  }

  // Relaxed equilibria at the peak (the load path) and at the low voltage.
  double PeriodicSteadyState::Impl::quasi_static_amplitude()
  {
    if (!std::isnan(qs_amplitude))
      return qs_amplitude;
    auto                      relaxed = make_fe_model(p, scene);
    const std::vector<double> peak    = scene.path.voltages(scene.path.n_segments());
    relaxed_equilibrium(*relaxed, peak);
    const double        z_peak = relaxed->disk_position();
    std::vector<double> low    = peak;
    for (double &v : low)
      v *= settings.low_fraction;
    relaxed_equilibrium(*relaxed, low);
    qs_amplitude = 0.5 * std::abs(z_peak - relaxed->disk_position());
    return qs_amplitude;
  }

  PeriodicSteadyState::PeriodicSteadyState(const Parameters &p, const Scene &scene,
                                           const SteadyStateSettings &settings)
    : impl(std::make_unique<Impl>(p, scene, settings))
  {}

  PeriodicSteadyState::~PeriodicSteadyState() = default;

  SteadyPeriod PeriodicSteadyState::solve(const double frequency) { return impl->solve(frequency); }

  double PeriodicSteadyState::quasi_static_amplitude() { return impl->quasi_static_amplitude(); }
} // namespace cdea
