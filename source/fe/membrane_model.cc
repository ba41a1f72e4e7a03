#include "membrane_model_impl.h"

#include <cdea/numerics/arc_length.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cdea
{
  MembraneModel::Impl::Impl(const Scene &scene_in, const FeDiscretization &disc,
                            const NewtonSettings &newton)
    : scene(scene_in)
    , newton_settings(newton)
    , mesh(scene_in, disc)
    , plain_law(scene_in.law())
    , relaxed_law(plain_law->n_internal_variables() == 0 ?
                    std::make_shared<TensionField>(plain_law) :
                    nullptr)
    , kernel(mesh, scene_in.n_rings())
    , membrane(kernel.add_term(std::make_unique<MembraneTerm>(scene_in, mesh, plain_law)))
    , solution(Eigen::VectorXd::Zero(mesh.n_dofs()))
    , solver(make_tangent_solver(LinearSolver::banded_lu))
  {
    // The terms add into each cell in this order (fixed: it decides the last
    // bits of every sum): the model's own, the load terms (set_load_terms(),
    // in the registry's order), inertia.
    kernel.add_term(std::make_unique<DeadLoadTerm>());
    kernel.add_term(std::make_unique<EnclosedVolumeTerm>());
    load_term_slot = kernel.n_terms();
    kernel.add_term(std::make_unique<InertiaTerm>());
    kernel.set_law_constants(plain_law->own_constants().size());
  }

  void MembraneModel::Impl::set_load(const LoadState &new_load)
  {
    load = new_load;
    if (load.voltages.size() != scene.n_rings())
      load.voltages.assign(scene.n_rings(), 0.);
    kernel.set_load(load);
    tangent_is_current = false;
  }

  void MembraneModel::Impl::apply_boundary_values(Eigen::VectorXd &x) const
  {
    x[mesh.r_inner] = load.stretch * scene.inner_reference_radius();
    x[mesh.r_outer] = load.stretch * scene.outer_reference_radius();
    x[mesh.z_outer] = 0.;
  }

  double MembraneModel::Impl::residual_scale() const
  {
    return std::max({load.force,
                     2. * M_PI * scene.material.thickness * scene.material.shear_modulus *
                       scene.disk_radius,
                     kernel.term<InertiaTerm>().step().residual_scale});
  }

  bool MembraneModel::Impl::assemble_constrained(const Eigen::VectorXd &x, const unsigned int flags)
  {
    factorized         = false;
    tangent_is_current = false;
    const bool ok      = kernel.assemble(x, flags, system);
    for (const unsigned int i : mesh.constrained)
      {
        if (flags & assemble_residual)
          system.residual[i] = 0.;
        if (ok && (flags & assemble_tangent))
          {
            // Keep the scale of the matrix on the decoupled diagonal.
            const double d = std::abs(system.tangent(i, i));
            system.tangent.constrain(i, d > 0. ? d : 1.);
            if (system.rank_one_coupling != 0.)
              system.volume_gradient[i] = 0.;
          }
      }
    return ok;
  }

  void MembraneModel::Impl::ensure_converged_tangent()
  {
    if (!tangent_is_current)
      return;
    converged_tangent_used = true;
    if (!(system.flags & assemble_tangent))
      {
        assemble_constrained(solution, assemble_residual | assemble_tangent);
        tangent_is_current = true;
      }
  }

  bool MembraneModel::Impl::factorize()
  {
    if (factorized)
      return true;
    ensure_converged_tangent();
    free_surface = ShermanMorrison();
    factorized   = solver->factorize(system.tangent);
    if (factorized && system.rank_one_coupling != 0.)
      factorized = free_surface.prepare(*solver, system.rank_one_coupling, system.volume_gradient);
    return factorized;
  }

  void MembraneModel::Impl::solve_tangent(const Eigen::VectorXd &b, Eigen::VectorXd &u)
  {
    u = b;
    solve_in_place(u);
  }

  void MembraneModel::Impl::solve_in_place(Eigen::VectorXd &u)
  {
    for (const unsigned int i : mesh.constrained)
      u[i] = 0.;
    // A singular tangent: a non-finite update makes Newton and the arc-length
    // corrector report a failed step, which the driver cuts back or reports.
    if (!factorize() || !free_surface.solve(*solver, u))
      {
        u.setConstant(std::numeric_limits<double>::quiet_NaN());
        return;
      }
    for (const unsigned int i : mesh.constrained)
      u[i] = 0.;
  }

  void MembraneModel::Impl::evaluate(const Eigen::VectorXd &x, Eigen::VectorXd &r)
  {
    assemble_constrained(x, assemble_residual | assemble_tangent);
    r = system.residual;
  }

  void MembraneModel::Impl::evaluate_residual(const Eigen::VectorXd &x, Eigen::VectorXd &r)
  {
    assemble_constrained(x, assemble_residual);
    r = system.residual;
  }

  void MembraneModel::Impl::solve_linearized(const Eigen::VectorXd &r, Eigen::VectorXd &dx)
  {
    dx = -r;
    solve_in_place(dx);
  }

  double MembraneModel::Impl::residual_floor(const Eigen::VectorXd &x) const
  {
    const BandMatrix &K = system.tangent;
    if (K.size() != x.size())
      return 0.;
    const unsigned int bw      = K.bandwidth();
    double             largest = 0.;
    for (unsigned int i = 0; i < K.size(); ++i)
      {
        const unsigned int lo = i > bw ? i - bw : 0;
        const unsigned int hi = std::min(K.size() - 1, i + bw);
        double             sum = 0.;
        for (unsigned int j = lo; j <= hi; ++j)
          sum += std::abs(K(i, j) * x[j]);
        largest = std::max(largest, sum);
      }
    return 10. * std::numeric_limits<double>::epsilon() * largest;
  }

  bool MembraneModel::Access::state_tangent()
  {
    if (!m.tangent_is_current)
      {
        if (!m.assemble_constrained(m.solution, assemble_residual | assemble_tangent))
          return false;
        m.tangent_is_current = true;
      }
    return true;
  }

  bool MembraneModel::Access::assemble_without_inertia(const InternalVariables internal,
                                                       const unsigned int        flags)
  {
    MembraneTerm     &membrane = m.membrane;
    InertiaTerm      &inertia  = m.kernel.term<InertiaTerm>();
    const double      dt       = membrane.time_step();
    const TimeScheme  scheme   = membrane.time_scheme();
    const InertiaStep step     = inertia.step();
    const bool        relaxed  = internal == InternalVariables::relaxed;
    std::vector<double> old, current;
    if (relaxed)
      {
        old     = membrane.internal_old;
        current = membrane.internal_current;
      }
    membrane.set_time_step(relaxed ? std::numeric_limits<double>::infinity() : 0., scheme);
    inertia.set_step(InertiaStep());
    const bool ok = m.assemble_constrained(m.solution, flags);
    membrane.set_time_step(dt, scheme);
    inertia.set_step(step);
    if (relaxed)
      {
        membrane.internal_old     = std::move(old);
        membrane.internal_current = std::move(current);
      }
    m.tangent_is_current = false;
    return ok;
  }

  MembraneModel::MembraneModel(const Scene &scene, const FeDiscretization &discretization,
                               const NewtonSettings &newton)
    : impl(std::make_unique<Impl>(scene, discretization, newton))
    , model_access(std::make_unique<Access>(*impl))
  {
    set_reference_state();
    relax_internal_variables();
  }

  ModelAccess &MembraneModel::access() { return *model_access; }

  unsigned int MembraneModel::n_dofs() const { return impl->mesh.n_dofs(); }
  unsigned int MembraneModel::n_elements() const { return impl->mesh.n_cells(); }
  const Discretization &MembraneModel::discretization() const { return impl->mesh; }
  unsigned int MembraneModel::disk_z_dof() const { return impl->mesh.z_inner; }
  const LoadState &MembraneModel::load() const { return impl->load; }

  void MembraneModel::set_reference_state()
  {
    LoadState reference;
    reference.stretch = 1.;
    impl->set_load(reference);
    // r = R, z = 0 at every support point.
    for (unsigned int i = 0; i < n_dofs(); ++i)
      impl->solution[i] = impl->mesh.support_component[i] == 0 ? impl->mesh.support_radius[i] : 0.;
    impl->membrane.internal_old.assign(impl->membrane.internal_old.size(), 0.);
    impl->membrane.internal_current = impl->membrane.internal_old;
  }

  std::vector<std::pair<double, unsigned int>> MembraneModel::dof_support() const
  {
    std::vector<std::pair<double, unsigned int>> support(n_dofs());
    for (unsigned int i = 0; i < n_dofs(); ++i)
      support[i] = {impl->mesh.support_radius[i], impl->mesh.support_component[i]};
    return support;
  }

  SolveReport MembraneModel::solve(const LoadState &load)
  {
    const LoadState       old_load     = impl->load;
    const Eigen::VectorXd old_solution = impl->solution;

    // Predictor: the homogeneous part of a change of pre-stretch is exact
    // (r scales with the stretch); otherwise start from the current state.
    if (load.stretch != old_load.stretch)
      for (unsigned int i = 0; i < n_dofs(); ++i)
        if (impl->mesh.support_component[i] == 0)
          impl->solution[i] *= load.stretch / old_load.stretch;
    impl->set_load(load);
    impl->apply_boundary_values(impl->solution);

    NewtonSettings settings = impl->newton_settings;
    settings.residual_scale = impl->residual_scale();
    settings.update_scale   = impl->scene.disk_radius;
    settings.exact_tangent  = impl->membrane.law().tangent_is_exact();
    // The converged state's tangent only if the last one was used (by the
    // stability check, say); else it is assembled when asked for.
    settings.residual_alone_when_converging =
      settings.residual_alone_when_converging && !impl->converged_tangent_used;
    impl->converged_tangent_used            = false;
    LineSearchNewton newton(settings);
    SolveReport      report = newton.solve(*impl, impl->solution);
    // Newton's last evaluation was at the converged state: a term may reject
    // it (the water's free surface below the frame plane).
    if (report.converged)
      if (std::string why = impl->kernel.reject_state(impl->system); !why.empty())
        {
          report.converged = false;
          report.message   = why;
        }
    if (!report.converged)
      {
        report.message += impl->gent_limit_note(impl->solution);
        impl->set_load(old_load);
        impl->solution = old_solution;
        return report;
      }
    // Newton's last evaluation was at the converged state (with its tangent, or
    // that left for ensure_converged_tangent()).
    impl->tangent_is_current = true;
    return report;
  }

  bool MembraneModel::assemble(const unsigned int flags, AssembledSystem &system) const
  {
    const bool ok = impl->kernel.assemble(impl->solution, flags, system);
    return ok;
  }

  double MembraneModel::energy() const
  {
    impl->kernel.assemble(impl->solution, assemble_energy, impl->query);
    return impl->query.energy;
  }

  std::vector<double> MembraneModel::residual_vector() const
  {
    const Eigen::VectorXd &r = impl->query.residual;
    impl->kernel.assemble(impl->solution, assemble_residual, impl->query);
    return {r.data(), r.data() + r.size()};
  }

  std::vector<std::vector<double>> MembraneModel::tangent_matrix() const
  {
    const AssembledSystem &s = impl->query;
    impl->kernel.assemble(impl->solution, assemble_tangent, impl->query);
    const unsigned int               n = n_dofs();
    std::vector<std::vector<double>> K(n, std::vector<double>(n, 0.));
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        K[i][j] = s.tangent.entry(i, j) +
                  (s.rank_one_coupling != 0. ?
                     s.rank_one_coupling * s.volume_gradient[i] * s.volume_gradient[j] :
                     0.);
    return K;
  }

  TangentStability MembraneModel::Impl::check_stability(const bool with_eigenvalue)
  {
    ensure_converged_tangent();
    return stability_check.compute(system.tangent, mesh.constrained, system.rank_one_coupling,
                                   system.volume_gradient, with_eigenvalue);
  }

  TangentStability MembraneModel::Impl::check_stability_near_folds(const bool first)
  {
    ensure_converged_tangent();
    return stability_check.compute_near_folds(system.tangent, mesh.constrained,
                                              system.rank_one_coupling, system.volume_gradient,
                                              first);
  }

  StateStability MembraneModel::stability(const StabilityEigenvalue eigenvalue)
  {
    if (!impl->tangent_is_current)
      {
        impl->assemble_constrained(impl->solution, assemble_residual | assemble_tangent);
        impl->tangent_is_current = true;
      }
    const TangentStability t =
      eigenvalue == StabilityEigenvalue::every_step ?
        impl->check_stability(true) :
        impl->check_stability_near_folds(eigenvalue == StabilityEigenvalue::near_folds_first);
    return {t.smallest_eigenvalue,
            t.known ? double(t.positive_definite) : std::numeric_limits<double>::quiet_NaN()};
  }

  double MembraneModel::min_tangent_eigenvalue()
  {
    return stability(StabilityEigenvalue::every_step).min_eigenvalue;
  }

  void MembraneModel::set_relaxed(const bool relaxed)
  {
    if (relaxed && impl->plain_law->n_internal_variables() != 0)
      throw std::invalid_argument("MembraneModel::set_relaxed: the relaxed (tension-field) "
                                  "membrane needs an elastic law");
    impl->relaxed = relaxed;
    impl->membrane.set_law(relaxed ? impl->relaxed_law : impl->plain_law);
    impl->tangent_is_current = false;
  }

  bool MembraneModel::relaxed() const { return impl->relaxed; }

  void MembraneModel::set_linear_solver(const LinearSolver solver)
  {
    if (solver != impl->linear_solver)
      {
        impl->linear_solver = solver;
        impl->solver        = make_tangent_solver(solver);
        impl->factorized    = false;
      }
  }

  void MembraneModel::set_load_terms(const ParameterValues &values)
  {
    set_load_terms(make_load_terms(values));
  }

  void MembraneModel::set_load_terms(std::vector<std::unique_ptr<LoadTerm>> terms)
  {
    Impl                                  &m         = *impl;
    const std::size_t                      n_before  = m.load_terms.size();
    std::vector<std::unique_ptr<CellTerm>> cell_terms;
    m.load_terms.clear();
    for (auto &term : terms)
      {
        term->set_load(m.load);
        m.load_terms.push_back(term.get());
        cell_terms.push_back(std::move(term));
      }
    m.kernel.replace_terms(m.load_term_slot, n_before, std::move(cell_terms));
    m.tangent_is_current = false;
  }

  std::vector<const LoadTerm *> MembraneModel::load_terms() const
  {
    return {impl->load_terms.begin(), impl->load_terms.end()};
  }

  double MembraneModel::enclosed_volume() const
  {
    impl->kernel.assemble(impl->solution, assemble_volume, impl->query);
    return impl->query.volume;
  }

  std::vector<double> MembraneModel::solution() const
  {
    return {impl->solution.data(), impl->solution.data() + impl->solution.size()};
  }

  void MembraneModel::set_solution(const std::vector<double> &x)
  {
    std::copy(x.begin(), x.end(), impl->solution.data());
    impl->tangent_is_current = false;
  }

  ModelState MembraneModel::state() const
  {
    return {impl->load, solution(), impl->membrane.internal_old};
  }

  void MembraneModel::set_state(const ModelState &s)
  {
    if (s.unknowns.size() != n_dofs() || s.load.voltages.size() != impl->scene.n_rings() ||
        s.internal.size() != impl->membrane.internal_old.size())
      throw std::invalid_argument("MembraneModel::set_state: not a state of this model");
    impl->set_load(s.load);
    set_solution(s.unknowns);
    impl->membrane.internal_old     = s.internal;
    impl->membrane.internal_current = s.internal;
  }

  MembraneModel::~MembraneModel() = default;

  void MembraneModel::predict(const ModelState &older, const double factor)
  {
    if (older.unknowns.size() != n_dofs())
      return;
    for (unsigned int i = 0; i < n_dofs(); ++i)
      impl->solution[i] += factor * (impl->solution[i] - older.unknowns[i]);
    impl->tangent_is_current = false;
  }
} // namespace cdea
