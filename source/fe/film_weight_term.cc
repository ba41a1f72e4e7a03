// The film's own weight as a load term (load_term.h), registered as "film
// weight": a dead load spread over the membrane. A ring dR of the undeformed
// film has the mass rho H 2 pi R dR, which does not change as it stretches,
// so with z down the potential is linear in z:
//
//   Pi_g = -s rho g H 2 pi int_A^B z R dR,
//
// residual -s rho g H 2 pi int phi_i R dR on the z unknowns and no tangent;
// the share s of gravity follows the load stages as the dead load's does
// (0 while pre-stretching, the load factor while hanging the weight, then 1).
// Material/Density (kg/m^3) switches it on; 0 (the default) neglects the
// film's weight, as earlier versions did. The membrane's inertia in time runs
// stays neglected (Time/Inertia). The integrand z R is of degree p + 1 in R:
// the p + 1 Gauss points of the energy rule integrate it exactly.

#include <cdea/base/units.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/fe/load_term.h>

#include <cmath>

namespace cdea
{
  namespace
  {
    const std::string density_entry = "Material/Density (kg/m^3)";
  } // namespace

  class FilmWeightTerm final : public LoadTerm
  {
  public:
    static void declare_parameters(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Material");
      prm.add_number("Density (kg/m^3)", "0",
                     "Density rho of the film: its own weight, rho g H per area of the "
                     "undeformed film, pulls the membrane down like the dead load (ramped "
                     "with it). 0: the film's weight is neglected.");
      prm.leave_subsection();
      prm.enter_subsection("Loading");
      prm.read_number("Gravity (m/s^2)");
      prm.leave_subsection();
      prm.enter_subsection("Geometry");
      prm.read_number("Film thickness (mm)");
      prm.leave_subsection();
    }

    explicit FilmWeightTerm(const ParameterValues &values) { parse_parameters(values); }

    void parse_parameters(const ParameterValues &values) override
    {
      density = values.number(density_entry);
      require_range(density, 1e-12, 1e12, density_entry, " (in its unit)", true);
      weight_per_area = density * values.number("Loading/Gravity (m/s^2)") *
                        units::mm.in_si(values.number("Geometry/Film thickness (mm)"));
    }

    bool        active() const override { return density > 0.; }
    std::string switched_on() const override
    {
      return density_entry + " = " + format_number(density);
    }
    std::string off_value() const override { return "0"; }
    std::string describe() const override
    {
      return "Film weight: density " + format_number(density) + " kg/m^3";
    }

    void set_load(const LoadState &load) override
    {
      gravity_share = load.stage == Stage::prestretch ? 0. :
                      load.stage == Stage::dead_load  ? load.load_factor :
                                                        1.;
    }

    bool add_cell(const CellInput &in, const unsigned int flags, CellScratch &,
                  CellContribution &out) override
    {
      const double c = gravity_share * weight_per_area * 2. * M_PI;
      if (!(c > 0.) || !(flags & (assemble_energy | assemble_residual)))
        return true;
      const Discretization &mesh = *in.mesh;
      const ShapeTable     &rule = mesh.energy_rule;
      const unsigned int    n    = mesh.dofs_per_cell();
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          const PointKinematics p = kinematics(mesh, rule, q, *in.cell, in.x);
          const double          w = c * p.R * in.cell->h * rule.weights[q];
          out.energy -= w * p.z;
          for (unsigned int i = 0; i < n; ++i)
            if (mesh.component[i] == 1)
              out.residual[i] -= w * rule.value[q * n + i];
        }
      return true;
    }

  private:
    double density         = 0.; ///< kg/m^3, as the file gives it
    double weight_per_area = 0.; ///< rho g H (N/m^2 of undeformed film)
    double gravity_share   = 0.;
  };

  CDEA_REGISTER_PLUGIN(LoadTerms, FilmWeightTerm, "film weight",
                       supports_time_runs | supports_arc_length | supports_stability,
                       "the film's own weight, rho g H per area of the undeformed film")
} // namespace cdea
