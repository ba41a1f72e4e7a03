// What MembraneModel reports of its current state: displacement, hoop
// stresses (with the relaxed law's wrinkled zone and validity), the fields
// along the meridian and profiles at given radii.

#include <cdea/base/units.h>

#include "membrane_model_impl.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The law's plain response at a point of the current state, with the
    /// state's internal variables held fixed.
    struct PointEvaluator
    {
      const Discretization &mesh;
      const MembraneTerm   &membrane;
      const MembraneLaw    &plain_law, &relaxed_law;
      std::vector<double>   interpolated, scratch;
      std::vector<RelaxedValue> relaxes_to; ///< of each internal variable

      PointEvaluator(const Discretization &mesh, const MembraneTerm &membrane,
                     const MembraneLaw &plain_law, const MembraneLaw &relaxed_law)
        : mesh(mesh)
        , membrane(membrane)
        , plain_law(plain_law)
        , relaxed_law(relaxed_law)
        , interpolated(membrane.n_internal())
        , scratch(membrane.n_internal())
      {
        for (const InternalVariable &v : membrane.law().internal_variables())
          relaxes_to.push_back(v.relaxed);
      }

      /// At point @p q of the cell's energy rule: the stored variables.
      InternalStep at_quadrature_point(const unsigned int cell, const unsigned int q)
      {
        const unsigned int m = membrane.n_internal();
        if (m == 0)
          return {};
        const std::size_t k = (std::size_t(cell) * mesh.energy_rule.size() + q) * m;
        return {membrane.internal_current.data() + k, scratch.data(), 0.,
                TimeScheme::backward_euler};
      }

      /// At point @p p, reference coordinate @p t in [0, 1] of cell @p c with
      /// local dof values @p x: the stored variables interpolated through the
      /// cell's quadrature points (Lagrange). A variable that relaxes to a
      /// stretch (a viscous stretch xi) is interpolated as ln(xi / lambda)
      /// (spring B's elastic log-stretch), not xi itself, so that the
      /// stress it causes belongs to the stretches at the point and vanishes
      /// exactly where it has relaxed (xi = lambda at the quadrature points).
      InternalStep at_point(const unsigned int c, const double *x, const double t,
                            const PointKinematics &p)
      {
        const unsigned int m = membrane.n_internal();
        if (m == 0)
          return {};
        const ShapeTable  &rule = mesh.energy_rule;
        const unsigned int n    = rule.size();
        std::fill(interpolated.begin(), interpolated.end(), 0.);
        for (unsigned int q = 0; q < n; ++q)
          {
            double weight = 1.;
            for (unsigned int j = 0; j < n; ++j)
              if (j != q)
                weight *= (t - rule.points[j]) / (rule.points[q] - rule.points[j]);
            const double *stored =
              membrane.internal_current.data() + (std::size_t(c) * n + q) * m;
            const PointKinematics g = kinematics(mesh, rule, q, mesh.cells[c], x);
            for (unsigned int i = 0; i < m; ++i)
              interpolated[i] += weight * interpolant(relaxes_to[i], stored[i], g);
          }
        for (unsigned int i = 0; i < m; ++i)
          interpolated[i] = from_interpolant(relaxes_to[i], interpolated[i], p);
        return {interpolated.data(), scratch.data(), 0., TimeScheme::backward_euler};
      }

      /// What is interpolated of an internal variable @p value at a point
      /// with kinematics @p g, and the value back from it.
      static double interpolant(const RelaxedValue rule, const double value,
                                const PointKinematics &g)
      {
        switch (rule)
          {
            case RelaxedValue::meridian_stretch:
              return std::log(value / g.l1);
            case RelaxedValue::hoop_stretch:
              return std::log(value / g.l2);
            case RelaxedValue::zero:
              break;
          }
        return value;
      }

      static double from_interpolant(const RelaxedValue rule, const double value,
                                     const PointKinematics &p)
      {
        switch (rule)
          {
            case RelaxedValue::meridian_stretch:
              return p.l1 * std::exp(value);
            case RelaxedValue::hoop_stretch:
              return p.l2 * std::exp(value);
            case RelaxedValue::zero:
              break;
          }
        return value;
      }

      LawResponse plain(const PointKinematics &p, const unsigned int cell,
                        const InternalStep &step)
      {
        LawResponse r;
        plain_law.evaluate(membrane.law_input(p, mesh.cells[cell].ring), step, law_stress, r);
        return r;
      }

      LawResponse relaxed(const PointKinematics &p, const unsigned int cell,
                          const InternalStep &step)
      {
        LawResponse r;
        relaxed_law.evaluate(membrane.law_input(p, mesh.cells[cell].ring), step,
                             law_stress | law_tangent, r);
        return r;
      }
    };

    /// Local dof values of cell @p c.
    void gather(const Discretization &mesh, const Eigen::VectorXd &x, const unsigned int c,
                std::vector<double> &local)
    {
      local.resize(mesh.dofs_per_cell());
      const unsigned int *dofs = mesh.dofs_of(c);
      for (unsigned int i = 0; i < local.size(); ++i)
        local[i] = x[dofs[i]];
    }
  } // namespace

  // The Gent law's locking measure (I - 3) / Jlim, I = l1^2 + l2^2 + (l1 l2)^-2:
  // 1 at the limit, where the stiffness grows without bound and the
  // residual's round-off with it.
  double MembraneModel::Impl::gent_fraction(const Eigen::VectorXd &x, double &where) const
  {
    const double jlim = scene.material.jlim;
    double       worst = 0.;
    where              = 0.;
    if (!(jlim > 0.) || x.size() != solution.size() || !x.allFinite())
      return 0.;
    std::vector<double> local;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        gather(mesh, x, c, local);
        for (unsigned int q = 0; q < mesh.energy_rule.size(); ++q)
          {
            const PointKinematics p =
              kinematics(mesh, mesh.energy_rule, q, mesh.cells[c], local.data());
            const double I  = p.l1 * p.l1 + p.l2 * p.l2 + 1. / (p.l1 * p.l1 * p.l2 * p.l2);
            const double to = (I - 3.) / jlim;
            if (to > worst)
              {
                worst = to;
                where = p.R;
              }
          }
      }
    return worst;
  }

  std::string MembraneModel::Impl::gent_limit_note(const Eigen::VectorXd &x) const
  {
    double       R     = 0.;
    const double worst = gent_fraction(x, R);
    const double jlim  = scene.material.jlim;
    if (!(worst > near_gent_limit))
      return "";
    std::ostringstream o;
    o << std::setprecision(4);
    if (worst < 1.)
      o << "; the stretch is within " << std::setprecision(2) << 100. * (1. - worst)
        << std::setprecision(4) << "% of the Gent limit (I1 - 3 = " << worst * jlim
        << " of Jlim = " << jlim;
    else
      o << "; the stretch reaches the Gent limit (I1 - 3 = " << worst * jlim
        << " >= Jlim = " << jlim;
    o << " at r/a = " << std::setprecision(3) << scene.prestretch * R / scene.disk_radius
      << (worst < 1. ? "): the film stiffens without bound there, which stalls Newton" :
                       "): the film cannot stretch that far");
    return o.str();
  }

  double MembraneModel::displacement() const
  {
    return std::abs(impl->solution[impl->mesh.z_inner] - impl->solution[impl->mesh.z_outer]);
  }

  HoopStresses MembraneModel::hoop_stresses() const
  {
    const Impl           &m    = *impl;
    const Discretization &mesh = m.mesh;
    HoopStresses          h;
    h.s2_ring_inner.assign(m.scene.n_rings(), nan);
    h.s2_min = std::numeric_limits<double>::infinity();
    PointEvaluator      at(mesh, m.membrane, *m.plain_law, *m.relaxed_law);
    std::vector<double> local;

    // Where the plain hoop stress is negative the relaxed law is wrinkled:
    // record the zone, and whether the relaxed law is still admissible there
    // (elliptic, natural width found).
    const auto note = [&](const PointKinematics &p, const double s2, const unsigned int c,
                          const InternalStep &step) {
      if (s2 < h.s2_min)
        {
          h.s2_min        = s2;
          h.s2_min_radius = p.R;
        }
      if (!m.relaxed || !(s2 < 0.))
        return;
      const LawResponse e = at.relaxed(p, c, step);
      h.wrinkled_zone_inner = std::isnan(h.wrinkled_zone_inner) ? p.R :
                                                                  std::min(h.wrinkled_zone_inner, p.R);
      h.wrinkled_zone_outer = std::isnan(h.wrinkled_zone_outer) ? p.R :
                                                                  std::max(h.wrinkled_zone_outer, p.R);
      if (h.validity_limit.empty() && (e.tension == TensionState::failed || e.loses_ellipticity))
        {
          std::ostringstream o;
          o << "the relaxed (tension-field) law "
            << (e.tension == TensionState::failed ?
                  "has no natural width below the Gent limit" :
                  "loses ellipticity, ds1/dlambda1 <= 0 (pull-in)")
            << " at r = " << units::mm.from_si(m.scene.prestretch * p.R)
            << " mm (r/a = " << m.scene.prestretch * p.R / m.scene.disk_radius
            << ", lambda1 = " << p.l1 << ", lambda2 = " << p.l2 << ", natural width "
            << e.natural_width << ")";
          h.validity_limit = o.str();
        }
    };

    int previous_ring = -1;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        gather(mesh, m.solution, c, local);
        const MeshCell &cell = mesh.cells[c];
        for (unsigned int q = 0; q < mesh.energy_rule.size(); ++q)
          {
            const PointKinematics p = kinematics(mesh, mesh.energy_rule, q, cell, local.data());
            const InternalStep    step = at.at_quadrature_point(c, q);
            note(p, at.plain(p, c, step).stress.s2, c, step);
          }
        // Each ring's inner edge, on that ring's side (its first element).
        if (int(cell.ring) != previous_ring)
          {
            const PointKinematics p  = kinematics(mesh, mesh.left_end, 0, cell, local.data());
            const InternalStep    step = at.at_point(c, local.data(), mesh.left_end.points[0], p);
            const double          s2   = at.plain(p, c, step).stress.s2;
            h.s2_ring_inner[cell.ring] = s2;
            note(p, s2, c, step);
            previous_ring = cell.ring;
          }
      }
    return h;
  }

  StepFields MembraneModel::fields() const
  {
    const Impl           &m    = *impl;
    const Discretization &mesh = m.mesh;
    const ShapeTable     &t    = mesh.samples;
    const double          H    = m.scene.material.thickness;
    StepFields            f;
    PointEvaluator        at(mesh, m.membrane, *m.plain_law, *m.relaxed_law);
    std::vector<double>   local;
    int                   previous_ring = -1;
    // The internal variables the law writes, by their stored positions.
    std::vector<unsigned int> written;
    const std::vector<InternalVariable> &declared = m.membrane.law().internal_variables();
    for (unsigned int i = 0; i < declared.size(); ++i)
      if (declared[i].written)
        {
          written.push_back(i);
          f.internal.push_back({declared[i].name, declared[i].unit, declared[i].description, {}});
        }
    // The left end is written only where a ring starts, so that the jump
    // of lambda1 at a ring edge shows as two samples at one radius.
    std::vector<unsigned int> first_sample(mesh.n_cells());
    std::size_t               samples = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        first_sample[c] = int(mesh.cells[c].ring) != previous_ring ? 0 : 1;
        samples += t.size() - first_sample[c];
        previous_ring = mesh.cells[c].ring;
      }
    for (std::vector<double> *v : {&f.R, &f.r, &f.z, &f.theta, &f.lambda1, &f.lambda2, &f.s1,
                                   &f.s2, &f.Phi, &f.E})
      v->resize(samples);
    f.ring.resize(samples);
    for (InternalField &field : f.internal)
      field.values.resize(samples);
    std::size_t i = 0;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        gather(mesh, m.solution, c, local);
        const MeshCell &cell = mesh.cells[c];
        const double    Phi  = m.load.voltages[cell.ring];
        for (unsigned int k = first_sample[c]; k < t.size(); ++k, ++i)
          {
            const PointKinematics p = kinematics(mesh, t, k, cell, local.data());
            const InternalStep    step = at.at_point(c, local.data(), t.points[k], p);
            NominalStress         s    = at.plain(p, c, step).stress;
            if (m.relaxed && s.s2 < 0.)
              {
                const LawResponse e = at.relaxed(p, c, step);
                if (e.tension == TensionState::wrinkled)
                  s = e.stress;
              }
            f.R[i]       = p.R;
            f.r[i]       = p.r;
            f.z[i]       = p.z;
            f.theta[i]   = std::atan2(-p.dz, p.dr);
            f.lambda1[i] = p.l1;
            f.lambda2[i] = p.l2;
            f.s1[i]      = s.s1;
            f.s2[i]      = s.s2;
            f.Phi[i]     = Phi;
            f.E[i]       = Phi * p.l1 * p.l2 / H;
            f.ring[i]    = cell.ring;
            for (std::size_t j = 0; j < written.size(); ++j)
              f.internal[j].values[i] = step.old[written[j]];
          }
      }
    return f;
  }

  void MembraneModel::profile_at(const std::vector<double> &R, std::vector<double> &r,
                                 std::vector<double> &z) const
  {
    const Discretization &mesh = impl->mesh;
    r.assign(R.size(), 0.);
    z.assign(R.size(), 0.);
    std::vector<double> value, derivative;
    // Cells are sorted by radius: walk them once for sorted input, restart
    // the walk for a radius behind the current cell.
    unsigned int c = 0;
    for (unsigned int k = 0; k < R.size(); ++k)
      {
        if (R[k] < mesh.cells[c].x0)
          c = 0;
        while (R[k] > mesh.cells[c].x0 + mesh.cells[c].h && c + 1 < mesh.n_cells())
          ++c;
        const MeshCell &cell = mesh.cells[c];
        mesh.shape_at(std::clamp((R[k] - cell.x0) / cell.h, 0., 1.), value, derivative);
        const unsigned int *dofs = mesh.dofs_of(c);
        for (unsigned int i = 0; i < value.size(); ++i)
          (mesh.component[i] == 0 ? r[k] : z[k]) += value[i] * impl->solution[dofs[i]];
      }
  }
} // namespace cdea
