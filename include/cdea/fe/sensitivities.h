#pragma once
// Exact sensitivities of a converged FE state. With the residual R(x, p) = 0
// at the state x(p), the state derivative follows from the tangent K = dR/dx
// of that state (already assembled and factored by Newton):
//
//   direct:   K dx/dp = -dR/dp,        dJ/dp = dJ/dp|_x + dJ/dx . dx/dp;
//   adjoint:  K^T lambda = dJ/dx,      dJ/dp = dJ/dp|_x - lambda . dR/dp.
//
// dR/dp comes from the cell kernel (assemble_parameter_derivatives): the ring
// voltages, the material constants and the dead load directly, the ring edges
// and the pre-stretch as shape derivatives (the cells move with the edges,
// the nodal values stay). The parameters are those of the Scene, in its units:
// voltages in V, mu in Pa, Jlim, eps in F/m, mass in kg, lam_pre, an
// interior ring edge k as r_v/a on the pre-stretched flat film, R_k =
// (r_v/a) a / lam_pre, and a constant of the scene's law's own
// (MembraneLaw::own_constants()) by its entry, in the entry's units.
// Changing lam_pre moves every reference radius (A = a/lam_pre, B = b/lam_pre,
// R_k), while r(A) = a and r(B) = b stay.
//
// Outputs: the displacement, the enclosed volume, and at every quadrature
// point and at each ring's inner edge (that ring's side) the hoop stress s2
// and the true electric field E = Phi l1 l2 / H. A stroke or volume change is
// the difference of two states (loaded and zero voltage), each with its own
// StateSensitivity.

#include <cdea/model/scene.h>
#include <cdea/model/equilibrium_model.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  class MembraneModel;
  class ModelAccess;

  enum class ParameterKind
  {
    voltage,
    shear_modulus,
    jlim,
    permittivity,
    mass,
    prestretch,
    ring_edge,
    law_constant ///< one of the law's own constants, by its entry
  };

  /// One parameter of a scene.
  struct SceneParameter
  {
    SceneParameter() = default;
    SceneParameter(ParameterKind kind, unsigned int index = 0, std::string entry = {})
      : kind(kind)
      , index(index)
      , entry(std::move(entry))
    {}

    ParameterKind kind  = ParameterKind::voltage;
    unsigned int  index = 0; ///< the ring of a voltage (from 0), the edge k (from 1) of a ring edge
    /// A law constant's entry of subsection Material ("Mooney-Rivlin C2 (kPa)").
    std::string entry;
    /// "voltage of ring 1 (V)", "shear modulus (Pa)", "ring edge 1 (r/a)",
    /// a law constant's entry, ...
    std::string name() const;
  };

  /// All parameters of an @p n_rings scene: the voltages, shear modulus,
  /// Jlim, permittivity, mass, pre-stretch and the n_rings - 1 interior edges.
  std::vector<SceneParameter> all_parameters(unsigned int n_rings);

  /// The value of @p parameter in @p scene (a voltage: that of the last
  /// waypoint of the path), and @p scene with it set to @p value.
  double parameter_value(const Scene &scene, const SceneParameter &parameter);
  Scene  with_parameter(const Scene &scene, const SceneParameter &parameter, double value);

  /// s2 and E at the points of a state, with their parameter derivatives.
  /// Points: the energy rule's quadrature points cell by cell, then the inner
  /// edge of each ring (its first cell's left end).
  struct PointValues
  {
    std::vector<double>       R;    ///< reference radius (m)
    std::vector<unsigned int> ring; ///< ring of the point
    unsigned int              n_quadrature_points = 0; ///< the ring edges follow them
    Eigen::VectorXd           s2;      ///< Pa
    Eigen::VectorXd           field;   ///< V/m
    Eigen::MatrixXd           d_s2;    ///< points x parameters
    Eigen::MatrixXd           d_field; ///< points x parameters
  };

  /// The tangent predictor of a state after a parameter change @p dp:
  /// unknowns x + (dx/dp) dp, the load and internal variables of @p state.
  ModelState predicted_state(const ModelState &state, const Eigen::MatrixXd &dx_dp,
                             const Eigen::VectorXd &dp);

  class StateSensitivity
  {
  public:
    /// At the current state of @p model, which must be an equilibrium (after
    /// a converged solve the tangent is at hand; otherwise it is assembled).
    /// Throws std::runtime_error if the tangent is singular.
    StateSensitivity(MembraneModel &model, std::vector<SceneParameter> parameters);

    const std::vector<SceneParameter> &parameters() const { return parameters_; }

    /// dx/dp (dof order x parameters; zero in constrained entries).
    const Eigen::MatrixXd &state_derivative() const { return dx_dp; }
    /// dR/dp (dof order x parameters; zero in constrained entries).
    const Eigen::MatrixXd &residual_derivative() const { return dR_dp; }

    /// |z(A) - z(B)| (m) and its gradient.
    double                 displacement() const { return displacement_; }
    const Eigen::VectorXd &d_displacement() const { return d_displacement_; }
    /// Enclosed volume (m^3) and its gradient.
    double                 volume() const { return volume_; }
    const Eigen::VectorXd &d_volume() const { return d_volume_; }

    /// s2 and E at every point of the state, with their gradients.
    PointValues points() const;

    /// Whether the tangent of the state (loads held) is positive definite,
    /// i.e. the state is stable: a Cholesky factorization of the band
    /// (O(n bw^2), far cheaper than its smallest eigenvalue).
    bool stable() const;

    /// Gradient of an output J by the adjoint method, from dJ/dx (dof order)
    /// and the explicit dJ/dp at fixed x.
    Eigen::VectorXd adjoint(const Eigen::VectorXd &dJ_dx,
                            const Eigen::VectorXd &dJ_dp_explicit) const;

  private:
    ModelAccess                &model; ///< the model's state and tangent, read-only
    std::vector<SceneParameter> parameters_;
    Eigen::MatrixXd             dR_dp, dx_dp;
    double                      displacement_ = 0., volume_ = 0.;
    Eigen::VectorXd             d_displacement_, d_volume_;
  };
} // namespace cdea
