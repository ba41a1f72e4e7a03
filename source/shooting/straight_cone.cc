#include <cdea/material/gent_dielectric.h>
#include <cdea/numerics/bracketed_root.h>
#include <cdea/numerics/dormand_prince.h>
#include <cdea/shooting/straight_cone.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cdea::shooting
{
  namespace
  {
    constexpr double none = std::numeric_limits<double>::quiet_NaN();
    constexpr double pi   = 3.14159265358979323846;

    using Integrator = DormandPrince45<1>;

    /// The film of one scene along a straight cone.
    class ConeFilm
    {
    public:
      explicit ConeFilm(const Scene &scene)
        : scene(scene)
        , law(scene.material, 0.)
        , H(scene.material.thickness)
        , eps(scene.material.permittivity)
        , F(scene.dead_load())
      {}

      double theta(const double C) const { return std::atan(F / (2. * pi * H * C)); }

      /// sigma = s1 - s2 l2 / l1: the meridian stress once the voltage has
      /// cancelled s2.
      double sigma(const double l1, const double l2) const
      {
        const NominalStress s = law.stress(l1, l2);
        return s.s1 - s.s2 * l2 / l1;
      }

      /// l1 with sigma(l1, l2) = T: scanned up from 1 in factors of 1.05
      /// (sigma grows with l1 there), then the bracketed root; NaN beyond the
      /// Gent limit.
      double meridian_stretch(const double l2, const double T) const
      {
        double lo = 1., hi = 1.;
        while (law.gent_margin(hi * 1.05, l2) > 0. && sigma(hi, l2) < T)
          lo = hi, hi *= 1.05;
        if (!(sigma(hi, l2) >= T) || !(sigma(lo, l2) <= T))
          return none;
        BracketedRootSettings settings;
        settings.x_tolerance = 1e-14;
        return find_bracketed_root([&](const double l1) { return sigma(l1, l2) - T; }, lo,
                                   sigma(lo, l2) - T, hi, sigma(hi, l2) - T, settings)
          .x;
      }

      /// The voltage that makes s2 = 0 at (l1, l2): e l1^2 l2 = s2_el.
      double voltage(const double l1, const double l2) const
      {
        const double s2 = law.stress(l1, l2).s2;
        return H * std::sqrt(std::max(s2, 0.) / (eps * l1 * l1 * l2));
      }

      /// r(B) - b for the tension @p C (NaN if the meridian leaves the law's
      /// range); the largest voltage met into @p max_voltage, each accepted
      /// step's dense output to @p observe.
      template <typename Observer>
      double shoot(const double C, double &max_voltage, Observer &&observe) const
      {
        const double cos_theta = std::cos(theta(C));
        const auto   rhs = [&](const double R, const Integrator::State &y, Integrator::State &dy) {
          const double l2 = y[0] / R;
          const double l1 = meridian_stretch(l2, C / (R * cos_theta));
          if (!std::isfinite(l1))
            return false;
          dy[0]       = l1 * cos_theta;
          max_voltage = std::max(max_voltage, voltage(l1, l2));
          return true;
        };
        Integrator::Control control;
        control.rtol = control.atol = 1e-12;
        const auto r = Integrator(control).integrate(rhs, scene.inner_reference_radius(),
                                                     scene.outer_reference_radius(),
                                                     Integrator::State(scene.disk_radius), 0.,
                                                     observe);
        return r.ok ? r.y[0] - scene.frame_radius : none;
      }

      const Scene         &scene;
      const GentDielectric law;
      const double         H, eps, F;
    };

    /// The voltages at @p sample_R along the cone of tension @p C, from the
    /// dense output of its integration.
    std::vector<double> sampled_voltages(const ConeFilm &film, const double C,
                                         const std::vector<double> &sample_R)
    {
      std::vector<double> voltages(sample_R.size(), none);
      const double        cos_theta = std::cos(film.theta(C));
      double              unused    = 0.;
      film.shoot(C, unused, [&](const Integrator::DenseStep &step, double, const auto &) {
        for (std::size_t i = 0; i < sample_R.size(); ++i)
          {
            const double R = sample_R[i];
            if (R < step.x0 || R > step.x0 + step.h)
              continue;
            const double l2 = step(R)[0] / R;
            const double l1 = film.meridian_stretch(l2, C / (R * cos_theta));
            voltages[i]     = film.voltage(l1, l2);
          }
      });
      return voltages;
    }
  } // namespace

  StraightCone straight_cone(const Scene &scene, const std::vector<double> &sample_R)
  {
    const ConeFilm film(scene);
    double         max_voltage = 0.;
    const auto     ignore      = [](const auto &, double, const auto &) {};
    const auto     shoot = [&](const double C) { return film.shoot(C, max_voltage, ignore); };
    // The tension C: scanned in factors of 1.2 for a sign change of r(B) - b.
    double c0 = 1., f0 = shoot(c0);
    for (double c1 = 1.2; c1 < 1e4; c1 *= 1.2)
      {
        const double f1 = shoot(c1);
        if (std::isfinite(f0) && std::isfinite(f1) && (f0 < 0.) != (f1 < 0.))
          {
            BracketedRootSettings settings;
            settings.x_tolerance = 1e-13 * c1;
            StraightCone cone;
            cone.tension = find_bracketed_root(shoot, c0, f0, c1, f1, settings).x;
            max_voltage  = 0.;
            shoot(cone.tension);
            cone.ok           = true;
            cone.theta        = film.theta(cone.tension);
            cone.displacement = std::tan(cone.theta) * (scene.frame_radius - scene.disk_radius);
            cone.max_voltage  = max_voltage;
            cone.sample_R     = sample_R;
            cone.sample_voltage = sampled_voltages(film, cone.tension, sample_R);
            return cone;
          }
        c0 = c1;
        f0 = f1;
      }
    return {};
  }
} // namespace cdea::shooting
