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

  bool MembraneTerm::add_cell(const CellInput &in, const unsigned int flags, CellScratch &s,
                              CellContribution &out)
  {
    const unsigned int n     = mesh.dofs_per_cell();
    const ShapeTable  &rule  = mesh.energy_rule;
    const auto        &comp  = mesh.component;
    const unsigned int ring  = in.cell->ring;
    const double       h     = in.cell->h;
    const bool         first = flags & (assemble_residual | assemble_tangent |
                                assemble_parameter_derivatives);
    unsigned int request = 0;
    if (flags & assemble_energy)
      request |= law_energy;
    if (first)
      request |= law_stress;
    if (flags & assemble_tangent)
      request |= law_tangent;
    if (request == 0)
      return true;

    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const PointKinematics p    = kinematics(mesh, rule, q, *in.cell, in.x);
        const double          w    = two_pi_H * p.R * h * rule.weights[q];
        const LawInput        at   = law_input(p, ring);
        const InternalStep    step = internal_step(in.index, q);
        LawResponse           law;
        if (!(p.l1 > 0.) || !law_->evaluate(at, step, request, law))
          return false;
        out.energy += w * law.energy;
        if (!first)
          continue;
        // First variations: dl1 = (r' dr' + z' dz') / l1, dl2 = dr / R.
        const double *value = &rule.value[q * n], *deriv = &rule.derivative[q * n];
        for (unsigned int i = 0; i < n; ++i)
          {
            s.gradient[i] = deriv[i] / h;
            s.dl1[i]      = (comp[i] == 0 ? p.dr : p.dz) * s.gradient[i] / p.l1;
            s.dl2[i]      = comp[i] == 0 ? value[i] / p.R : 0.;
            out.residual[i] += w * (law.stress.s1 * s.dl1[i] + law.stress.s2 * s.dl2[i]);
          }
        if (flags & assemble_tangent)
          {
            // w [t11 dl1_i dl1_j + t12 (dl1_i dl2_j + dl2_i dl1_j) + t22 dl2_i dl2_j
            //    + s1 ((dr'_i dr'_j + dz'_i dz'_j) - dl1_i dl1_j) / l1]
            // = u_i dl1_j + v_i dl2_j + [same component] c g_i g_j with
            // u = w ((t11 - s1/l1) dl1 + t12 dl2), v = w (t12 dl1 + t22 dl2), c = w s1/l1.
            const StressTangent &t  = law.tangent;
            const double         c  = w * law.stress.s1 / p.l1;
            const double         a1 = w * t.s11 - c, a2 = w * t.s12, a3 = w * t.s22;
            double              *K  = out.tangent.data();
            for (unsigned int i = 0; i < n; ++i)
              {
                const double u  = a1 * s.dl1[i] + a2 * s.dl2[i];
                const double v  = a2 * s.dl1[i] + a3 * s.dl2[i];
                const double cg = c * s.gradient[i];
                for (unsigned int j = 0; j < n; ++j)
                  K[i * n + j] += u * s.dl1[j] + v * s.dl2[j] +
                                  (comp[i] == comp[j] ? cg * s.gradient[j] : 0.);
              }
          }
        if (flags & assemble_parameter_derivatives)
          {
            const ParameterLayout layout{static_cast<unsigned int>(voltages.size())};
            const std::pair<LawParameter, unsigned int> parameters[] = {
              {LawParameter::voltage, layout.voltage(ring)},
              {LawParameter::shear_modulus, layout.shear_modulus()},
              {LawParameter::jlim, layout.jlim()},
              {LawParameter::permittivity, layout.permittivity()}};
            for (const auto &[parameter, column] : parameters)
              {
                double        dW = 0.;
                NominalStress ds{0., 0.};
                if (!law_->parameter_derivative(at, step, parameter, dW, ds))
                  continue;
                for (unsigned int i = 0; i < n; ++i)
                  out.parameter_residual[column * n + i] +=
                    w * (ds.s1 * s.dl1[i] + ds.s2 * s.dl2[i]);
              }
          }
      }
    return true;
  }

  bool DeadLoadTerm::add_cell(const CellInput &in, const unsigned int, CellScratch &,
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
        }
    return true;
  }
} // namespace cdea
