// MembraneModel in time-dependent runs: the material law with internal
// variables, their time step and acceptance, the inertia terms, and the
// energy budget of a state (transient_model.h).

#include "membrane_model_impl.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cdea
{
  namespace
  {
    /// Calls f(cell, q, kinematics, quadrature weight 2 pi H R h w_q) at every
    /// point of the energy rule of @p x.
    template <typename F>
    void for_each_weighted_point(const Discretization &mesh, const Eigen::VectorXd &x,
                                 const double thickness, F &&f)
    {
      const ShapeTable &rule = mesh.energy_rule;
      for_each_point(mesh, rule, x,
                     [&](const unsigned int c, const unsigned int q, const PointKinematics &p) {
                       f(c, q, p, 2. * M_PI * thickness * p.R * mesh.cells[c].h * rule.weights[q]);
                     });
    }
  } // namespace

  void MembraneModel::set_material_law(std::shared_ptr<const MembraneLaw> law)
  {
    if (!law)
      throw std::invalid_argument("MembraneModel::set_material_law: no law");
    const bool elastic = law->n_internal_variables() == 0;
    if (!elastic && impl->relaxed)
      throw std::invalid_argument("MembraneModel::set_material_law: the relaxed (tension-field) "
                                  "membrane needs an elastic law");
    impl->plain_law = law;
    impl->relaxed_law = elastic ? std::make_shared<TensionField>(law) : nullptr;
    impl->kernel.set_law_constants(law->own_constants().size());
    impl->membrane.set_law(impl->relaxed ? impl->relaxed_law : impl->plain_law);
    relax_internal_variables();
    impl->tangent_is_current = false;
  }

  const MembraneLaw &MembraneModel::material_law() const { return *impl->plain_law; }

  bool MembraneModel::has_internal_variables() const { return impl->membrane.n_internal() > 0; }

  void MembraneModel::set_time_step(const double dt, const TimeScheme scheme)
  {
    impl->membrane.set_time_step(dt, scheme);
    impl->tangent_is_current = false;
  }

  void MembraneModel::set_inertia(const InertiaStep &inertia)
  {
    impl->kernel.term<InertiaTerm>().set_step(inertia);
    impl->tangent_is_current = false;
  }

  void MembraneModel::accept_time_step()
  {
    // Newton's last assembly was at the converged state.
    impl->membrane.accept_internal();
    impl->tangent_is_current = false;
  }

  void MembraneModel::relax_internal_variables()
  {
    MembraneTerm      &m = impl->membrane;
    const unsigned int n = m.n_internal();
    if (n == 0)
      return;
    const unsigned int per_cell = impl->mesh.energy_rule.size();
    for_each_weighted_point(impl->mesh, impl->solution, impl->scene.material.thickness,
                   [&](const unsigned int c, const unsigned int q, const PointKinematics &p,
                       double) {
                     m.law().relaxed_internal_variables(
                       m.law_input(p, impl->mesh.cells[c].ring),
                       m.internal_old.data() + (std::size_t(c) * per_cell + q) * n);
                   });
    m.internal_current       = m.internal_old;
    impl->tangent_is_current = false;
  }

  double MembraneModel::step_dissipation() const
  {
    MembraneTerm &m = impl->membrane;
    double        D = 0.;
    if (m.n_internal() == 0)
      return D;
    for_each_weighted_point(impl->mesh, impl->solution, impl->scene.material.thickness,
                   [&](const unsigned int c, const unsigned int q, const PointKinematics &,
                       const double w) { D += w * m.law().dissipation(m.internal_step(c, q)); });
    return D;
  }

  double MembraneModel::disk_position() const { return impl->solution[impl->mesh.z_inner]; }

  EnergyBudget MembraneModel::energy_budget() const
  {
    Impl        &m = *impl;
    EnergyBudget budget;
    budget.charge.assign(m.scene.n_rings(), 0.);

    // Q_k = -int dW/dPhi dV over ring k (the ideal dielectric's W is
    // quadratic in Phi, so (1/2) Phi Q is its electrostatic energy).
    MembraneTerm &membrane = m.membrane;
    for_each_weighted_point(m.mesh, m.solution, m.scene.material.thickness,
                   [&](const unsigned int c, const unsigned int q, const PointKinematics &p,
                       const double w) {
                     const unsigned int ring = m.mesh.cells[c].ring;
                     double             dW   = 0.;
                     NominalStress      ds{0., 0.};
                     if (membrane.law().parameter_derivative(membrane.law_input(p, ring),
                                                             membrane.internal_step(c, q),
                                                             LawParameter::voltage, dW, ds))
                       budget.charge[ring] -= w * dW;
                   });
    for (unsigned int k = 0; k < budget.charge.size(); ++k)
      budget.electrostatic += 0.5 * m.load.voltages[k] * budget.charge[k];

    // The potential at zero voltage with the accepted internal variables held
    // (dt = 0) and no inertia: elastic energy - F z(A) + water potential.
    const double              dt      = membrane.time_step();
    const TimeScheme          scheme  = membrane.time_scheme();
    InertiaTerm              &inertia_term = m.kernel.term<InertiaTerm>();
    const InertiaStep         inertia      = inertia_term.step();
    const std::vector<double> current = membrane.internal_current;
    membrane.set_time_step(0., scheme);
    membrane.set_voltages(std::vector<double>(m.scene.n_rings(), 0.));
    inertia_term.set_step(InertiaStep());
    AssembledSystem s;
    m.kernel.assemble(m.solution, assemble_energy, s);
    budget.mechanical = s.energy;
    membrane.set_time_step(dt, scheme);
    membrane.set_voltages(m.load.voltages);
    inertia_term.set_step(inertia);
    membrane.internal_current = current;
    return budget;
  }

  // k = K_zz - K_zf K_ff^-1 K_fz over the free unknowns f other than z(A),
  // with the internal variables held (dt = 0) and no inertia.
  double MembraneModel::disk_stiffness() const
  {
    Impl             &m       = *impl;
    const double      dt      = m.membrane.time_step();
    const TimeScheme  scheme  = m.membrane.time_scheme();
    InertiaTerm      &inertia_term = m.kernel.term<InertiaTerm>();
    const InertiaStep inertia      = inertia_term.step();
    const std::vector<double> current = m.membrane.internal_current;
    m.membrane.set_time_step(0., scheme);
    inertia_term.set_step(InertiaStep());
    const auto K = tangent_matrix();
    m.membrane.set_time_step(dt, scheme);
    inertia_term.set_step(inertia);
    m.membrane.internal_current = current;

    const unsigned int        z = m.mesh.z_inner;
    std::vector<unsigned int> others;
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (i != z && std::find(m.mesh.constrained.begin(), m.mesh.constrained.end(), i) ==
                      m.mesh.constrained.end())
        others.push_back(i);
    const int       n = others.size();
    Eigen::MatrixXd Kff(n, n);
    Eigen::VectorXd Kfz(n);
    for (int i = 0; i < n; ++i)
      {
        Kfz[i] = K[others[i]][z];
        for (int j = 0; j < n; ++j)
          Kff(i, j) = K[others[i]][others[j]];
      }
    return K[z][z] - Kfz.dot(Kff.ldlt().solve(Kfz));
  }
} // namespace cdea
