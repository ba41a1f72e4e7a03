#pragma once
// The pump's water load as a load term (load_term.h), registered as "water".
//
// Water load (doc/pump.md): the water fills the cone above the membrane and
// the disk (z > 0 is down) and rises in a level tube of cross-section
// tube_area above the frame plane, to the free-surface height
// h = (water_volume - V) / tube_area. The pressure rho g (h + z) acts normal
// to the deformed membrane and on the disk. It is conservative:
//
//   E_w = c [(water_volume - V)^2 / (2 tube_area) + pi int r^2 z z' dR],  c = rho g,
//
// with gravity ramped by the load stage (off in stage 0, times the load factor
// in stage 1, full in stage 2). On each cell the term adds its part at h = 0;
// finish() adds the head's part once V is known: residual -c h dV/dx, tangent
// -c h d2V/dx2 and the dense rank-one (c / tube_area) dV/dx dV/dx^T, which the
// linear solver handles by Sherman-Morrison. V is the enclosed volume
// (EnclosedVolumeTerm, membrane_term.h).
//
// Its entries are those of subsection Reservoir: Water volume (ml), Water
// density (kg/m^3) and Water load (on or off); it reads the level tube's
// Width and Depth (mm), which the core declares for the level drop of every
// run, and Loading/Gravity (m/s^2).

#include <cdea/fe/load_term.h>

namespace cdea
{
  struct WaterLoad
  {
    bool   enabled      = false;
    double density      = 1000.;  ///< kg/m^3
    double gravity      = 9.81;   ///< m/s^2
    double water_volume = 150e-6; ///< m^3, in the cone and the tube together
    double tube_area    = 400e-6; ///< m^2, cross-section of the level tube
  };

  class WaterTerm final : public LoadTerm
  {
  public:
    static void declare_parameters(ParameterDeclarations &prm);
    WaterTerm() = default;
    /// The plugin: the term of the entries' @p values.
    explicit WaterTerm(const ParameterValues &values) { parse_parameters(values); }
    /// The water load of the Reservoir's entries in SI units (checked: each
    /// positive and at most 1e12 in its unit).
    void        parse_parameters(const ParameterValues &values) override;
    bool        active() const override { return settings.enabled; }
    std::string switched_on() const override { return "Reservoir/Water load = true"; }
    std::string off_value() const override { return "false"; }
    /// "Water load: 150 ml of density 1000 kg/m^3 above the membrane, level tube 20 x 20 mm"
    std::string describe() const override;
    /// "  water: free surface ... mm above the frame plane"
    std::string describe_state(const StepSummary &summary) const override;
    /// The water in the cone and the level tube, when the load is on.
    LiquidColumn liquid_column() const override;

    void             set_water(const WaterLoad &water);
    const WaterLoad &water() const { return settings; }
    /// rho g times the load stage's share of gravity (0 without water).
    double water_weight() const { return weight; }
    /// Height of the free surface above the frame plane at the enclosed
    /// volume @p volume: (water_volume - V) / tube_area.
    double free_surface_height(double volume) const;

    /// Gravity is off in stage 0, ramped by the load factor in stage 1 and
    /// full in stage 2.
    void set_load(const LoadState &load) override;
    /// The model assumes a full cone under the free surface: a state whose
    /// free surface lies below the frame plane is rejected.
    std::string reject_state(const AssembledSystem &system) const override;

    unsigned int extra_flags(unsigned int flags) const override;
    bool         add_cell(const CellInput &cell, unsigned int flags, CellScratch &scratch,
                          CellContribution &contribution) override;
    void         finish(unsigned int flags, AssembledSystem &system) const override;

  private:
    WaterLoad settings;
    /// The entries as the file gives them (ml, mm), for describe().
    double volume_ml = 150., width_mm = 20., depth_mm = 20.;
    double    gravity_share = 0.;
    double    weight        = 0.;
  };
} // namespace cdea
