// The small-signal dynamics of the FE model (see linear_dynamics.h).

#include <cdea/fe/linear_dynamics.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/fe/model_access.h>
#include <cdea/material/linear_response.h>
#include <cdea/numerics/complex_band.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cdea
{
  class LinearizedDynamics::Data
  {
  public:
    unsigned int              n = 0, rings = 0, z_dof = 0;
    std::vector<bool>         free;
    BandMatrix                stiffness, mass;
    double                    rank_one_stiffness = 0., water_mass = 0.;
    Eigen::VectorXd           g;
    Eigen::MatrixXd           load; ///< -dR/dPhi_k, one column per ring

    /// A quadrature point of a law with evolving variables.
    struct Point
    {
      const unsigned int   *dofs = nullptr;
      std::vector<double>   dl1, dl2;
      double                w = 0.;
      InternalLinearization law;
    };
    std::vector<Point> points;

    /// w B^T (C(omega) - C_inst) B of every point into @p A.
    template <typename Add>
    void add_viscous(const double omega, Add &&add) const
    {
      for (const Point &p : points)
        {
          ComplexTangent c = frequency_tangent(p.law, omega);
          c.s11 -= p.law.instantaneous.s11;
          c.s12 -= p.law.instantaneous.s12;
          c.s22 -= p.law.instantaneous.s22;
          const std::size_t m = p.dl1.size();
          for (std::size_t i = 0; i < m; ++i)
            {
              if (!free[p.dofs[i]])
                continue;
              const std::complex<double> u = p.w * (c.s11 * p.dl1[i] + c.s12 * p.dl2[i]);
              const std::complex<double> v = p.w * (c.s12 * p.dl1[i] + c.s22 * p.dl2[i]);
              for (std::size_t j = 0; j < m; ++j)
                if (free[p.dofs[j]])
                  add(p.dofs[i], p.dofs[j], u * p.dl1[j] + v * p.dl2[j]);
            }
        }
    }

    void set_up_points(const ModelAccess &m);
    void set_up_mass(const ModelAccess &m, double disk_mass, double density);
  };

  // The first variations of (l1, l2) at every point with the law's
  // linearization at the point's stored internal variables.
  void LinearizedDynamics::Data::set_up_points(const ModelAccess &m)
  {
    const MembraneLaw &law = m.membrane().law();
    if (law.n_evolving() == 0)
      return;
    m.for_each_variation_point([&](const VariationPoint &v) {
      Point p;
      p.dofs = v.dofs;
      p.w    = v.w;
      p.dl1  = v.dl1;
      p.dl2  = v.dl2;
      if (!law.linearize(v.input, v.stored, p.law))
        throw std::runtime_error("the material law cannot be linearized at the state");
      points.push_back(std::move(p));
    });
  }

  // The disk's mass on z(A) and the membrane's consistent mass
  // rho H int N_i N_j 2 pi R dR for equal components (the energy rule of
  // p + 1 Gauss points integrates it exactly).
  void LinearizedDynamics::Data::set_up_mass(const ModelAccess &m, const double disk_mass,
                                             const double density)
  {
    const Discretization &mesh = m.discretization();
    mass.reinit(n, mesh.bandwidth());
    mass(z_dof, z_dof) += disk_mass;
    if (!(density > 0.))
      return;
    const ShapeTable  &rule = mesh.energy_rule;
    const unsigned int nc   = mesh.dofs_per_cell();
    const double       rho_H = density * m.scene().material.thickness;
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const MeshCell     &cell = mesh.cells[c];
        const unsigned int *dofs = mesh.dofs_of(c);
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const double R = cell.x0 + cell.h * rule.points[q];
            const double w = rho_H * 2. * M_PI * R * cell.h * rule.weights[q];
            const double *v = &rule.value[q * nc];
            for (unsigned int i = 0; i < nc; ++i)
              for (unsigned int j = 0; j < nc; ++j)
                if (mesh.component[i] == mesh.component[j] && free[dofs[i]] &&
                    free[dofs[j]])
                  mass(dofs[i], dofs[j]) += w * v[i] * v[j];
          }
      }
  }

  LinearizedDynamics::LinearizedDynamics(MembraneModel &model, const double disk_mass,
                                         const double density, const double water_mass)
    : data(std::make_unique<Data>())
  {
    ModelAccess          &m    = model.access();
    const Discretization &mesh = m.discretization();
    Data                 &d    = *data;
    d.n     = mesh.n_dofs();
    d.rings = m.scene().n_rings();
    d.z_dof = mesh.z_inner;
    d.free.assign(d.n, true);
    for (const unsigned int i : mesh.constrained)
      d.free[i] = false;

    // The tangent with the internal variables held and no inertia.
    if (!m.assemble_without_inertia(InternalVariables::held,
                                    assemble_residual | assemble_tangent |
                                      assemble_parameter_derivatives | assemble_volume))
      throw std::runtime_error("the state lies outside the material's range");
    const AssembledSystem &system = m.system();
    d.stiffness          = system.tangent;
    d.rank_one_stiffness = system.rank_one_coupling;
    d.g                  = system.volume_gradient;
    d.load.resize(d.n, d.rings);
    ParameterLayout layout;
    layout.n_rings = d.rings;
    for (unsigned int k = 0; k < d.rings; ++k)
      d.load.col(k) = -system.parameter_residual[layout.voltage(k)];
    for (unsigned int i = 0; i < d.n; ++i)
      if (!d.free[i])
        {
          d.g[i] = 0.;
          d.load.row(i).setZero();
        }
    d.water_mass = water_mass;
    d.set_up_points(m);
    d.set_up_mass(m, disk_mass, density);
  }

  LinearizedDynamics::~LinearizedDynamics() = default;

  unsigned int LinearizedDynamics::n_dofs() const { return data->n; }
  unsigned int LinearizedDynamics::n_rings() const { return data->rings; }
  unsigned int LinearizedDynamics::disk_dof() const { return data->z_dof; }
  const Eigen::VectorXd &LinearizedDynamics::volume_gradient() const { return data->g; }

  Eigen::MatrixXcd LinearizedDynamics::response(const double omega) const
  {
    const Data   &d = *data;
    ComplexBandLU A;
    A.assign(d.stiffness);
    for (unsigned int j = 0; j < d.n; ++j)
      for (unsigned int i = j > d.mass.bandwidth() ? j - d.mass.bandwidth() : 0;
           i <= std::min(d.n - 1, j + d.mass.bandwidth()); ++i)
        if (d.free[i] && d.free[j])
          A(i, j) -= omega * omega * d.mass.entry(i, j);
    d.add_viscous(omega, [&](const unsigned int i, const unsigned int j,
                             const std::complex<double> &value) { A(i, j) += value; });
    const double     coupling = d.rank_one_stiffness - omega * omega * d.water_mass;
    Eigen::MatrixXcd u        = d.load.cast<std::complex<double>>();
    if (!A.factorize(coupling, d.g) || !A.solve(u))
      throw std::runtime_error("the small-signal system is singular at " +
                               std::to_string(omega / (2. * M_PI)) + " Hz");
    return u;
  }

  namespace
  {
    /// The rows and columns of @p free dofs of a band matrix, dense.
    Eigen::MatrixXd dense_free(const BandMatrix &band, const std::vector<unsigned int> &free)
    {
      const Eigen::Index n = free.size();
      Eigen::MatrixXd    dense(n, n);
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j)
          dense(i, j) = band.entry(free[i], free[j]);
      return dense;
    }

    /// L with M = L L^T over the range of the symmetric positive
    /// semi-definite @p M (its eigenvectors times sqrt(eigenvalue)).
    Eigen::MatrixXd range_factor(const Eigen::MatrixXd &M)
    {
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(M);
      const Eigen::VectorXd                               &mu = eigen.eigenvalues();
      std::vector<Eigen::Index>                            range;
      for (Eigen::Index k = 0; k < mu.size(); ++k)
        if (mu[k] > 1e-12 * mu.maxCoeff())
          range.push_back(k);
      Eigen::MatrixXd L(M.rows(), Eigen::Index(range.size()));
      for (std::size_t k = 0; k < range.size(); ++k)
        L.col(k) = eigen.eigenvectors().col(range[k]) * std::sqrt(mu[range[k]]);
      return L;
    }
  } // namespace

  std::vector<LinearizedDynamics::Mode> LinearizedDynamics::modes(const unsigned int wanted) const
  {
    const Data               &d = *data;
    std::vector<unsigned int> free;
    for (unsigned int i = 0; i < d.n; ++i)
      if (d.free[i])
        free.push_back(i);
    const Eigen::Index nf = free.size();
    Eigen::VectorXd    g(nf);
    for (Eigen::Index i = 0; i < nf; ++i)
      g[i] = d.g[free[i]];

    const Eigen::MatrixXd L =
      range_factor(dense_free(d.mass, free) + d.water_mass * g * g.transpose());

    const Eigen::MatrixXd K_inst =
      dense_free(d.stiffness, free) + d.rank_one_stiffness * g * g.transpose();
    std::vector<int> index(d.n, -1);
    for (Eigen::Index i = 0; i < nf; ++i)
      index[free[i]] = int(i);
    // Re or Im of K(omega) - K_inst, dense on the free dofs.
    const auto viscous = [&](const double omega, const bool imaginary) {
      Eigen::MatrixXd V = Eigen::MatrixXd::Zero(nf, nf);
      d.add_viscous(omega, [&](const unsigned int i, const unsigned int j,
                               const std::complex<double> &value) {
        V(index[i], index[j]) += imaginary ? value.imag() : value.real();
      });
      return V;
    };

    std::vector<Mode> result;
    const unsigned int count = std::min<unsigned int>(wanted, L.cols());
    for (unsigned int k = 0; k < count; ++k)
      {
        // Fixed point in omega: the k-th mode of (Re K(omega), M) at omega.
        double          omega = 0.;
        Eigen::VectorXd shape;
        Eigen::MatrixXd K;
        for (unsigned int iteration = 0; iteration < 50; ++iteration)
          {
            K = K_inst + viscous(omega > 0. ? omega : 1e12, false);
            const Eigen::MatrixXd X = K.ldlt().solve(L);
            const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reduced(L.transpose() * X);
            // Largest eigenvalue of L^T K^-1 L: the lowest frequency.
            const Eigen::Index column = reduced.eigenvalues().size() - 1 - k;
            const double       flex   = reduced.eigenvalues()[column];
            if (!(flex > 0.))
              break;
            const double next = 1. / std::sqrt(flex);
            shape             = X * reduced.eigenvectors().col(column);
            const bool done   = std::abs(next - omega) <= 1e-12 * next;
            omega             = next;
            if (done)
              break;
          }
        if (!(omega > 0.))
          break;
        Mode mode;
        mode.frequency     = omega / (2. * M_PI);
        mode.damping_ratio = 0.5 * shape.dot(viscous(omega, true) * shape) / shape.dot(K * shape);
        mode.shape         = Eigen::VectorXd::Zero(d.n);
        for (Eigen::Index i = 0; i < nf; ++i)
          mode.shape[free[i]] = shape[i];
        const double disk = mode.shape[d.z_dof];
        const double scale =
          std::abs(disk) > 1e-6 * mode.shape.cwiseAbs().maxCoeff() ? disk :
                                                                     mode.shape.cwiseAbs().maxCoeff();
        mode.shape /= scale;
        result.push_back(mode);
      }
    return result;
  }
} // namespace cdea
