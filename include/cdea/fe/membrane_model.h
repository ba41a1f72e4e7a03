#pragma once
// Axisymmetric nonlinear membrane FE model of the cone actuator.
//
// Unknowns r(R) and z(R) on the undeformed radius R in [A, B] (Discretization:
// two FE_Q of degree p, element boundaries on every ring edge, each element at
// the voltage of its ring). The total potential
//
//   Pi[r, z] = 2 pi H int_A^B W(l1, l2; Phi) R dR  -  F z(A)  [+ the load terms],
//
// is stationary at equilibrium; the cell kernel (cell_kernel.h) evaluates it,
// its residual and its exact tangent from its terms (membrane energy, dead
// load and enclosed volume, then the load terms the parameters switch on,
// such as the water load, see load_term.h, then inertia). Boundary conditions:
// r(A) = s A and r(B) = s B with s the current pre-stretch (s = lam_pre after
// stage 0), z(B) = 0; z(A) is free and carries the dead load.
//
// Newton evaluates the residual and the tangent together at every trial
// state, so the tangent of a converged state is at hand for the stability
// eigenvalue, the arc-length tangent and sensitivities without assembling
// again.

#include <cdea/fe/cell_kernel.h>
#include <cdea/fe/discretization.h>
#include <cdea/model/scene.h>
#include <cdea/model/equilibrium_model.h>
#include <cdea/numerics/newton.h>
#include <cdea/numerics/tangent_solver.h>
#include <cdea/model/transient_model.h>

#include <memory>
#include <vector>

namespace cdea
{
  class LoadTerm;
  class ModelAccess;
  class ParameterValues;

  class MembraneModel : public TransientModel
  {
  public:
    MembraneModel(const Scene &scene, const FeDiscretization &discretization,
                  const NewtonSettings &newton);
    ~MembraneModel() override;

    void             set_reference_state() override;
    SolveReport      solve(const LoadState &load) override;
    const LoadState &load() const override;
    double           displacement() const override;
    HoopStresses     hoop_stresses() const override;
    StepFields       fields() const override;
    ModelState       state() const override;
    void             set_state(const ModelState &state) override;
    void             predict(const ModelState &older, double factor) override;
    ContinuationProblem *continuation(const std::function<LoadState(double)> &path) override;
    /// With the tangent of the current state when it is at hand (after a solve).
    double min_tangent_eigenvalue() override;
    /// Positive definite by the inertia of the tangent's factorization, and
    /// the smallest eigenvalue by shift-invert Lanczos on its factors
    /// (StabilityCheck::compute_near_folds() for near_folds).
    StateStability stability(StabilityEigenvalue eigenvalue) override;

    /// Tension-field relaxation where the hoop stress would be negative
    /// (Wrinkling/Model = relaxed); off: the plain law everywhere.
    void set_relaxed(bool relaxed);
    bool relaxed() const;

    void set_linear_solver(LinearSolver solver);

    /// pi int_A^B r^2 (-z') dR by Gauss quadrature exact for the FE solution.
    double enclosed_volume() const override;

    /// The registered load terms that @p values switch on (load_term.h), in
    /// their order, in place of those set before (none by default); they
    /// apply from the next solve.
    void set_load_terms(const ParameterValues &values);
    /// These load terms, in this order, in place of those set before.
    void set_load_terms(std::vector<std::unique_ptr<LoadTerm>> terms);
    /// The load terms of the model, in their order.
    std::vector<const LoadTerm *> load_terms() const;

    unsigned int n_dofs() const;
    unsigned int n_elements() const;
    const Discretization &discretization() const;

    /// Total potential Pi at the current state and load (J).
    double energy() const;

    /// Residual and tangent at the current state and load, in dof order with
    /// no boundary condition applied (for tests against finite differences).
    std::vector<double>              residual_vector() const;
    std::vector<std::vector<double>> tangent_matrix() const;

    /// The system of the current state as @p flags (AssemblyFlag) ask, no
    /// boundary condition applied; false outside the material's range.
    bool assemble(unsigned int flags, AssembledSystem &system) const;

    /// Unknown vector of the current state and its replacement (dof order).
    std::vector<double> solution() const;
    void                set_solution(const std::vector<double> &x);

    /// r and z (m) of the current state at reference radii @p R (m, in [A, B]).
    void profile_at(const std::vector<double> &R, std::vector<double> &r,
                    std::vector<double> &z) const;

    /// Support points (R) and component (0: r, 1: z) of each dof.
    std::vector<std::pair<double, unsigned int>> dof_support() const;

    /// Index of the dof holding z at the disk edge.
    unsigned int disk_z_dof() const override;

    // Time-dependent runs (source/fe/membrane_time.cc; doc/time.md).
    /// Replace the material law (elastic or with internal variables; the
    /// relaxed wrinkling model needs an elastic one). Internal variables
    /// start relaxed at the current state.
    void set_material_law(std::shared_ptr<const MembraneLaw> law);
    const MembraneLaw &material_law() const;
    void   set_time_step(double dt, TimeScheme scheme) override;
    void   set_inertia(const InertiaStep &inertia) override;
    void   accept_time_step() override;
    void   relax_internal_variables() override;
    double step_dissipation() const override;
    bool   has_internal_variables() const override;
    double disk_position() const override;
    EnergyBudget energy_budget() const override;
    double disk_stiffness() const override;
    std::vector<double> internal_now() const override;
    void   set_internal_start(const std::vector<double>                  &start,
                              const std::vector<const std::vector<double> *> &stages,
                              const std::vector<double> &weights, double h) override;
    double internal_error(const std::vector<const std::vector<double> *> &stages,
                          const std::vector<double> &d, double h, const std::vector<double> &end,
                          double absolute, double relative,
                          std::vector<double> *shifted) const override;
    double disk_position_change(const std::vector<double> &internal) override;
    std::vector<double> charges() const override;
    double              dissipation_rate() const override;

    /// Read-only access to the model for the computations built on its
    /// state and tangent (model_access.h): sensitivities, linear dynamics,
    /// sensitivities through time.
    ModelAccess &access();

  private:
    class Impl;
    class Access;
    class Continuation;
    std::unique_ptr<Impl>                impl;
    std::unique_ptr<Access>              model_access;
    std::unique_ptr<ContinuationProblem> continuation_problem;
  };
} // namespace cdea
