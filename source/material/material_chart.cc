#include <cdea/base/format.h>
#include <cdea/material/linear_response.h>
#include <cdea/material/material_chart.h>
#include <cdea/material/membrane_law.h>
#include <cdea/numerics/bracketed_root.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cdea
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// The law at (l1, l2), zero voltage, with the internal variables in
    /// equilibrium with (l1, l2) (relaxed) or with the undeformed state
    /// (instantaneous), held there (dt = 0).
    bool evaluate_at(const MembraneLaw &law, const double l1, const double l2,
                     const bool instantaneous, const unsigned int request, LawResponse &r)
    {
      const unsigned int  n = law.n_internal_variables();
      std::vector<double> old(n), current(n);
      law.relaxed_internal_variables(instantaneous ? LawInput{1., 1., 0.} : LawInput{l1, l2, 0.},
                                     old.data());
      const InternalStep step{old.data(), current.data(), 0., TimeScheme::backward_euler};
      return law.range_margin(l1, l2) > 0. && law.evaluate({l1, l2, 0.}, step, request, r) &&
             std::isfinite(r.stress.s1) && std::isfinite(r.stress.s2);
    }

    /// s2(L, l2), NaN outside the law's range.
    double transverse_stress(const MembraneLaw &law, const double L, const double l2,
                             const bool instantaneous)
    {
      LawResponse r;
      return evaluate_at(law, L, l2, instantaneous, law_stress, r) ? r.stress.s2 :
                                                                     std::nan("");
    }

    /// The uniaxial l2 at L: s2(L, l2) = 0, bracketed from l2 = L^-1/2 (the
    /// isotropic answer) outwards by steps that double from 1e-9 (which
    /// stay inside the range close to a lock); NaN if no bracket.
    double uniaxial_transverse_stretch(const MembraneLaw &law, const double L,
                                       const bool instantaneous)
    {
      const auto   f    = [&](const double l2) { return transverse_stress(law, L, l2, instantaneous); };
      const double x0   = 1. / std::sqrt(L);
      const double f0   = f(x0);
      if (!std::isfinite(f0))
        return std::nan("");
      if (f0 == 0.)
        return x0;
      // s2 grows with l2: look above x0 if s2 < 0 there, below otherwise.
      const double direction = f0 < 0. ? 1. : -1.;
      double       x1 = x0, f1 = f0;
      for (double d = 1e-9; d < 0.9; d *= 2.)
        {
          x1 = x0 * (1. + direction * d);
          f1 = f(x1);
          if (!std::isfinite(f1))
            return std::nan("");
          if ((f1 > 0.) != (f0 > 0.) || f1 == 0.)
            break;
        }
      if ((f1 > 0.) == (f0 > 0.) && f1 != 0.)
        return std::nan("");
      BracketedRootSettings settings;
      settings.x_tolerance     = 4. * DBL_EPSILON * x0;
      settings.max_evaluations = 200;
      settings.stop_on_failure = true;
      const BracketedRoot root =
        direction > 0. ? find_bracketed_root(f, x0, f0, x1, f1, settings) :
                         find_bracketed_root(f, x1, f1, x0, f0, settings);
      return root.converged ? root.x : std::nan("");
    }

    /// Whether both curves of the path exist at L.
    bool inside(const MembraneLaw &law, const ChartPath path, const double L)
    {
      double s, l2;
      if (!path_stress(law, path, L, false, s, l2))
        return false;
      return law.n_internal_variables() == 0 || path_stress(law, path, L, true, s, l2);
    }

    /// The stretch where the path leaves the law's range, by bisection on
    /// [1, max_stretch]; infinity if it stays inside up to max_stretch.
    double locking_stretch(const MembraneLaw &law, const ChartPath path, const double max_stretch)
    {
      if (inside(law, path, max_stretch))
        return std::numeric_limits<double>::infinity();
      double lo = 1., hi = max_stretch;
      while (hi - lo > 1e-12 * hi)
        {
          const double mid = 0.5 * (lo + hi);
          (inside(law, path, mid) ? lo : hi) = mid;
        }
      return lo;
    }

    /// The uniaxial modulus of a 2 x 2 tangent: s1 at s2 = 0.
    double uniaxial_modulus(const StressTangent &k)
    {
      return k.s11 - k.s12 * k.s12 / k.s22;
    }
  } // namespace

  std::string path_name(const ChartPath path)
  {
    return path == ChartPath::uniaxial ? "uniaxial" : "equibiaxial";
  }

  bool path_stress(const MembraneLaw &law, const ChartPath path, const double L,
                   const bool instantaneous, double &s1, double &l2)
  {
    l2 = path == ChartPath::equibiaxial ? L : uniaxial_transverse_stretch(law, L, instantaneous);
    LawResponse r;
    if (!std::isfinite(l2) || !evaluate_at(law, L, l2, instantaneous, law_stress, r))
      return false;
    s1 = r.stress.s1;
    return true;
  }

  StressStretchCurve stress_stretch_curve(const MembraneLaw &law, const ChartPath path,
                                          const ChartSettings &settings)
  {
    const bool         viscous = law.n_internal_variables() > 0;
    StressStretchCurve c;
    c.path = path;
    if (!inside(law, path, 1.))
      throw std::runtime_error("the law cannot be evaluated at the undeformed state");
    c.locking_stretch = locking_stretch(law, path, settings.max_stretch);
    // Just below the locking stretch (1 % of the way from 1), where the
    // stress is finite but already steep.
    const double end = std::isfinite(c.locking_stretch) ? 1. + 0.99 * (c.locking_stretch - 1.) :
                                                          settings.max_stretch;
    const unsigned int n = std::max(2u, settings.stretch_points);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double L = k + 1 == n ? end : 1. + (end - 1.) * k / (n - 1);
        double       s, l2;
        if (!path_stress(law, path, L, false, s, l2))
          throw std::runtime_error("no " + path_name(path) + " state at stretch " +
                                   format_number(L));
        c.stretch.push_back(L);
        c.nominal_stress.push_back(s);
        c.transverse_stretch.push_back(l2);
        if (viscous)
          {
            if (!path_stress(law, path, L, true, s, l2))
              throw std::runtime_error("no instantaneous " + path_name(path) +
                                       " state at stretch " + format_number(L));
            c.instantaneous_stress.push_back(s);
            c.instantaneous_transverse_stretch.push_back(l2);
          }
      }
    return c;
  }

  double step_modulus(const MembraneLaw &law, const double dt)
  {
    const unsigned int  n = law.n_internal_variables();
    std::vector<double> old(n), current(n);
    law.relaxed_internal_variables({1., 1., 0.}, old.data());
    const InternalStep step{old.data(), current.data(), dt, TimeScheme::backward_euler};
    LawResponse        r;
    if (!law.evaluate({1., 1., 0.}, step, law_stress | law_tangent, r))
      throw std::runtime_error("the law cannot be evaluated at the undeformed state");
    return uniaxial_modulus(r.tangent);
  }

  SmallStrainModuli small_strain_moduli(const MembraneLaw &law)
  {
    SmallStrainModuli m;
    m.instantaneous = step_modulus(law, 0.);
    m.relaxed       = step_modulus(law, std::numeric_limits<double>::infinity());
    // An elastic law has no relaxation time, a spectrum (more than one
    // branch: two evolving variables each) none single.
    if (law.n_internal_variables() == 0 || law.n_evolving() > 2)
      return m;
    const double E_B = m.instantaneous - m.relaxed;
    if (!(E_B > 1e-9 * m.instantaneous) || !(m.relaxed > 0.))
      throw std::runtime_error("the law's small-strain response has no viscous part "
                               "(instantaneous modulus " + format_number(m.instantaneous) +
                               " Pa, relaxed " + format_number(m.relaxed) + " Pa)");
    // E^(1/dt) = E_A + E_B tau / (tau + dt): tau = dt (E - E_A) / (E_A + E_B - E),
    // first at dt = 1 s, then twice at dt = tau (best conditioned).
    double tau = 1.;
    for (int pass = 0; pass < 3; ++pass)
      {
        const double dt = tau, E = step_modulus(law, dt);
        tau             = dt * (E - m.relaxed) / (m.instantaneous - E);
        if (!(tau > 0.) || !std::isfinite(tau))
          throw std::runtime_error("the law's small-strain response is not a standard linear "
                                   "solid (no relaxation time at step " +
                                   format_number(dt) + " s)");
      }
    m.relaxation_time = tau;
    for (const double dt : {tau / 10., 10. * tau})
      {
        const double expected = m.relaxed + E_B * tau / (tau + dt);
        if (!(std::abs(step_modulus(law, dt) - expected) <= 1e-9 * m.instantaneous))
          throw std::runtime_error("the law's small-strain response is not a standard linear "
                                   "solid (one relaxation time)");
      }
    return m;
  }

  void standard_linear_solid(const SmallStrainModuli &m, const double f, double &storage,
                             double &loss)
  {
    const double x = 2. * pi * f * m.relaxation_time, E_B = m.instantaneous - m.relaxed;
    storage        = m.relaxed + E_B * x * x / (1. + x * x);
    loss           = E_B * x / (1. + x * x);
  }

  std::complex<double> complex_modulus(const MembraneLaw &law, const double f)
  {
    const unsigned int  n = law.n_internal_variables();
    std::vector<double> relaxed(n);
    law.relaxed_internal_variables({1., 1., 0.}, relaxed.data());
    InternalLinearization lin;
    if (!law.linearize({1., 1., 0.}, relaxed.data(), lin))
      throw std::runtime_error("the law cannot be linearized at the undeformed state");
    const ComplexTangent c = frequency_tangent(lin, 2. * pi * f);
    return c.s11 - c.s12 * c.s12 / c.s22;
  }

  DmaChart dma_chart(const MembraneLaw &law, const ChartSettings &settings)
  {
    if (law.n_internal_variables() == 0)
      throw std::invalid_argument("dma_chart: an elastic law has no loss");
    DmaChart chart;
    chart.moduli         = small_strain_moduli(law);
    const bool spectrum  = !(chart.moduli.relaxation_time > 0.);
    const unsigned int n = std::max(2u, settings.frequency_points);
    const double       a = std::log10(settings.min_frequency), b = std::log10(settings.max_frequency);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double f = std::pow(10., a + (b - a) * k / (n - 1));
        double       storage, loss;
        if (spectrum)
          {
            const std::complex<double> E = complex_modulus(law, f);
            storage                      = E.real();
            loss                         = E.imag();
          }
        else
          standard_linear_solid(chart.moduli, f, storage, loss);
        chart.frequency.push_back(f);
        chart.storage.push_back(storage);
        chart.loss.push_back(loss);
        chart.loss_factor.push_back(loss / storage);
      }
    return chart;
  }
} // namespace cdea
