#pragma once
// The small-signal dynamics of the FE model about an equilibrium (doc/
// dynamics.md): ring voltages Phi_k + dPhi_k exp(i omega t) move the
// unknowns by u exp(i omega t) with
//
//   [K(omega) - omega^2 M] u = -(dR/dPhi_k) dPhi_k,
//
//   K(omega) = K_inst + sum_points B^T (C(omega) - C_inst) B w,
//   M        = m e_z e_z^T + rho H int N^T N 2 pi R dR + m_V g g^T.
//
// K_inst is the tangent with the material's internal variables held (the
// instantaneous, glassy film; the water load's rank-one term included), C
// the law's complex tangent at each quadrature point (material/
// linear_response.h: each viscous branch as its complex modulus), B the
// first variations of the stretches (l1, l2) there and w its weight
// 2 pi H R dR. The mass: the disk's m on z(A), the membrane's consistent
// mass with density rho (0: massless, as in the time runs), and the pump's
// water column m_V = rho_w h / S on the enclosed volume V (g = dV/dx). The
// equilibrium's internal variables are taken at rest (their rates zero: a
// relaxed network B).
//
// Natural frequencies: the modes of (Re K(omega), M) with omega of each mode
// made consistent by fixed-point iteration, M's range reduced to its rank
// (one for the disk alone); damping ratio u^T Im K u / (2 u^T Re K u).

#include <Eigen/Core>

#include <complex>
#include <memory>
#include <vector>

namespace cdea
{
  class MembraneModel;

  class LinearizedDynamics
  {
  public:
    /// About the current state of @p model (an equilibrium). @p disk_mass
    /// (kg) on z(A); @p density: the membrane's (kg/m^3); @p water_mass:
    /// rho_w h / S of the water column on the enclosed volume (kg/m^4, 0: none).
    LinearizedDynamics(MembraneModel &model, double disk_mass, double density,
                       double water_mass);
    ~LinearizedDynamics();

    unsigned int n_dofs() const;
    unsigned int n_rings() const;
    /// The dof of z(A).
    unsigned int disk_dof() const;
    /// dV/dx of the state (m^2), zero at the constrained dofs.
    const Eigen::VectorXd &volume_gradient() const;

    /// u (m/V) for a unit voltage amplitude on each ring: one column per ring.
    Eigen::MatrixXcd response(double omega) const;

    struct Mode
    {
      double          frequency     = 0.; ///< Hz
      double          damping_ratio = 0.;
      Eigen::VectorXd shape;              ///< dof values, z(A) = 1 (or largest entry 1)
    };
    /// The @p n lowest modes (fewer if the mass has a smaller rank).
    std::vector<Mode> modes(unsigned int n) const;

  private:
    class Data;
    std::unique_ptr<Data> data;
  };
} // namespace cdea
