#include <cdea/fe/inertia_term.h>

namespace cdea
{
  unsigned int InertiaTerm::extra_flags(const unsigned int flags) const
  {
    const bool needs_volume =
      active() && inertia.volume_mass > 0. && (flags & (assemble_energy | assemble_residual |
                                                        assemble_tangent));
    return needs_volume ? static_cast<unsigned int>(assemble_volume) : 0u;
  }

  bool InertiaTerm::add_cell(const CellInput &in, const unsigned int flags, CellScratch &,
                             CellContribution &out)
  {
    if (!active() || !(inertia.disk_mass > 0.) || in.index != 0)
      return true;
    // z(A) = sum of the z dofs times their values at the first cell's left end.
    const Discretization &mesh = *in.mesh;
    const unsigned int    n    = mesh.dofs_per_cell();
    const double         *v    = mesh.left_end.value.data();
    double                z    = 0.;
    for (unsigned int i = 0; i < n; ++i)
      if (mesh.component[i] == 1)
        z += v[i] * in.x[i];
    const double k = stiffness(inertia.disk_mass), dz = z - inertia.disk_target;
    out.energy += 0.5 * k * dz * dz;
    for (unsigned int i = 0; i < n; ++i)
      if (mesh.component[i] == 1)
        {
          out.residual[i] += k * dz * v[i];
          if (flags & assemble_tangent)
            for (unsigned int j = 0; j < n; ++j)
              if (mesh.component[j] == 1)
                out.tangent[i * n + j] += k * v[i] * v[j];
        }
    return true;
  }

  void InertiaTerm::finish(const unsigned int flags, AssembledSystem &system) const
  {
    if (!active() || !(inertia.volume_mass > 0.))
      return;
    if (inertia.volume_mass_slope != 0.)
      {
        finish_variable_mass(flags, system);
        return;
      }
    const double k = stiffness(inertia.volume_mass), dV = system.volume - inertia.volume_target;
    if (flags & assemble_energy)
      system.energy += 0.5 * k * dV * dV;
    if (flags & assemble_residual)
      system.residual += k * dV * system.volume_gradient;
    if (flags & assemble_tangent)
      {
        system.tangent.add(k * dV, system.volume_hessian);
        system.rank_one_coupling += k;
      }
  }

  // With m(V) = m0 + m' (V - V_ref), a = (V - V_target) / (beta dt^2) and
  // v = (V - V_start) / dt the column's force is c g, g = dV/dx, with
  //   c = m(V) a + m' v^2 / 2,
  //   dc/dV = m(V) / (beta dt^2) + m' a + m' v / dt.
  // No potential has this gradient: the energy gets m(V) (V - V_target)^2 /
  // (2 beta dt^2) (the line search reads residuals only).
  void InertiaTerm::finish_variable_mass(const unsigned int flags, AssembledSystem &system) const
  {
    const double V     = system.volume;
    const double slope = inertia.volume_mass_slope;
    const double mass  = inertia.volume_mass + slope * (V - inertia.volume_reference);
    const double a     = (V - inertia.volume_target) / (inertia.beta * inertia.dt * inertia.dt);
    const double v     = (V - inertia.volume_start) / inertia.dt;
    const double c     = mass * a + 0.5 * slope * v * v;
    if (flags & assemble_energy)
      system.energy += 0.5 * mass * a * (V - inertia.volume_target);
    if (flags & assemble_residual)
      system.residual += c * system.volume_gradient;
    if (flags & assemble_tangent)
      {
        system.tangent.add(c, system.volume_hessian);
        system.rank_one_coupling +=
          stiffness(mass) + slope * a + slope * v / inertia.dt;
      }
  }
} // namespace cdea
