#pragma once
// The inside of MembraneModel, shared by its source files (model, fields,
// continuation); not installed with the public headers.

#include <cdea/fe/cell_kernel.h>
#include <cdea/fe/inertia_term.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/membrane_term.h>
#include <cdea/fe/trilinos_solver.h>
#include <cdea/fe/water_term.h>
#include <cdea/material/tension_field.h>
#include <cdea/numerics/band_eigenvalue.h>
#include <cdea/numerics/sherman_morrison.h>

namespace cdea
{
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
    CellKernel    kernel;
    MembraneTerm &membrane;

    LoadState       load;
    Eigen::VectorXd solution;

    /// The last assembly with its tangent, and whether that is the tangent of
    /// the current state (solution and load).
    AssembledSystem system;
    bool            tangent_is_current = false;
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

    void evaluate(const Eigen::VectorXd &x, Eigen::VectorXd &r) override;
    void solve_linearized(const Eigen::VectorXd &r, Eigen::VectorXd &dx) override;
    /// 10 eps max_i sum_j |K_ij| |x_j| with the tangent of the last assembly
    /// that had one: a residual entry is a difference of terms that large
    /// (the positions carry eps |x| each, the tangent turns that into forces).
    /// Only within 10 % of the Gent limit (0 elsewhere): the cause this
    /// floor is for; elsewhere Newton converges as it always did.
    double residual_floor(const Eigen::VectorXd &x) const override;

    /// The largest (I - 3) / Jlim over the quadrature points at @p x (1 at
    /// the Gent limit; 0 if not finite), and its reference radius @p where.
    double gent_fraction(const Eigen::VectorXd &x, double &where) const;
    /// Within 10 % of the Gent limit: where Newton may stop at the
    /// residual's round-off level, and a failure names the limit.
    static constexpr double near_gent_limit = 0.9;
    /// Why a solve that ended at @p x may have failed, if the Gent limit
    /// is the cause: where gent_fraction() exceeds near_gent_limit, a
    /// sentence naming the limit (starting with "; "); empty otherwise.
    std::string gent_limit_note(const Eigen::VectorXd &x) const;

    /// Residual scale of Newton and the corrector (N).
    double residual_scale() const;
  };
} // namespace cdea
