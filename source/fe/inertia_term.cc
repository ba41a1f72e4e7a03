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
} // namespace cdea
