#include <cdea/numerics/bracketed_root.h>
#include <cdea/numerics/dormand_prince.h>
#include <cdea/shooting/meridian.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace cdea::shooting
{
  namespace
  {
    using Integrator = DormandPrince45<4>;
    using State      = Integrator::State;
    constexpr double pi = 3.14159265358979323846;

    void set(std::string *why, const std::string &text)
    {
      if (why != nullptr)
        *why = text;
    }

    /// Append one sample (x = R/A, y in units of A) to @p f.
    void push_sample(StepFields &f, const ShootingLaw &law, const int ring,
                     const double A, const double x, const State &y)
    {
      const double l1 = y[3];
      const double l2 = y[0] / x;
      const auto   s  = law.stress(l1, l2);
      f.R.push_back(x * A);
      f.r.push_back(y[0] * A);
      f.z.push_back(y[1] * A);
      f.theta.push_back(y[2]);
      f.lambda1.push_back(l1);
      f.lambda2.push_back(l2);
      f.s1.push_back(s.s1);
      f.s2.push_back(s.s2);
      f.E.push_back(law.electric_field(l1, l2));
      f.Phi.push_back(law.voltage());
      f.ring.push_back(ring);
    }

    /// The meridian equations (Guo et al. 2025, eqs. 1-15) in x = R/A on the
    /// ring `ring`: y = (r/A, z/A, theta, l1). States outside the model's
    /// domain are refused, saying why in `fail` (at `fail_x`).
    struct MeridianEquations
    {
      MeridianEquations(const std::vector<ShootingLaw> &law, const bool cone)
        : law(law)
        , cone(cone)
      {}

      const std::vector<ShootingLaw> &law;
      const bool                      cone; ///< under a dead load (theta in (0, pi))
      unsigned int                    ring   = 0;
      std::string                     fail;
      double                          fail_x = 0.;
      std::string                     outside; ///< the message of a state outside the law's range

      /// The reason a state at x is refused (nullptr if it is not), and
      /// there the stresses and tangent of the ring's law.
      const char *refusal(const double x, const State &y, NominalStress &s, StressTangent &t)
      {
        const double th = y[2], l1 = y[3];
        const double l2 = y[0] / x;
        if (!(l1 > 0.) || !(l2 > 0.))
          return "a stretch became non-positive";
        if (!law[ring].respond(l1, l2, s, t))
          {
            outside = law[ring].range_margin(l1, l2) > 0. ? "the law cannot be evaluated" :
                                                            law[ring].limit_reached();
            return outside.c_str();
          }
        if (cone && !(th > 0. && th < pi))
          return "theta left (0, pi)";
        if (!(t.s11 > 0.))
          return "ds1/dlambda1 <= 0 (loss of monotonicity, pull-in)";
        if (cone && !(s.s1 > 0.))
          return "the meridian stress s1 became non-positive";
        return nullptr;
      }

      bool operator()(const double x, const State &y, State &dy)
      {
        fail_x = x;
        NominalStress s{0., 0.};
        StressTangent t{0., 0., 0.};
        if (const char *why = refusal(x, y, s, t))
          {
            fail = why;
            return false;
          }
        const double th = y[2], l1 = y[3];
        const double l2 = y[0] / x;
        const double c = std::cos(th), sn = std::sin(th);
        const double dl2 = (l1 * c - l2) / x;
        dy[0]            = l1 * c;
        dy[1]            = -l1 * sn;
        dy[2]            = cone ? -s.s2 * sn / (s.s1 * x) : 0.;
        dy[3]            = (s.s2 * c - s.s1 - x * t.s12 * dl2) / (x * t.s11);
        return std::isfinite(dy[2]) && std::isfinite(dy[3]);
      }
    };

    /// One integration from the disk edge to the frame, ring by ring, into
    /// a Profile: s1 continuous at each ring edge (eq. 14), the smallest
    /// hoop stress and, on request, m samples per ring.
    class RingByRing
    {
    public:
      RingByRing(const std::vector<ShootingLaw> &law, const std::vector<double> &edges,
                 const double A, const double mu, const Integrator::Control &control,
                 const bool cone, const unsigned int samples, Profile &p)
        : law(law)
        , edges(edges)
        , A(A)
        , mu(mu)
        , control(control)
        , rk(control)
        , equations(law, cone)
        , m(samples)
        , p(p)
      {
        p.s2_min = std::numeric_limits<double>::infinity();
      }

      /// From y at the disk edge to the frame; y is then the state there.
      /// False (p.message says why) if a ring fails.
      bool run(State &y)
      {
        double h = 0.;
        for (unsigned int &ring = equations.ring; ring < law.size(); ++ring)
          if (!enter_ring(y) || !integrate_ring(y, h))
            return false;
        return true;
      }

    private:
      const std::vector<ShootingLaw> &law;
      const std::vector<double>      &edges;
      const double                    A, mu;
      const Integrator::Control       control;
      const Integrator                rk;
      MeridianEquations               equations;
      const unsigned int              m; ///< samples per ring, 0: none
      Profile                        &p;

      /// Keep the smallest hoop stress and where it occurs (x = R/A).
      void note_s2(const double s2, const double x)
      {
        if (s2 < p.s2_min)
          {
            p.s2_min        = s2;
            p.s2_min_radius = x * A;
          }
      }

      /// p.message: @p what, where, and the state @p at there if given.
      bool failed(const std::string &what, const State *at = nullptr)
      {
        const unsigned int ring   = equations.ring;
        const double       fail_x = equations.fail_x;
        std::ostringstream o;
        o << what << " in ring " << ring + 1 << " at R/A = " << fail_x;
        if (at != nullptr)
          {
            const double l1 = (*at)[3], l2 = (*at)[0] / fail_x;
            o << " (l1 = " << l1 << ", l2 = " << l2 << ", theta = " << (*at)[2]
              << law[ring].margin_text(l1, l2)
              << ", ds1/dl1 / mu = " << law[ring].s11(l1, l2) / mu << ")";
          }
        p.message = o.str();
        return false;
      }

      /// At the ring's inner edge: l1 from s1 continuity (eq. 14) past the
      /// first ring, the Gent limit, the hoop stress there.
      bool enter_ring(State &y)
      {
        const unsigned int ring = equations.ring;
        const double       x0   = edges[ring];
        if (ring > 0)
          {
            const double l2     = y[0] / x0;
            const double s1_old = law[ring - 1].stress(y[3], l2).s1;
            std::string  why;
            const auto   l1 = solve_lambda1(law[ring], l2, s1_old, y[3], &why);
            equations.fail_x = x0;
            if (!l1)
              return failed("ring edge: " + why);
            y[3] = *l1;
          }
        if (!(law[ring].range_margin(y[3], y[0] / x0) > 0.))
          {
            equations.fail_x = x0;
            return failed(law[ring].limit_reached());
          }
        const double s2_in = law[ring].plain_stress(y[3], y[0] / x0).s2;
        p.s2_ring_inner.push_back(s2_in);
        note_s2(s2_in, x0);
        return true;
      }

      /// Across the ring from its inner edge, with the first trial step h
      /// (then the one proposed for the next ring).
      bool integrate_ring(State &y, double &h)
      {
        const unsigned int ring = equations.ring;
        const double       x0 = edges[ring], x1 = edges[ring + 1];
        // Uniform samples x0 + j (x1 - x0)/(m - 1), j = 0 .. m-1.
        const auto sample = [&](const unsigned int j) {
          return j == m - 1 ? x1 : x0 + j * (x1 - x0) / (m - 1);
        };
        unsigned int next = 0;
        if (m > 0)
          push_sample(p.samples, law[ring], ring, A, x0, y);
        ++next;
        const auto observe = [&](const Integrator::DenseStep &step, const double x,
                                 const State &ye) {
          note_s2(law[ring].plain_stress(ye[3], ye[0] / x).s2, x);
          if (m == 0)
            return;
          while (next < m - 1 && sample(next) <= x)
            {
              const double xs = sample(next);
              const State  ys = step(xs);
              push_sample(p.samples, law[ring], ring, A, xs, ys);
              note_s2(law[ring].plain_stress(ys[3], ys[0] / xs).s2, xs);
              ++next;
            }
        };
        const auto res = rk.integrate(equations, x0, x1, y, h, observe);
        p.rhs_evaluations += res.rhs_evaluations;
        p.accepted_steps += res.accepted_steps;
        p.rejected_steps += res.rejected_steps;
        if (!res.ok)
          return ring_failed(res);
        y = res.y;
        h = res.h_next;
        if (m > 0)
          push_sample(p.samples, law[ring], ring, A, x1, y);
        return true;
      }

      bool ring_failed(const Integrator::Result &res)
      {
        if (res.domain_failure)
          return failed(equations.fail);
        equations.fail_x = res.x;
        return failed(res.accepted_steps + res.rejected_steps >= control.max_steps ?
                        "too many Runge-Kutta steps" :
                        "the Runge-Kutta step size underflowed (the solution "
                        "turns singular)",
                      &res.y);
      }
    };
  } // namespace

  MeridianIntegrator::MeridianIntegrator(const Scene &scene,
                                         const ShootingOptions &options)
    : sc(scene)
    , opts(options)
    , plain_law(scene.law())
    , A(scene.inner_reference_radius())
  {
    if (!plain_law->serves_every_model())
      throw std::invalid_argument("the shooting model needs an elastic law that states its "
                                  "range (Material/Model = " + scene.material_model + ")");
    for (const double e : scene.reference_ring_edges())
      edges.push_back(e / A);
    edges.front() = 1.;
  }

  std::vector<ShootingLaw> MeridianIntegrator::laws(const MeridianLoad &load) const
  {
    std::vector<ShootingLaw> result;
    for (unsigned int k = 0; k < sc.n_rings(); ++k)
      result.emplace_back(plain_law, sc.material, load.voltages.empty() ? 0. : load.voltages[k],
                          opts.relaxed);
    return result;
  }

  std::string MeridianIntegrator::check_load(const MeridianLoad &load) const
  {
    if (!load.voltages.empty() && load.voltages.size() != sc.n_rings())
      return "the load has " + std::to_string(load.voltages.size()) +
             " voltages for " + std::to_string(sc.n_rings()) + " rings";
    if (!(load.stretch > 0.) || !std::isfinite(load.stretch))
      return "the pre-stretch must be positive";
    if (!(load.force >= 0.) || !std::isfinite(load.force))
      return "the dead load must be finite and >= 0 (the disk is pulled along +F)";
    return {};
  }

  double MeridianIntegrator::equibiaxial_stress(const double stretch,
                                                const double voltage) const
  {
    return ShootingLaw(plain_law, sc.material, voltage, false).stress(stretch, stretch).s1;
  }

  std::optional<double>
  MeridianIntegrator::disk_edge_lambda1(const MeridianLoad &load, const double theta0,
                                        const double guess, std::string *why) const
  {
    const std::string bad = check_load(load);
    if (!bad.empty())
      {
        set(why, bad);
        return std::nullopt;
      }
    if (!(theta0 > 0. && theta0 < pi))
      {
        set(why, "the shooting angle must lie in (0, pi)");
        return std::nullopt;
      }
    // 2 pi A H s1 sin(theta0) = F.
    const double target =
      load.force / (2. * pi * A * sc.material.thickness * std::sin(theta0));
    const ShootingLaw law(plain_law, sc.material, load.voltages.empty() ? 0. : load.voltages[0],
                          opts.relaxed);
    std::string       reason;
    const auto l1 = solve_lambda1(law, load.stretch, target,
                                  guess > 0. ? guess : load.stretch, &reason);
    if (!l1)
      set(why, "disk edge: " + reason);
    return l1;
  }

  Profile MeridianIntegrator::shoot(const MeridianLoad &load, const double theta0,
                                    const double lambda1_guess,
                                    const bool with_samples) const
  {
    std::string why;
    const auto  l1 = disk_edge_lambda1(load, theta0, lambda1_guess, &why);
    if (!l1)
      {
        Profile p;
        p.theta0  = theta0;
        p.message = why;
        return p;
      }
    return integrate(load, theta0, *l1, with_samples);
  }

  Profile MeridianIntegrator::integrate(const MeridianLoad &load, const double theta0,
                                        const double lambda1_start,
                                        const bool   with_samples) const
  {
    Profile p;
    p.theta0        = theta0;
    p.lambda1_start = lambda1_start;
    p.message       = check_load(load);
    const bool cone = load.force > 0.;
    if (p.message.empty() && cone && !(theta0 > 0. && theta0 < pi))
      p.message = "the shooting angle must lie in (0, pi) under a dead load";
    if (p.message.empty() && !cone && theta0 != 0.)
      p.message = "without a dead load the film is flat: theta0 must be 0";
    if (!p.message.empty())
      return p;

    Integrator::Control control;
    control.rtol      = opts.tolerance;
    control.atol      = opts.effective_absolute_tolerance();
    control.max_steps = opts.max_steps_per_ring;
    const auto law    = laws(load);
    State      y(load.stretch, 0., theta0, lambda1_start);
    RingByRing rings(law, edges, A, sc.material.shear_modulus, control, cone,
                     with_samples ? std::max(2u, opts.samples_per_ring) : 0u, p);
    if (!rings.run(y))
      return p;

    // Shift z so that z(B) = 0; the disk then sits at z(A) = -z_end.
    const double z_end = y[1] * A;
    for (double &z : p.samples.z)
      z -= z_end;
    p.r_end        = y[0] * A;
    p.z_disk       = -z_end;
    p.displacement = std::abs(z_end);
    p.ok           = true;
    return p;
  }

  Profile MeridianIntegrator::homogeneous(const MeridianLoad &load,
                                          const bool         with_samples) const
  {
    Profile p;
    p.message = check_load(load);
    if (!p.message.empty())
      return p;
    if (load.force != 0.)
      {
        p.message = "the homogeneous flat state needs F = 0";
        return p;
      }
    const auto law = laws(load);
    for (const auto &l : law)
      if (l.voltage() != law.front().voltage())
        {
          p.message = "the homogeneous flat state needs equal ring voltages";
          return p;
        }
    const double lam = load.stretch;
    if (!(law.front().range_margin(lam, lam) > 0.))
      {
        const std::string limit = plain_law->limit().name;
        p.message = "the pre-stretch is beyond " + (limit.empty() ? "the law's range" : limit);
        return p;
      }
    const double s = law.front().stress(lam, lam).s1;
    p.lambda1_start = lam;
    p.s2_ring_inner.assign(sc.n_rings(), s);
    p.s2_min        = s;
    p.s2_min_radius = A;
    p.r_end         = lam * edges.back() * A;
    p.ok     = true;
    if (with_samples)
      {
        const unsigned int m = std::max(2u, opts.samples_per_ring);
        for (unsigned int k = 0; k < sc.n_rings(); ++k)
          for (unsigned int j = 0; j < m; ++j)
            {
              const double x = j == m - 1 ? edges[k + 1] :
                                            edges[k] + j * (edges[k + 1] - edges[k]) / (m - 1);
              push_sample(p.samples, law[k], k, A, x, State(lam * x, 0., 0., lam));
            }
      }
    return p;
  }
} // namespace cdea::shooting
