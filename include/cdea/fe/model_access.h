#pragma once
// Read-only access to a MembraneModel for the computations built on its
// state, as ASPECT's SimulatorAccess gives its plugins the simulator: the
// exact sensitivities (sensitivities.h), the small-signal dynamics
// (linear_dynamics.h) and the sensitivities through time
// (time_sensitivity.h). MembraneModel::access() hands it out. It shows the
// model's parts as const (scene, discretization, kernel, membrane term with
// its internal variables, law, load, unknowns) and offers what the
// computations need of the tangent: that of the state, assembled where it is
// not at hand and factored once, solves and the stability with it, and the
// system of the state with the internal variables held or relaxed and no
// inertia. None of it changes the model's state (load, unknowns, accepted
// internal variables, time step, inertia): what it computes the model keeps
// as it keeps Newton's last tangent, until the state changes.

#include <cdea/fe/cell_kernel.h>
#include <cdea/fe/discretization.h>
#include <cdea/fe/membrane_term.h>
#include <cdea/model/scene.h>

#include <Eigen/Core>

#include <vector>

namespace cdea
{
  /// One point of the energy rule with the first variations of its stretches
  /// (as MembraneTerm forms them) and its weight 2 pi H R dR.
  struct VariationPoint
  {
    unsigned int        cell = 0, q = 0;
    const unsigned int *dofs = nullptr; ///< the cell's global dofs
    double              w    = 0.;
    std::vector<double> dl1, dl2;       ///< d l1, d l2 per local dof
    LawInput            input;          ///< the law's input there
    const double       *stored = nullptr; ///< its current internal variables
  };

  /// The internal variables of a system assembled apart from the state's
  /// own time step (ModelAccess::assemble_without_inertia()).
  enum class InternalVariables
  {
    /// Held at their values (time step 0): the instantaneous (glassy) film;
    /// the assembly leaves the state's current internal variables and rates.
    held,
    /// Relaxed (time step infinity): network B carries nothing; the current
    /// internal variables are the state's again afterwards.
    relaxed
  };

  class ModelAccess
  {
  public:
    virtual ~ModelAccess() = default;

    virtual const Scene          &scene() const          = 0;
    virtual const Discretization &discretization() const = 0;
    virtual const CellKernel     &kernel() const         = 0;
    /// The membrane term: the law in use (plain or relaxed), its input at a
    /// point, the internal variables per point.
    virtual const MembraneTerm &membrane() const = 0;
    /// The law without the tension-field relaxation (MembraneModel::material_law()).
    virtual const MembraneLaw &material_law() const = 0;
    virtual const LoadState   &load() const         = 0;
    /// The unknowns of the state (dof order).
    virtual const Eigen::VectorXd &unknowns() const = 0;

    /// Make the tangent of the current state the model's system, assembled
    /// if it is not at hand; false if the state lies outside the material's
    /// range.
    virtual bool state_tangent() = 0;
    /// Factor the system's tangent (once); false if it is singular.
    virtual bool factor_tangent() = 0;
    /// u = K^-1 b with the system's tangent (factored on first use; NaN if
    /// singular), constrained entries zero.
    virtual void solve_tangent(const Eigen::VectorXd &b, Eigen::VectorXd &u) = 0;
    /// Whether the system's tangent without the constrained dofs is
    /// positive definite.
    virtual bool tangent_positive_definite() = 0;
    /// The system of the current state as @p flags (AssemblyFlag) ask with
    /// the internal variables @p internal and no inertia, constrained as
    /// Newton's, made the model's system (the state's tangent is assembled
    /// again when next needed); false outside the material's range.
    virtual bool assemble_without_inertia(InternalVariables internal, unsigned int flags) = 0;
    /// The model's system: its last assembly.
    virtual const AssembledSystem &system() const = 0;
    /// The system of the current state as @p flags ask into @p out, no
    /// boundary condition applied (the model's system stays).
    virtual bool assemble(unsigned int flags, AssembledSystem &out) = 0;

    /// Calls f(point) (a VariationPoint) at every point of the energy rule
    /// of the current state, cell by cell.
    template <typename F>
    void for_each_variation_point(F &&f) const;
  };

  template <typename F>
  void ModelAccess::for_each_variation_point(F &&f) const
  {
    const Discretization &mesh     = discretization();
    const MembraneTerm   &membrane = this->membrane();
    const Eigen::VectorXd &x       = unknowns();
    const ShapeTable     &rule     = mesh.energy_rule;
    const unsigned int    nc = mesh.dofs_per_cell(), ni = membrane.n_internal();
    const double          two_pi_H = 2. * M_PI * scene().material.thickness;
    std::vector<double>   local(nc);
    VariationPoint        p;
    p.dl1.assign(nc, 0.);
    p.dl2.assign(nc, 0.);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const MeshCell &cell = mesh.cells[c];
        p.cell               = c;
        p.dofs               = mesh.dofs_of(c);
        for (unsigned int i = 0; i < nc; ++i)
          local[i] = x[p.dofs[i]];
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const PointKinematics k = kinematics(mesh, rule, q, cell, local.data());
            p.q                     = q;
            p.w                     = two_pi_H * k.R * cell.h * rule.weights[q];
            for (unsigned int i = 0; i < nc; ++i)
              {
                const double gradient = rule.derivative[q * nc + i] / cell.h;
                p.dl1[i] = (mesh.component[i] == 0 ? k.dr : k.dz) * gradient / k.l1;
                p.dl2[i] = mesh.component[i] == 0 ? rule.value[q * nc + i] / k.R : 0.;
              }
            p.input  = membrane.law_input(k, cell.ring);
            p.stored = ni ? membrane.internal_current.data() +
                              (std::size_t(c) * rule.size() + q) * ni :
                            nullptr;
            f(p);
          }
      }
  }
} // namespace cdea
