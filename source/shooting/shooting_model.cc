#include <cdea/shooting/shooting_model.h>
#include <cdea/shooting/shooting_solver.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace cdea::shooting
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    MeridianLoad meridian_load(const LoadState &load)
    {
      return {load.stretch, load.force, load.voltages};
    }

    bool uniform(const std::vector<double> &v)
    {
      for (const double x : v)
        if (x != v.front())
          return false;
      return true;
    }
  } // namespace

  ShootingModel::ShootingModel(const Scene &scene, const ShootingOptions &options)
    : sc(scene)
    , integrator(scene, options)
  {
    set_reference_state();
  }

  void ShootingModel::set_options(const ShootingOptions &options)
  {
    integrator = MeridianIntegrator(sc, options);
  }

  void ShootingModel::set_reference_state()
  {
    LoadState load;
    load.stage    = Stage::prestretch;
    load.stretch  = 1.;
    load.voltages.assign(sc.n_rings(), 0.);
    current = {Kind::homogeneous, load, 0, rebuild(Kind::homogeneous, load, 0., 1.)};
    stats   = {};
  }

  Profile ShootingModel::rebuild(const Kind kind, const LoadState &load,
                                 const double theta0, const double lambda1_start) const
  {
    if (kind == Kind::homogeneous)
      return integrator.homogeneous(meridian_load(load), true);
    return integrator.integrate(meridian_load(load), theta0, lambda1_start, true);
  }

  SolveReport ShootingModel::solve(const LoadState &load_in)
  {
    const auto  t_start = std::chrono::steady_clock::now();
    SolveReport report;
    LoadState   load = load_in;
    if (load.voltages.empty())
      load.voltages.assign(sc.n_rings(), 0.);
    stats = {};

    ShootingSolution sol;
    Kind             kind = Kind::homogeneous;
    if (load.voltages.size() != sc.n_rings())
      sol.message = "the load has " + std::to_string(load.voltages.size()) +
                    " voltages for " + std::to_string(sc.n_rings()) + " rings";
    else if (!(load.force >= 0.) || !std::isfinite(load.force))
      sol.message = "the dead load must be finite and >= 0";
    else if (load.force == 0. && uniform(load.voltages))
      {
        sol.profile   = integrator.homogeneous(meridian_load(load), true);
        sol.converged = sol.profile.ok;
        sol.message   = sol.profile.message;
      }
    else if (load.force == 0.)
      {
        kind = Kind::flat;
        const double guess = current.kind == Kind::cone ? load.stretch :
                                                          current.profile.lambda1_start;
        sol = solve_flat(integrator, meridian_load(load), guess, true);
      }
    else
      {
        kind = Kind::cone;
        double theta0 = current.profile.theta0;
        double l1     = current.profile.lambda1_start;
        if (current.kind != Kind::cone)
          {
            // Linearised tensioned membrane: R s0 theta = F / (2 pi H).
            const double c  = load.force / (2. * pi * sc.material.thickness *
                                           sc.inner_reference_radius());
            const double s0 = integrator.equibiaxial_stress(load.stretch, load.voltages[0]);
            theta0          = s0 > 0. ? std::atan(c / s0) : 0.25 * pi;
            l1              = load.stretch;
          }
        sol = solve_cone(integrator, meridian_load(load), theta0, l1, true);
      }

    stats.root_iterations = sol.integrations;
    stats.rhs_evaluations = sol.rhs_evaluations;
    if (sol.converged)
      {
        stats.rhs_evaluations_per_integration = sol.profile.rhs_evaluations;
        stats.accepted_steps                  = sol.profile.accepted_steps;
        current = {kind, load, sol.integrations, std::move(sol.profile)};
      }
    report.converged  = sol.converged;
    report.iterations = sol.integrations;
    report.message    = sol.converged ? std::string() : "shooting: " + sol.message;
    stats.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    return report;
  }

  double ShootingModel::displacement() const { return current.profile.displacement; }

  HoopStresses ShootingModel::hoop_stresses() const
  {
    HoopStresses h;
    h.s2_min        = current.profile.s2_min;
    h.s2_min_radius = current.profile.s2_min_radius;
    h.s2_ring_inner = current.profile.s2_ring_inner;
    return h;
  }

  StepFields ShootingModel::fields() const
  {
    return current.profile.samples;
  }

  double ShootingModel::enclosed_volume() const
  {
    // 5-point Gauss-Legendre on [0, 1]: exact for r^2 z' with cubic r and z.
    static const double xg[5] = {0.04691007703066800, 0.23076534494715845, 0.5,
                                 0.76923465505284155, 0.95308992296933200};
    static const double wg[5] = {0.11846344252809454, 0.23931433524968324,
                                 0.28444444444444444, 0.23931433524968324,
                                 0.11846344252809454};
    const StepFields &f = current.profile.samples;
    double            v = 0.;
    for (std::size_t i = 0; i + 1 < f.R.size(); ++i)
      {
        const double h = f.R[i + 1] - f.R[i];
        if (!(h > 0.)) // the two sides of a ring edge
          continue;
        const double r0 = f.r[i], r1 = f.r[i + 1], z0 = f.z[i], z1 = f.z[i + 1];
        const double dr0 = h * f.lambda1[i] * std::cos(f.theta[i]);
        const double dr1 = h * f.lambda1[i + 1] * std::cos(f.theta[i + 1]);
        const double dz0 = -h * f.lambda1[i] * std::sin(f.theta[i]);
        const double dz1 = -h * f.lambda1[i + 1] * std::sin(f.theta[i + 1]);
        for (unsigned int q = 0; q < 5; ++q)
          {
            const double t = xg[q], s = 1. - t;
            // Cubic Hermite basis on [0, 1] and its derivative.
            const double r = r0 * s * s * (1. + 2. * t) + r1 * t * t * (3. - 2. * t) +
                             dr0 * t * s * s - dr1 * t * t * s;
            const double dz = 6. * t * s * (z1 - z0) + dz0 * s * (1. - 3. * t) +
                              dz1 * t * (3. * t - 2.);
            v -= wg[q] * pi * r * r * dz; // dz is dz/dt = h z'
          }
      }
    return v;
  }

  ShootingModel::Kind ShootingModel::kind_of(const LoadState &load)
  {
    if (load.force != 0.)
      return Kind::cone;
    return uniform(load.voltages) ? Kind::homogeneous : Kind::flat;
  }

  void ShootingModel::predict(const ModelState &older, const double factor)
  {
    if (older.unknowns.size() != 2 || current.kind != Kind::cone ||
        kind_of(older.load) != Kind::cone)
      return;
    current.profile.theta0 += factor * (current.profile.theta0 - older.unknowns[0]);
    current.profile.lambda1_start += factor * (current.profile.lambda1_start - older.unknowns[1]);
  }

  ModelState ShootingModel::state() const
  {
    return {current.load, {current.profile.theta0, current.profile.lambda1_start}, {}};
  }

  void ShootingModel::set_state(const ModelState &s)
  {
    if (s.unknowns.size() != 2 || s.load.voltages.size() != sc.n_rings())
      throw std::invalid_argument("ShootingModel::set_state: not a state of this model");
    Current c;
    c.load    = s.load;
    c.kind    = kind_of(s.load);
    c.profile = rebuild(c.kind, c.load, s.unknowns[0], s.unknowns[1]);
    if (!c.profile.ok)
      throw std::runtime_error("ShootingModel::set_state: " + c.profile.message);
    current = std::move(c);
  }
} // namespace cdea::shooting
