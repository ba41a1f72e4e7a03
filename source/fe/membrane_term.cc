#include <cdea/fe/membrane_term.h>

#include <cmath>

namespace cdea
{
  MembraneTerm::MembraneTerm(const Scene &scene, const Discretization &mesh_in,
                             std::shared_ptr<const MembraneLaw> law)
    : mesh(mesh_in)
    , two_pi_H(2. * M_PI * scene.material.thickness)
    , voltages(scene.n_rings(), 0.)
  {
    g_masked.resize(2 * mesh.dofs_per_cell());
    // The mesh never moves: d/dR = (d/dxi) / h and value / R at each point
    // once, with R as kinematics() forms it, instead of at every assembly.
    const ShapeTable  &rule = mesh.energy_rule;
    const unsigned int n    = mesh.dofs_per_cell();
    shape_gradient.reserve(std::size_t(mesh.n_cells()) * rule.size() * n);
    shape_over_R.reserve(shape_gradient.capacity());
    for (const MeshCell &cell : mesh.cells)
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          const double R = cell.x0 + cell.h * rule.points[q];
          for (unsigned int i = 0; i < n; ++i)
            {
              shape_gradient.push_back(rule.derivative[q * n + i] / cell.h);
              shape_over_R.push_back(rule.value[q * n + i] / R);
            }
        }
    set_law(std::move(law));
  }

  void MembraneTerm::set_law(std::shared_ptr<const MembraneLaw> law)
  {
    law_ = std::move(law);
    const std::size_t n =
      std::size_t(mesh.n_cells()) * mesh.energy_rule.size() * law_->n_internal_variables();
    internal_old.assign(n, 0.);
    internal_current.assign(n, 0.);
  }

  void MembraneTerm::set_voltages(const std::vector<double> &v) { voltages = v; }

  void MembraneTerm::set_time_step(const double step, const TimeScheme s)
  {
    dt     = step;
    scheme = s;
  }

  InternalStep MembraneTerm::internal_step(const unsigned int c, const unsigned int q)
  {
    const unsigned int m = law_->n_internal_variables();
    if (m == 0)
      return {};
    const std::size_t k = (std::size_t(c) * mesh.energy_rule.size() + q) * m;
    return {internal_old.data() + k, internal_current.data() + k, dt, scheme};
  }

  namespace
  {
    /// At one point: the shape gradients g = d/dR (@p gradient), the first
    /// variations dl1 = (r' dr' + z' dz') / l1 and dl2 = dr / R (@p over_R:
    /// the shape values over R), and the residual w (s1 dl1 + s2 dl2) added.
    /// N as in with_dofs_per_cell(); the outputs (restrict) alias nothing else.
    template <unsigned int N>
    void add_first_variations(const unsigned int n_run, const PointKinematics &p, const double w,
                              const NominalStress &stress, const double *gradient,
                              const double *over_R, const unsigned int *comp,
                              double *__restrict g, double *__restrict dl1,
                              double *__restrict dl2, double *__restrict residual)
    {
      const unsigned int n = N == 0 ? n_run : N;
      for (unsigned int i = 0; i < n; ++i)
        {
          g[i]   = gradient[i];
          dl1[i] = (comp[i] == 0 ? p.dr : p.dz) * g[i] / p.l1;
          dl2[i] = comp[i] == 0 ? over_R[i] : 0.;
          residual[i] += w * (stress.s1 * dl1[i] + stress.s2 * dl2[i]);
        }
    }

    /// The coefficients of one point's tangent (add_point_tangent()).
    struct TangentCoefficients
    {
      double a1, a2, a3, c;
    };

    /// K += the tangent of one point, N as in with_dofs_per_cell(), with
    /// @p mask_store (2n) for the masked gradients if N = 0 (else on the
    /// stack). K (restrict) aliases no input.
    template <unsigned int N>
    void add_tangent_rows(const unsigned int n_run, const TangentCoefficients &k,
                          const double *dl1, const double *dl2, const double *g,
                          const unsigned int *comp, double *mask_store, double *__restrict K)
    {
      const unsigned int n = N == 0 ? n_run : N;
      double             mask_local[N == 0 ? 1 : 2 * N];
      double            *gm_all = N == 0 ? mask_store : mask_local;
      for (unsigned int j = 0; j < n; ++j)
        {
          gm_all[j]     = comp[j] == 0 ? g[j] : 0.;
          gm_all[n + j] = comp[j] == 0 ? 0. : g[j];
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          const double  u  = k.a1 * dl1[i] + k.a2 * dl2[i], v = k.a2 * dl1[i] + k.a3 * dl2[i];
          const double  cg = k.c * g[i];
          const double *gm = gm_all + (comp[i] == 0 ? 0 : n);
          double       *row = K + i * n;
          for (unsigned int j = 0; j < n; ++j)
            row[j] += u * dl1[j] + v * dl2[j] + cg * gm[j];
        }
    }
  } // namespace

  // w [t11 dl1_i dl1_j + t12 (dl1_i dl2_j + dl2_i dl1_j) + t22 dl2_i dl2_j
  //    + s1 ((dr'_i dr'_j + dz'_i dz'_j) - dl1_i dl1_j) / l1]
  // = u_i dl1_j + v_i dl2_j + [same component] c g_i g_j with
  // u = w ((t11 - s1/l1) dl1 + t12 dl2), v = w (t12 dl1 + t22 dl2), c = w s1/l1.
  // The bracket as g masked by the row's component (g_j or 0), dl2_j = 0 for
  // a z dof: every row is one contiguous loop over j with the same numbers
  // as the sum without its zero terms (only a zero's sign may differ).
  template <unsigned int N>
  void MembraneTerm::add_point_tangent(const LawResponse &law, const PointKinematics &p,
                                       const double w, const CellScratch &s, double *K) const
  {
    const StressTangent      &t = law.tangent;
    const double              c = w * law.stress.s1 / p.l1;
    const TangentCoefficients k{w * t.s11 - c, w * t.s12, w * t.s22, c};
    add_tangent_rows<N>(mesh.dofs_per_cell(), k, s.dl1.data(), s.dl2.data(),
                        s.gradient.data(), mesh.component.data(), g_masked.data(), K);
  }

  bool MembraneTerm::add_cell(const CellInput &in, const unsigned int flags, CellScratch &s,
                              CellContribution &out)
  {
    const bool first =
      flags & (assemble_residual | assemble_tangent | assemble_parameter_derivatives);
    unsigned int request = 0;
    if (flags & assemble_energy)
      request |= law_energy;
    if (first)
      request |= law_stress;
    // The shape derivatives need the tangent (the stresses change with the stretches).
    if (flags & (assemble_tangent | assemble_parameter_derivatives))
      request |= law_tangent;
    if (request == 0)
      return true;
    bool regular = true;
    with_dofs_per_cell(mesh.dofs_per_cell(), [&](auto n_fixed) {
      regular = add_cell_points<n_fixed()>(in, flags, request, s, out);
    });
    return regular;
  }

  template <unsigned int N>
  bool MembraneTerm::add_cell_points(const CellInput &in, const unsigned int flags,
                                     const unsigned int request, CellScratch &s,
                                     CellContribution &out)
  {
    const unsigned int n     = N == 0 ? mesh.dofs_per_cell() : N;
    const ShapeTable  &rule  = mesh.energy_rule;
    const unsigned int ring  = in.cell->ring;
    const double       h     = in.cell->h;
    const bool         first = request & law_stress;
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const PointKinematics p    = kinematics<N>(mesh, rule, q, *in.cell, in.x);
        const double          w    = two_pi_H * p.R * h * rule.weights[q];
        const LawInput        at   = law_input(p, ring);
        const InternalStep    step = internal_step(in.index, q);
        LawResponse           law;
        if (!(p.l1 > 0.) || !law_->evaluate(at, step, request, law))
          return false;
        out.energy += w * law.energy;
        if (!first)
          continue;
        const std::size_t at_point = (std::size_t(in.index) * rule.size() + q) * n;
        add_first_variations<N>(n, p, w, law.stress, &shape_gradient[at_point],
                                &shape_over_R[at_point], mesh.component.data(),
                                s.gradient.data(), s.dl1.data(), s.dl2.data(),
                                out.residual.data());
        if (flags & assemble_tangent)
          add_point_tangent<N>(law, p, w, s, out.tangent.data());
        if (flags & assemble_parameter_derivatives)
          {
            for (const auto &[parameter, column] : law_parameter_columns(*in.layout, ring))
              {
                double        dW = 0.;
                NominalStress ds{0., 0.};
                if (!law_->parameter_derivative(at, step, parameter, dW, ds))
                  continue;
                for (unsigned int i = 0; i < n; ++i)
                  out.parameter_residual[column * n + i] +=
                    w * (ds.s1 * s.dl1[i] + ds.s2 * s.dl2[i]);
              }
            add_geometry_derivative(p, h, w, rule.points[q], law, s, out);
          }
      }
    return true;
  }

  // The residual w (s1 dl1_i + s2 dl2_i) at a point R = x0 + h xi moves with
  // the cell: with R_x0 = 1, R_h = xi and the nodal values held,
  //   w_x0 = w / R,  w_h = w (1/h + xi/R),
  //   l1_h = -l1/h,  dl1_i,h = -dl1_i/h  (r', z' and the shape gradients scale with 1/h),
  //   l2_t = -l2 R_t / R,  dl2_i,t = -dl2_i R_t / R,
  //   s_k,t = s_k1 l1_t + s_k2 l2_t.
  void MembraneTerm::add_geometry_derivative(const PointKinematics &p, const double h,
                                             const double w, const double xi,
                                             const LawResponse &law, const CellScratch &s,
                                             CellContribution &out) const
  {
    const unsigned int   n = mesh.dofs_per_cell();
    const StressTangent &t = law.tangent;
    const double         s1 = law.stress.s1, s2 = law.stress.s2;
    // t = x0: R_t = 1, l1_t = 0;  t = h: R_t = xi, l1_t = -l1/h.
    const double R_t[2]  = {1., xi};
    const double l1_t[2] = {0., -p.l1 / h};
    const double w_t[2]  = {w / p.R, w * (1. / h + xi / p.R)};
    for (unsigned int k = 0; k < 2; ++k)
      {
        const double l2_t  = -p.l2 * R_t[k] / p.R;
        const double s1_t  = t.s11 * l1_t[k] + t.s12 * l2_t;
        const double s2_t  = t.s12 * l1_t[k] + t.s22 * l2_t;
        const double dl1_f = k == 1 ? -1. / h : 0.; // dl1_i,t = dl1_f dl1_i
        const double dl2_f = -R_t[k] / p.R;         // dl2_i,t = dl2_f dl2_i
        double      *d     = &out.geometry_residual[k * n];
        for (unsigned int i = 0; i < n; ++i)
          d[i] += w_t[k] * (s1 * s.dl1[i] + s2 * s.dl2[i]) +
                  w * ((s1_t + s1 * dl1_f) * s.dl1[i] + (s2_t + s2 * dl2_f) * s.dl2[i]);
      }
  }

  bool DeadLoadTerm::add_cell(const CellInput &in, const unsigned int flags, CellScratch &,
                              CellContribution &out)
  {
    if (in.index != 0)
      return true;
    // z(A) = sum of the z dofs times their values at the cell's left end.
    const Discretization &mesh = *in.mesh;
    const unsigned int    n    = mesh.dofs_per_cell();
    for (unsigned int i = 0; i < n; ++i)
      if (mesh.component[i] == 1)
        {
          const double v = mesh.left_end.value[i];
          out.energy -= force * v * in.x[i];
          out.residual[i] -= force * v;
          if (flags & assemble_parameter_derivatives)
            out.parameter_residual[in.layout->dead_load() * n + i] -= v;
        }
    return true;
  }

  // V = -pi int r^2 z' dR: dV = -pi int (2 r z' dr + r^2 dz'), and
  // d2V = -pi int (2 z' dr Dr + 2 r (dr Dz' + Dr dz')).
  bool EnclosedVolumeTerm::add_cell(const CellInput &in, const unsigned int flags,
                                    CellScratch &s, CellContribution &out)
  {
    if (!(flags & assemble_volume))
      return true;
    const Discretization &mesh = *in.mesh;
    const ShapeTable     &rule = mesh.volume_rule;
    const unsigned int    n    = mesh.dofs_per_cell();
    const auto           &comp = mesh.component;
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const PointKinematics p     = kinematics(mesh, rule, q, *in.cell, in.x);
        const double          w     = M_PI * in.cell->h * rule.weights[q];
        const double         *value = &rule.value[q * n];
        out.volume -= w * p.r * p.r * p.dz;
        for (unsigned int i = 0; i < n; ++i)
          {
            s.gradient[i] = rule.derivative[q * n + i] / in.cell->h;
            out.volume_gradient[i] -=
              w * (comp[i] == 0 ? 2. * p.r * p.dz * value[i] : p.r * p.r * s.gradient[i]);
          }
        if (flags & assemble_tangent)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              {
                double d = 0.;
                if (comp[i] == 0 && comp[j] == 0)
                  d = 2. * p.dz * value[i] * value[j];
                else if (comp[i] != comp[j])
                  {
                    const unsigned int a = comp[i] == 0 ? i : j; // the r dof
                    const unsigned int b = comp[i] == 0 ? j : i; // the z dof
                    d                    = 2. * p.r * value[a] * s.gradient[b];
                  }
                out.volume_hessian[i * n + j] -= w * d;
              }
      }
    return true;
  }
} // namespace cdea
