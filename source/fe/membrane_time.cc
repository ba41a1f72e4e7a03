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

  // Q_k = -int dW/dPhi dV over ring k (the ideal dielectric's W is
  // quadratic in Phi, so (1/2) Phi Q is its electrostatic energy).
  std::vector<double> MembraneModel::charges() const
  {
    Impl               &m = *impl;
    std::vector<double> charge(m.scene.n_rings(), 0.);
    MembraneTerm       &membrane = m.membrane;
    for_each_weighted_point(m.mesh, m.solution, m.scene.material.thickness,
                   [&](const unsigned int c, const unsigned int q, const PointKinematics &p,
                       const double w) {
                     const unsigned int ring = m.mesh.cells[c].ring;
                     double             dW   = 0.;
                     NominalStress      ds{0., 0.};
                     if (membrane.law().parameter_derivative(membrane.law_input(p, ring),
                                                             membrane.internal_step(c, q),
                                                             LawParameter::voltage, dW, ds))
                       charge[ring] -= w * dW;
                   });
    return charge;
  }

  EnergyBudget MembraneModel::energy_budget() const
  {
    Impl        &m = *impl;
    EnergyBudget budget;
    budget.charge          = charges();
    MembraneTerm &membrane = m.membrane;
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

  std::vector<double> MembraneModel::internal_now() const { return impl->membrane.internal_current; }

  namespace
  {
    /// Calls f(k) with the offset k of every point's stored internal
    /// variables in a vector of @p law's layout with @p size numbers.
    template <typename F>
    void for_each_stored_point(const MembraneLaw &law, const std::size_t size, F &&f)
    {
      const unsigned int n = law.n_internal_variables();
      if (n == 0 || law.n_evolving() == 0)
        return;
      for (std::size_t k = 0; k + n <= size; k += n)
        f(k);
    }
  } // namespace

  void MembraneModel::set_internal_start(const std::vector<double>                  &start,
                                         const std::vector<const std::vector<double> *> &stages,
                                         const std::vector<double> &weights, const double h)
  {
    MembraneTerm      &m   = impl->membrane;
    const MembraneLaw &law = m.law();
    std::vector<double> out = start;
    const unsigned int  ne  = law.n_evolving();
    std::vector<double> y(ne), y_j(ne), rate(ne);
    for_each_stored_point(law, out.size(), [&](const std::size_t k) {
      law.evolving_state(start.data() + k, y.data(), rate.data());
      for (std::size_t j = 0; j < stages.size(); ++j)
        if (weights[j] != 0.)
          {
            law.evolving_state(stages[j]->data() + k, y_j.data(), rate.data());
            for (unsigned int i = 0; i < ne; ++i)
              y[i] += h * weights[j] * rate[i];
          }
      law.set_evolving_state(y.data(), out.data() + k);
    });
    m.internal_old           = out;
    m.internal_current       = std::move(out);
    impl->tangent_is_current = false;
  }

  double MembraneModel::internal_error(const std::vector<const std::vector<double> *> &stages,
                                       const std::vector<double> &d, const double h,
                                       const std::vector<double> &end, const double absolute,
                                       const double relative, std::vector<double> *shifted) const
  {
    const MembraneLaw &law = impl->membrane.law();
    const unsigned int ne  = law.n_evolving();
    std::vector<double> y(ne), y_j(ne), rate(ne), estimate(ne);
    double              worst = 0.;
    if (shifted)
      *shifted = end;
    for_each_stored_point(law, end.size(), [&](const std::size_t k) {
      std::fill(estimate.begin(), estimate.end(), 0.);
      for (std::size_t j = 0; j < stages.size(); ++j)
        {
          law.evolving_state(stages[j]->data() + k, y_j.data(), rate.data());
          for (unsigned int i = 0; i < ne; ++i)
            estimate[i] += h * d[j] * rate[i];
        }
      law.evolving_state(end.data() + k, y.data(), rate.data());
      for (unsigned int i = 0; i < ne; ++i)
        {
          worst = std::max(worst, std::abs(estimate[i]) / (absolute + relative * std::abs(y[i])));
          y[i] += estimate[i];
        }
      if (shifted)
        law.set_evolving_state(y.data(), shifted->data() + k);
    });
    return worst;
  }

  // dx = -K^-1 (R(x; internal) - R(x; current)), both residuals with the
  // internal variables held (dt = 0) and K the tangent of the last solve.
  double MembraneModel::disk_position_change(const std::vector<double> &internal)
  {
    Impl         &m = *impl;
    MembraneTerm &membrane = m.membrane;
    if (!m.tangent_is_current || !m.factorize())
      return std::numeric_limits<double>::quiet_NaN();
    const double           dt = membrane.time_step();
    const TimeScheme       scheme = membrane.time_scheme();
    const std::vector<double> old = membrane.internal_old, current = membrane.internal_current;
    Eigen::VectorXd residual[2];
    membrane.set_time_step(0., scheme);
    for (unsigned int k = 0; k < 2; ++k)
      {
        membrane.internal_old     = k == 0 ? current : internal;
        membrane.internal_current = membrane.internal_old;
        m.kernel.assemble(m.solution, assemble_residual, m.query);
        residual[k] = m.query.residual;
      }
    membrane.set_time_step(dt, scheme);
    membrane.internal_old     = old;
    membrane.internal_current = current;
    Eigen::VectorXd change;
    m.solve_tangent(residual[0] - residual[1], change);
    return change[m.mesh.z_inner];
  }

  double MembraneModel::dissipation_rate() const
  {
    MembraneTerm &m = impl->membrane;
    double        D = 0.;
    if (m.n_internal() == 0)
      return D;
    const unsigned int n = m.n_internal(), per_cell = impl->mesh.energy_rule.size();
    for_each_weighted_point(impl->mesh, impl->solution, impl->scene.material.thickness,
                   [&](const unsigned int c, const unsigned int q, const PointKinematics &,
                       const double w) {
                     D += w * m.law().dissipation_rate(m.internal_current.data() +
                                                       (std::size_t(c) * per_cell + q) * n);
                   });
    return D;
  }
} // namespace cdea
