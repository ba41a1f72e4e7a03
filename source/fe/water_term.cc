#include <cdea/base/units.h>
#include <cdea/base/text.h>
#include <cdea/fe/water_term.h>
#include <cdea/model/output_fields.h>
#include <cdea/model/records.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace cdea
{
  void WaterTerm::declare_parameters(ParameterDeclarations &prm)
  {
    prm.enter_subsection("Reservoir");
    prm.add_number("Water volume (ml)", "150",
                   "Water in the pump module (for the hydrostatic load).");
    prm.add_number("Water density (kg/m^3)", "1000", "Density of the water.");
    prm.add_flag("Water load", "false",
                 "Apply the water's hydrostatic pressure to the membrane and the disk "
                 "(a follower load). Off: the water only measures the volume change.");
    prm.read_number("Width (mm)");
    prm.read_number("Depth (mm)");
    prm.leave_subsection();
    prm.enter_subsection("Loading");
    prm.read_number("Gravity (m/s^2)");
    prm.leave_subsection();
  }

  void WaterTerm::parse_parameters(const ParameterValues &values)
  {
    const std::string volume_entry = "Reservoir/Water volume (ml)";
    const std::string density_entry = "Reservoir/Water density (kg/m^3)";
    volume_ml = values.number(volume_entry);
    require_range(volume_ml, 1e-12, 1e12, volume_entry, " (in its unit)");
    const double density = values.number(density_entry);
    require_range(density, 1e-12, 1e12, density_entry, " (in its unit)");
    width_mm = values.number("Reservoir/Width (mm)");
    depth_mm = values.number("Reservoir/Depth (mm)");
    WaterLoad w;
    w.enabled      = values.flag("Reservoir/Water load");
    w.density      = density;
    w.gravity      = values.number("Loading/Gravity (m/s^2)");
    w.water_volume = units::ml.in_si(volume_ml);
    w.tube_area    = units::mm.in_si(width_mm) * units::mm.in_si(depth_mm);
    set_water(w);
  }

  std::string WaterTerm::describe() const
  {
    std::ostringstream o;
    o << "Water load: " << volume_ml << " ml of density " << settings.density
      << " kg/m^3 above the membrane, level tube " << width_mm << " x " << depth_mm << " mm";
    return o.str();
  }

  std::string WaterTerm::describe_state(const StepSummary &summary) const
  {
    const double       volume_mm3 = summary.columns.in_file_units(summary_column::volume);
    std::ostringstream o;
    o << std::setprecision(7) << "  water: free surface "
      << units::mm.from_si((settings.water_volume - units::mm3.in_si(volume_mm3)) /
                           settings.tube_area)
      << " mm above the frame plane\n";
    return o.str();
  }

  LiquidColumn WaterTerm::liquid_column() const
  {
    if (!settings.enabled)
      return {};
    return {settings.density, settings.water_volume, settings.tube_area};
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

  CDEA_REGISTER_PLUGIN(LoadTerms, WaterTerm, "water",
                       supports_time_runs | supports_arc_length | supports_stability,
                       "the pump's water: its hydrostatic pressure on the membrane and the disk")
} // namespace cdea
