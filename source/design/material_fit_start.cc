// Starts of a material-test fit from the data (material_fit.h,
// material_test_starts()): the time scales of the histories, the initial
// stiffness and the long-time plateau of the stresses, each as a
// neo-Hookean modulus m = s / g(L) with g the test's neo-Hookean shape.

#include <cdea/design/material_fit.h>
#include <cdea/material/two_network_gent.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// s1 = mu g(L) of the neo-Hookean film in each test (doc/materials.md).
    double shape(const TestKind kind, const double L)
    {
      switch (kind)
        {
          case TestKind::uniaxial:
            return L - 1. / (L * L);
          case TestKind::equibiaxial:
            return L - std::pow(L, -5);
          case TestKind::pure_shear:
            break;
        }
      return L - std::pow(L, -3);
    }

    /// I1 - 3 of the test at stretch L.
    double invariant(const TestKind kind, const double L)
    {
      switch (kind)
        {
          case TestKind::uniaxial:
            return L * L + 2. / L - 3.;
          case TestKind::equibiaxial:
            return 2. * L * L + std::pow(L, -4) - 3.;
          case TestKind::pure_shear:
            break;
        }
      return L * L + 1. / (L * L) - 2.;
    }

    double median(std::vector<double> v)
    {
      if (v.empty())
        return nan;
      std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
      return v[v.size() / 2];
    }

    /// What the starts are made of.
    struct DataScales
    {
      double   short_time = nan, long_time = nan; ///< s
      double   initial = nan, plateau = nan;      ///< neo-Hookean moduli (Pa)
      TestKind plateau_kind    = TestKind::uniaxial;
      double   plateau_stretch = nan;
      double   largest_invariant = 0.; ///< I1 - 3
    };

    /// The median ratio s / g over the first rise of @p t where (L - 1) lies
    /// between 2 % and 20 % of the test's largest (L - 1).
    double initial_modulus(const MaterialTestData &t, const double top)
    {
      std::vector<double> m;
      const std::vector<double> &L = t.history.stretch;
      for (std::size_t i = 1; i < t.size() && L[i] >= L[i - 1]; ++i)
        if (L[i] - 1. >= 0.02 * (top - 1.) && L[i] - 1. <= 0.2 * (top - 1.))
          m.push_back(t.stress[i] / shape(t.history.kind, L[i]));
      return median(m);
    }

    /// The smallest s / g at the end of a hold (three samples or more at one
    /// stretch, away from rest) or, without holds, on loading beyond 10 % of
    /// the largest (L - 1); its stretch into @p at.
    double plateau_modulus(const MaterialTestData &t, const double top, double &at)
    {
      const std::vector<double> &L = t.history.stretch;
      double holds = HUGE_VAL, loading = HUGE_VAL, at_hold = nan, at_loading = nan;
      std::size_t run = 0;
      for (std::size_t i = 1; i < t.size(); ++i)
        {
          const double m    = t.stress[i] / shape(t.history.kind, L[i]);
          const bool   away = L[i] - 1. >= 0.1 * (top - 1.) && L[i] > 1.;
          run               = std::abs(L[i] - L[i - 1]) <= 1e-9 * L[i] ? run + 1 : 0;
          const bool ends   = i + 1 == t.size() || std::abs(L[i + 1] - L[i]) > 1e-9 * L[i];
          if (away && run >= 2 && ends && m < holds)
            holds = m, at_hold = L[i];
          if (away && L[i] > L[i - 1] && m < loading)
            loading = m, at_loading = L[i];
        }
      at = std::isfinite(holds) ? at_hold : at_loading;
      return std::isfinite(holds) ? holds : loading;
    }

    DataScales data_scales(const std::vector<MaterialTestData> &tests)
    {
      DataScales          d;
      std::vector<double> intervals;
      double              longest = 0.;
      for (const MaterialTestData &t : tests)
        {
          const std::vector<double> &time = t.history.time, &L = t.history.stretch;
          for (std::size_t i = 1; i < time.size(); ++i)
            intervals.push_back(time[i] - time[i - 1]);
          longest = std::max(longest, time.back() - time.front());
          const double top = *std::max_element(L.begin(), L.end());
          d.largest_invariant = std::max(d.largest_invariant, invariant(t.history.kind, top));
          if (!(top > 1.))
            continue;
          const double m0 = initial_modulus(t, top);
          if (std::isfinite(m0) && !(m0 <= d.initial))
            d.initial = m0;
          double       at = nan;
          const double m  = plateau_modulus(t, top, at);
          if (std::isfinite(m) && m > 0. && !(m >= d.plateau))
            d.plateau = m, d.plateau_kind = t.history.kind, d.plateau_stretch = at;
        }
      d.short_time = 3. * median(intervals);
      d.long_time  = std::max(longest / 3., 10. * d.short_time);
      if (!std::isfinite(d.plateau))
        d.plateau = d.initial;
      if (!std::isfinite(d.initial) || d.initial < d.plateau)
        d.initial = d.plateau;
      return d;
    }
  } // namespace

  namespace
  {
    /// Branch k (from 1) and whether @p p is its relaxation time; k = 0: no branch constant.
    std::pair<unsigned int, bool> branch_constant(const SceneParameter &p)
    {
      if (p.kind == ParameterKind::law_constant)
        for (unsigned int k = 1; k <= max_viscous_branches; ++k)
          for (const bool is_time : {false, true})
            if (p.entry == branch_constant_entry(k, is_time))
              return {k, is_time};
      return {0, false};
    }

    /// The law's relaxed s / g at the plateau's stretch (its internal
    /// variables in equilibrium: network A of a viscoelastic film).
    double relaxed_modulus(const MembraneLaw &law, const DataScales &d)
    {
      StretchHistory h;
      h.kind = d.plateau_kind;
      h.time = {0.};
      h.stretch = {d.plateau_stretch};
      MaterialPoint       point(law);
      MaterialPointResult r;
      std::string         why;
      if (!point.run(h, {}, r, why))
        return nan;
      return r.stress[0] / shape(d.plateau_kind, d.plateau_stretch);
    }

    /// Start @p s's lean of the branch moduli towards the short (even s) or
    /// long (odd s) times, and its shift of the relaxation times in units of
    /// their spacing: 0, +1/2, -1/2, +1/4, -1/4, ...
    double time_shift(const unsigned int s)
    {
      if (s == 0)
        return 0.;
      const double size = 0.5 / double((s + 1) / 2);
      return s % 2 ? size : -size;
    }
  } // namespace

  std::vector<std::vector<double>> material_test_starts(const Scene &base,
                                                        const std::vector<MaterialTestData> &tests,
                                                        const std::vector<SceneParameter>   &free,
                                                        const unsigned int                   starts)
  {
    const DataScales d   = data_scales(tests);
    const auto       law = base.law();
    const double     m_law = std::isfinite(d.plateau_stretch) ? relaxed_modulus(*law, d) : nan;
    std::vector<unsigned int> times, moduli; // positions in free of branch constants
    for (unsigned int j = 0; j < free.size(); ++j)
      if (const auto [k, is_time] = branch_constant(free[j]); k > 0)
        (is_time ? times : moduli).push_back(j);
    const auto by_branch = [&](unsigned int a, unsigned int b) {
      return branch_constant(free[a]).first < branch_constant(free[b]).first;
    };
    std::sort(times.begin(), times.end(), by_branch);
    std::sort(moduli.begin(), moduli.end(), by_branch);

    std::vector<std::vector<double>> out;
    for (unsigned int s = 0; s < std::max(starts, 1u); ++s)
      {
        std::vector<double> v;
        for (const SceneParameter &p : free)
          v.push_back(parameter_value(base, p));
        double mu_a = base.material.shear_modulus;
        for (unsigned int j = 0; j < free.size(); ++j)
          if (free[j].kind == ParameterKind::shear_modulus && std::isfinite(m_law) && m_law > 0.)
            mu_a = v[j] = base.material.shear_modulus * d.plateau / m_law;
          else if (free[j].kind == ParameterKind::jlim)
            v[j] = std::max(v[j], 2. * d.largest_invariant);
        const double n = double(times.size()), ratio = d.long_time / d.short_time;
        for (std::size_t i = 0; i < times.size(); ++i)
          v[times[i]] = n > 1. ? d.short_time * std::pow(ratio, (double(i) + time_shift(s)) / (n - 1.)) :
                                 std::sqrt(d.short_time * d.long_time) *
                                   std::pow(ratio, 0.5 * time_shift(s));
        const double total = std::max(d.initial - d.plateau, 0.1 * d.plateau);
        double       sum   = 0.;
        std::vector<double> lean(moduli.size());
        for (std::size_t i = 0; i < moduli.size(); ++i)
          sum += lean[i] = s == 0 ? 1. : s % 2 ? double(i + 1) : double(moduli.size() - i);
        for (std::size_t i = 0; i < moduli.size(); ++i)
          v[moduli[i]] = std::clamp(total * lean[i] / sum, 1e-5 * mu_a, 1e3 * mu_a);
        out.push_back(v);
      }
    return out;
  }
} // namespace cdea
