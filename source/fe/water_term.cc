#include <cdea/fe/water_term.h>

#include <cmath>

namespace cdea
{
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

  void WaterTerm::set_water(const WaterLoad &water)
  {
    settings = water;
    weight   = settings.enabled ? gravity_share * settings.density * settings.gravity : 0.;
  }

  void WaterTerm::set_load(const LoadState &load)
  {
    gravity_share = load.stage == Stage::prestretch ? 0. :
                    load.stage == Stage::dead_load  ? load.load_factor :
                                                      1.;
    set_water(settings);
  }

  double WaterTerm::free_surface_height(const double volume) const
  {
    return (settings.water_volume - volume) / settings.tube_area;
  }

  std::string WaterTerm::reject_state(const AssembledSystem &system) const
  {
    if (weight > 0. && (system.flags & assemble_volume) &&
        free_surface_height(system.volume) < 0.)
      return "the water (WaterLoad) no longer fills the cone: its free surface would lie "
             "below the frame plane";
    return {};
  }

  unsigned int WaterTerm::extra_flags(const unsigned int flags) const
  {
    return weight > 0. && (flags & (assemble_energy | assemble_residual | assemble_tangent)) ?
             static_cast<unsigned int>(assemble_volume) :
             0u;
  }

  // At h = 0 the local potential is c pi int phi dR with phi = z r^2 z':
  // phi_r = 2 z r z', phi_z = r^2 z', phi_z' = z r^2; phi_rr = 2 z z',
  // phi_rz = 2 r z', phi_rz' = 2 z r, phi_zz' = r^2.
  bool WaterTerm::add_cell(const CellInput &in, const unsigned int flags, CellScratch &s,
                           CellContribution &out)
  {
    if (!(weight > 0.))
      return true;
    const Discretization &mesh = *in.mesh;
    const ShapeTable     &rule = mesh.volume_rule;
    const unsigned int    n    = mesh.dofs_per_cell();
    const auto           &comp = mesh.component;
    const double          c    = weight;
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const PointKinematics p     = kinematics(mesh, rule, q, *in.cell, in.x);
        const double          w     = M_PI * in.cell->h * rule.weights[q];
        const double         *value = &rule.value[q * n];
        const double          r = p.r, z = p.z, dz = p.dz;
        out.energy += c * w * r * r * z * dz;
        for (unsigned int i = 0; i < n; ++i)
          {
            s.gradient[i] = rule.derivative[q * n + i] / in.cell->h;
            out.residual[i] += c * w *
                               (comp[i] == 0 ? 2. * z * r * dz * value[i] :
                                               r * r * dz * value[i] + z * r * r * s.gradient[i]);
          }
        if (flags & assemble_tangent)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              {
                double d = 0.;
                if (comp[i] == 0 && comp[j] == 0)
                  d = 2. * z * dz * value[i] * value[j];
                else if (comp[i] == 1 && comp[j] == 1)
                  d = r * r * (value[i] * s.gradient[j] + s.gradient[i] * value[j]);
                else
                  {
                    const unsigned int a = comp[i] == 0 ? i : j; // the r dof
                    const unsigned int b = comp[i] == 0 ? j : i; // the z dof
                    d = 2. * r * dz * value[a] * value[b] + 2. * z * r * value[a] * s.gradient[b];
                  }
                out.tangent[i * n + j] += c * w * d;
              }
      }
    return true;
  }

  void WaterTerm::finish(const unsigned int flags, AssembledSystem &system) const
  {
    if (!(weight > 0.))
      return;
    const double c = weight, A = settings.tube_area;
    const double head = (settings.water_volume - system.volume) / A;
    if (flags & assemble_energy)
      system.energy += c * 0.5 * A * head * head;
    if (flags & assemble_residual)
      system.residual -= c * head * system.volume_gradient;
    if (flags & assemble_tangent)
      {
        system.tangent.add(-c * head, system.volume_hessian);
        system.rank_one_coupling = c / A;
      }
  }
} // namespace cdea
