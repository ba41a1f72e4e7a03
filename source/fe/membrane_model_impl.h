#pragma once
// The inside of MembraneModel, shared by its source files (model, fields,
// continuation, time) and nowhere else: the computations built on a model's
// state reach it through ModelAccess (model_access.h), which Access below
// implements on it. Not installed with the public headers.

#include <cdea/fe/cell_kernel.h>
#include <cdea/fe/inertia_term.h>
#include <cdea/fe/load_term.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/membrane_term.h>
#include <cdea/fe/model_access.h>
#include <cdea/fe/trilinos_solver.h>
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
  };

  /// ModelAccess (model_access.h) on the inside of a model.
  class MembraneModel::Access final : public ModelAccess
  {
  public:
    explicit Access(Impl &m)
      : m(m)
    {}

    const Scene          &scene() const override { return m.scene; }
    const Discretization &discretization() const override { return m.mesh; }
    const CellKernel     &kernel() const override { return m.kernel; }
    const MembraneTerm   &membrane() const override { return m.membrane; }
    const MembraneLaw    &material_law() const override { return *m.plain_law; }
    const LoadState      &load() const override { return m.load; }
    const Eigen::VectorXd &unknowns() const override { return m.solution; }
    const AssembledSystem &system() const override { return m.system; }

    bool state_tangent() override;
    bool factor_tangent() override { return m.factorize(); }
    void solve_tangent(const Eigen::VectorXd &b, Eigen::VectorXd &u) override
    {
      m.solve_tangent(b, u);
    }
    bool tangent_positive_definite() override
    {
      return m.check_stability(false).positive_definite;
    }
    bool assemble_without_inertia(InternalVariables internal, unsigned int flags) override;
    bool assemble(const unsigned int flags, AssembledSystem &out) override
    {
      return m.kernel.assemble(m.solution, flags, out);
    }

  private:
    Impl &m;
  };
} // namespace cdea
