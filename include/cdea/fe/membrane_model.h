#pragma once
// Axisymmetric nonlinear membrane FE model of the cone actuator.
//
// Unknowns r(R) and z(R) on the undeformed radius R in [A, B], an FESystem of
// two FE_Q of degree p; element boundaries lie on every ring edge and each
// element carries the voltage of its ring. The total potential
//
//   Pi[r, z] = 2 pi H int_A^B W(l1, l2; Phi) R dR  -  F z(A)  [+ E_w, see WaterLoad],
//   l1 = sqrt(r'^2 + z'^2),  l2 = r / R,
//
// is stationary at equilibrium; its first and second variations give the
// residual and the exact tangent (see doc/theory.md). Boundary conditions:
// r(A) = s A and r(B) = s B with s the current pre-stretch (s = lam_pre after
// stage 0), z(B) = 0; z(A) is free and carries the dead load.
//
// The deal.II machinery stays in the source file (pimpl) so that including
// this header is cheap.

#include <cdea/scene.h>
#include <cdea/solver/equilibrium_model.h>
#include <cdea/solver/newton.h>

#include <memory>

namespace cdea
{
  /// How the tangent systems are solved: LAPACK's banded LU (factored once
  /// per assembly, cheap for the banded 1D tangent) or Trilinos' sparse
  /// direct solver KLU (through deal.II's wrappers).
  enum class LinearSolver
  {
    banded_lu,
    trilinos_klu
  };

  struct FeDiscretization
  {
    unsigned int degree              = 4;
    unsigned int elements_per_ring   = 4;
    double       grading             = 4.;
    unsigned int refinements         = 0;
    unsigned int samples_per_element = 16;
  };

  /// Hydrostatic load of the pump module's water (doc/pump.md). The water
  /// fills the cone above the membrane and the disk (z > 0 is down) and rises
  /// in a level tube of cross-section tube_area above the frame plane, to the
  /// free-surface height h = (water_volume - V) / tube_area with V the
  /// enclosed volume. The pressure rho g (h + z) acts normal to the deformed
  /// membrane and on the disk. It is conservative, with the potential
  ///   E_w = rho g [(water_volume - V)^2 / (2 tube_area) - pi int r^2 z (-z') dR],
  /// added to Pi (residual and exact tangent; the tangent has a dense rank-one
  /// part from h(V), solved by Sherman-Morrison). Gravity ramps with the load
  /// stage: off in stage 0, times the load factor in stage 1, full in stage 2.
  struct WaterLoad
  {
    bool   enabled      = false;
    double density      = 1000.;  ///< kg/m^3
    double gravity      = 9.81;   ///< m/s^2
    double water_volume = 150e-6; ///< m^3, in the cone and the tube together
    double tube_area    = 400e-6; ///< m^2, cross-section of the level tube
  };

  class MembraneModel : public EquilibriumModel
  {
  public:
    MembraneModel(const Scene &scene, const FeDiscretization &discretization,
                  const NewtonSettings &newton);
    ~MembraneModel() override;

    void                set_reference_state() override;
    SolveReport         solve(const LoadState &load) override;
    StepSummary         summary() const override;
    StepFields          fields() const override;
    std::vector<double> state() const override;
    void                set_state(const std::vector<double> &state) override;
    void predict(const std::vector<double> &older_state, double factor) override;
    ContinuationProblem *continuation(const std::function<LoadState(double)> &path) override;
    double               min_tangent_eigenvalue() const override;

    /// Tension-field relaxation where the hoop stress would be negative
    /// (Wrinkling/Model = relaxed); off: the plain law everywhere.
    void set_relaxed(bool relaxed);
    bool relaxed() const;

    void set_linear_solver(LinearSolver solver);

    /// pi int_A^B r^2 (-z') dR by Gauss quadrature exact for the FE solution.
    double enclosed_volume() const override;

    /// Switch the water load on or off (off by default); it applies from the next solve.
    void             set_water_load(const WaterLoad &water);
    const WaterLoad &water_load() const;
    /// Free-surface height h above the frame plane at the current state (m).
    double free_surface_height() const;

    unsigned int n_dofs() const;
    unsigned int n_elements() const;

    /// Total potential Pi at the current state and load (J).
    double energy() const;

    /// Residual and tangent at the current state and load, in natural dof
    /// order with no boundary condition applied (for tests against finite
    /// differences and automatic differentiation).
    std::vector<double>              residual_vector() const;
    std::vector<std::vector<double>> tangent_matrix() const;

    /// Unknown vector of the current state and its replacement (dof order).
    std::vector<double> solution() const;
    void                set_solution(const std::vector<double> &x);

    /// r and z (m) of the current state at reference radii @p R (m, in [A, B]).
    void profile_at(const std::vector<double> &R, std::vector<double> &r,
                    std::vector<double> &z) const;

    /// Support points (R) and component (0: r, 1: z) of each dof.
    std::vector<std::pair<double, unsigned int>> dof_support() const;

    /// Index of the dof holding z at the disk edge.
    unsigned int disk_z_dof() const;

  private:
    class Impl;
    class Continuation;
    std::unique_ptr<Impl>         impl;
    std::unique_ptr<Continuation> continuation_problem;
  };
} // namespace cdea
