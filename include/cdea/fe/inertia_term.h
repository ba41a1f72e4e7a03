#pragma once
// Inertia as a cell term (transient_model.h): Newmark's incremental potential
//
//   Pi_I = m (z(A) - z_pred)^2 / (2 beta dt^2)  +  m_V (V - V_pred)^2 / (2 beta dt^2)
//
// of the disk (mass m on z(A), on the first cell, like the dead load) and of
// the pump's water column (mass m_V = rho h / S on the enclosed volume V,
// added in finish() once V and its derivatives are assembled: residual
// k (V - V_pred) dV/dx, tangent k (V - V_pred) d2V/dx2 plus the rank-one
// k dV/dx dV/dx^T that the linear solver treats by Sherman-Morrison,
// k = m_V / (beta dt^2)). Off while dt = 0.

#include <cdea/fe/cell_kernel.h>
#include <cdea/model/transient_model.h>

namespace cdea
{
  class InertiaTerm final : public CellTerm
  {
  public:
    void               set_step(const InertiaStep &s) { inertia = s; }
    const InertiaStep &step() const { return inertia; }
    bool               active() const { return inertia.dt > 0.; }

    unsigned int extra_flags(unsigned int flags) const override;
    bool         add_cell(const CellInput &cell, unsigned int flags, CellScratch &scratch,
                          CellContribution &contribution) override;
    void         finish(unsigned int flags, AssembledSystem &system) const override;

  private:
    InertiaStep inertia;
    /// The water column with its mass following V (InertiaStep).
    void finish_variable_mass(unsigned int flags, AssembledSystem &system) const;
    /// m / (beta dt^2) for a mass m.
    double stiffness(double mass) const { return mass / (inertia.beta * inertia.dt * inertia.dt); }
  };
} // namespace cdea
