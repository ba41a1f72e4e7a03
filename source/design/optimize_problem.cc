// The layout problem of `cdea optimize` (optimize.h) before NLopt sees it:
// the starting layouts (a van der Corput sequence of free edges spread
// between their fixed neighbours, voltages likewise) and the constraints of
// a layout with their gradients and names (s2 >= 0 at every point, the field
// limit, the least ring width). One start's optimization is optimize.cc.

#include <cdea/base/format.h>
#include <cdea/base/units.h>
#include <cdea/design/optimize.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// The k-th number of the van der Corput sequence in @p base.
    double radical_inverse(unsigned int k, const unsigned int base)
    {
      double x = 0., f = 1. / base;
      for (; k > 0; k /= base, f /= base)
        x += f * (k % base);
      return x;
    }

    /// Free edges at fractions @p t of their room: each run of free edges
    /// between fixed neighbours spreads over the part of the bounds between
    /// them, in increasing order, then every ring is made at least the
    /// minimum width (forward, then backward).
    std::vector<double> place_edges(const OptimizationSettings &s, std::vector<double> t)
    {
      std::vector<double> e = s.edges;
      const unsigned int  N = s.n_rings;
      for (unsigned int k = 1; k < N;)
        {
          if (!std::isnan(s.edges[k]))
            {
              ++k;
              continue;
            }
          unsigned int end = k;
          while (end < N && std::isnan(s.edges[end]))
            ++end;
          const double lo = std::max(s.edge_lower, e[k - 1] + s.min_ring_width);
          const double hi = std::min(s.edge_upper, s.edges[end] - s.min_ring_width);
          std::vector<double> run(t.begin() + (k - 1), t.begin() + (end - 1));
          std::sort(run.begin(), run.end());
          for (unsigned int j = k; j < end; ++j)
            e[j] = lo + (hi - lo) * run[j - k];
          k = end;
        }
      for (unsigned int k = 1; k < N; ++k)
        if (std::isnan(s.edges[k]))
          e[k] = std::clamp(std::max(e[k], e[k - 1] + s.min_ring_width), s.edge_lower,
                            s.edge_upper);
      for (unsigned int k = N - 1; k >= 1; --k)
        if (std::isnan(s.edges[k]))
          e[k] = std::clamp(std::min(e[k], e[k + 1] - s.min_ring_width), s.edge_lower,
                            s.edge_upper);
      return e;
    }

    std::string position(const Scene &base, const PointValues &points, const unsigned int k)
    {
      std::ostringstream o;
      o << "r/a = " << format_number(base.prestretch * points.R[k] / base.disk_radius, 5)
        << (k >= points.n_quadrature_points ? " (inner edge of ring " : " (in ring ")
        << points.ring[k] + 1 << ")";
      return o.str();
    }
  } // namespace

  std::vector<Layout> starting_layouts(const OptimizationSettings &s)
  {
    static const unsigned int primes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43,
                                          47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97};
    std::vector<Layout>       starts;
    for (unsigned int k = 0; k < s.starts; ++k)
      {
        // Start 0 spreads the edges evenly and puts every free voltage at
        // 60 % of its range; the others are points of a Halton sequence,
        // voltages within the lower 80 % of their range.
        std::vector<double> t_edge(s.n_rings - 1), t_voltage(s.n_rings);
        for (unsigned int j = 0; j < s.n_rings; ++j)
          {
            const unsigned int b = primes[j % 25];
            t_voltage[j]         = k == 0 ? 0.6 : 0.8 * radical_inverse(k, b);
            if (j + 1 < s.n_rings)
              t_edge[j] = k == 0 ? (j + 1.) / s.n_rings :
                                   radical_inverse(k, primes[(s.n_rings + j) % 25]);
          }
        Layout layout;
        layout.edges = place_edges(s, t_edge);
        for (unsigned int j = 0; j < s.n_rings; ++j)
          layout.voltages.push_back(std::isnan(s.voltages[j]) ?
                                      s.voltage_lower +
                                        t_voltage[j] * (s.voltage_upper - s.voltage_lower) :
                                      s.voltages[j]);
        starts.push_back(layout);
      }
    return starts;
  }

  void constraints(const OptimizationSettings &s, const Scene &base, const Layout &layout,
                   const LayoutEvaluation &e, Eigen::VectorXd &c, Eigen::MatrixXd &dc,
                   std::vector<std::string> *names)
  {
    const auto         free     = s.free_parameters();
    const unsigned int n_points = e.points.s2.size();
    const bool         field    = std::isfinite(s.max_field);
    const double       mu       = base.material.shear_modulus;
    const double       span     = base.frame_radius / base.disk_radius - 1.;
    std::vector<unsigned int> rings; // rings whose width has a free edge
    for (unsigned int j = 0; j < s.n_rings; ++j)
      if (std::isnan(s.edges[j]) || std::isnan(s.edges[j + 1]))
        rings.push_back(j);
    const unsigned int m = n_points * (field ? 2 : 1) + rings.size();
    c.resize(m);
    dc.setZero(m, free.size());
    if (names)
      names->clear();
    unsigned int row = 0;
    for (unsigned int k = 0; k < n_points; ++k, ++row)
      {
        c[row]      = (s.min_hoop_stress - e.points.s2[k]) / mu;
        dc.row(row) = -e.points.d_s2.row(k) / mu;
        if (names)
          names->push_back("s2 >= " + format_number(units::kPa.from_si(s.min_hoop_stress)) +
                           " kPa at " +
                           position(base, e.points, k));
      }
    if (field)
      for (unsigned int k = 0; k < n_points; ++k, ++row)
        {
          c[row]      = (e.points.field[k] - s.max_field) / s.max_field;
          dc.row(row) = e.points.d_field.row(k) / s.max_field;
          if (names)
            names->push_back("E <= " + format_number(units::MV_per_m.from_si(s.max_field)) +
                             " MV/m at " +
                             position(base, e.points, k));
        }
    for (const unsigned int j : rings)
      {
        c[row] = (s.min_ring_width - (layout.edges[j + 1] - layout.edges[j])) / span;
        for (std::size_t v = 0; v < free.size(); ++v)
          if (free[v].kind == ParameterKind::ring_edge)
            dc(row, v) = free[v].index == j + 1 ? -1. / span : free[v].index == j ? 1. / span : 0.;
        if (names)
          names->push_back("ring " + std::to_string(j + 1) + " at least " +
                           format_number(units::mm.from_si(s.min_ring_width * base.disk_radius)) +
                           " mm wide");
        ++row;
      }
  }
} // namespace cdea
