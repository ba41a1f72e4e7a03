#pragma once
// The inside of MembraneModel, shared by its source files (model, fields,
// continuation); not installed with the public headers.

#include <cdea/fe/cell_kernel.h>
#include <cdea/fe/inertia_term.h>
#include <cdea/fe/load_term.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/membrane_term.h>
#include <cdea/fe/trilinos_solver.h>
#include <cdea/material/tension_field.h>
#include <cdea/numerics/band_eigenvalue.h>
#include <cdea/numerics/sherman_morrison.h>

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
  class MembraneModel::Impl : public NonlinearProblem
  {
  public:
    Impl(const Scene &scene, const FeDiscretization &disc, const NewtonSettings &newton);

    const Scene          scene;
    const NewtonSettings newton_settings;
    const Discretization mesh;
    /// The elastic law (or the one set by set_material_law()) and its
    /// tension-field relaxation; declared before the terms that use them.
    std::shared_ptr<const MembraneLaw> plain_law, relaxed_law;
    bool                               relaxed = false;

    /// The terms, each registered once; the others than the membrane are
    /// reached through kernel.term<Type>() where a model method needs one.
    /// The load terms sit from load_term_slot on, between the model's own
    /// terms and inertia.
    CellKernel              kernel;
    MembraneTerm           &membrane;
    std::size_t             load_term_slot = 0;
    std::vector<LoadTerm *> load_terms;

    LoadState       load;
    Eigen::VectorXd solution;

    /// The last assembly with its tangent, and whether that is the tangent of
    /// the current state (solution and load).
    AssembledSystem system;
    bool            tangent_is_current = false;
    /// Whether anything used the tangent of the last converged state
    /// (ensure_converged_tangent()): if not, the next solve leaves that
    /// tangent out (NewtonSettings::residual_alone_when_converging).
    bool converged_tangent_used = false;
    /// Work storage of the queries (energy, residual, tangent, volume), kept
    /// across calls and apart from the system Newton uses.
    AssembledSystem query;
    LinearSolver                   linear_solver = LinearSolver::banded_lu;
    std::unique_ptr<TangentSolver> solver;
    ShermanMorrison                free_surface;
    bool                           factorized = false;
    /// The stability check's factors and its last eigenvector.
    StabilityCheck stability_check;

    void set_load(const LoadState &new_load);
    void apply_boundary_values(Eigen::VectorXd &x) const;

    /// The kernel at @p x with the boundary conditions applied (constrained
    /// residual entries zero, rows and columns of the tangent decoupled).
    bool assemble_constrained(const Eigen::VectorXd &x, unsigned int flags);
    /// Where the tangent is current but Newton left it out (its last trial
    /// evaluated the residual alone): assemble it at the solution, with the
    /// same residual. Marks the converged tangent as used.
    void ensure_converged_tangent();
    /// Factor the tangent of the last assembly (once); false if singular.
    bool factorize();
    /// u = K^-1 b with the last tangent (NaN if singular), constrained entries zero.
    void solve_tangent(const Eigen::VectorXd &b, Eigen::VectorXd &u);
    /// u <- K^-1 u, the same.
    void solve_in_place(Eigen::VectorXd &u);
    /// The stability of the tangent of the last assembly without the
    /// constrained dofs: positive definite, and the smallest eigenvalue if
    /// @p with_eigenvalue.
    TangentStability check_stability(bool with_eigenvalue);
    /// The same with the eigenvalue near folds only (StabilityCheck::compute_near_folds()).
    /// @p first: the first state of a run (the reference is forgotten).
    TangentStability check_stability_near_folds(bool first);

    void evaluate(const Eigen::VectorXd &x, Eigen::VectorXd &r) override;
    void evaluate_residual(const Eigen::VectorXd &x, Eigen::VectorXd &r) override;
    void solve_linearized(const Eigen::VectorXd &r, Eigen::VectorXd &dx) override;
    /// 10 eps max_i sum_j |K_ij| |x_j| with the tangent of the last assembly
    /// that had one: a residual entry is a difference of terms that large
    /// (the positions carry eps |x| each, the tangent turns that into forces).
    /// Used only with NewtonSettings::converge_at_round_off (off by
    /// default): near the Gent limit, and on fine meshes (from 8192
    /// elements of the default case), where eps |K| |x| passes the tolerance.
    double residual_floor(const Eigen::VectorXd &x) const override;

    /// The largest (I - 3) / Jlim over the quadrature points at @p x (1 at
    /// the Gent limit; 0 if not finite), and its reference radius @p where.
    double gent_fraction(const Eigen::VectorXd &x, double &where) const;
    /// Within 10 % of the Gent limit: where a failure names the limit.
    static constexpr double near_gent_limit = 0.9;
    /// Why a solve that ended at @p x may have failed, if the Gent limit
    /// is the cause: where gent_fraction() exceeds near_gent_limit, a
    /// sentence naming the limit (starting with "; "); empty otherwise.
    std::string gent_limit_note(const Eigen::VectorXd &x) const;

    /// Residual scale of Newton and the corrector (N).
    double residual_scale() const;

    /// Calls f(point) (a VariationPoint) at every point of the energy rule
    /// of the current state.
    template <typename F>
    void for_each_variation_point(F &&f) const;
  };



  template <typename F>
  void MembraneModel::Impl::for_each_variation_point(F &&f) const
  {
    const Impl         &m    = *this;
    const ShapeTable   &rule = m.mesh.energy_rule;
    const unsigned int  nc = m.mesh.dofs_per_cell(), ni = m.membrane.n_internal();
    const double        two_pi_H = 2. * M_PI * m.scene.material.thickness;
    std::vector<double> local(nc);
    VariationPoint      p;
    p.dl1.assign(nc, 0.);
    p.dl2.assign(nc, 0.);
    for (unsigned int c = 0; c < m.mesh.n_cells(); ++c)
      {
        const MeshCell &cell = m.mesh.cells[c];
        p.cell               = c;
        p.dofs               = m.mesh.dofs_of(c);
        for (unsigned int i = 0; i < nc; ++i)
          local[i] = m.solution[p.dofs[i]];
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const PointKinematics k = kinematics(m.mesh, rule, q, cell, local.data());
            p.q                     = q;
            p.w                     = two_pi_H * k.R * cell.h * rule.weights[q];
            for (unsigned int i = 0; i < nc; ++i)
              {
                const double gradient = rule.derivative[q * nc + i] / cell.h;
                p.dl1[i] = (m.mesh.component[i] == 0 ? k.dr : k.dz) * gradient / k.l1;
                p.dl2[i] = m.mesh.component[i] == 0 ? rule.value[q * nc + i] / k.R : 0.;
              }
            p.input  = m.membrane.law_input(k, cell.ring);
            p.stored = ni ? m.membrane.internal_current.data() +
                              (std::size_t(c) * rule.size() + q) * ni :
                            nullptr;
            f(p);
          }
      }
  }
} // namespace cdea
