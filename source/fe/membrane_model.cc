#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cdea/app/mpi_session.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/material/tension_field.h>
#include <cdea/solver/arc_length.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

// LAPACK: LU factorization of a general band matrix and solves with it.
extern "C" void dgbtrf_(const int *m, const int *n, const int *kl, const int *ku, double *ab,
                        const int *ldab, int *ipiv, int *info);
extern "C" void dgbtrs_(const char *trans, const int *n, const int *kl, const int *ku,
                        const int *nrhs, const double *ab, const int *ldab, const int *ipiv,
                        double *b, const int *ldb, int *info);
// LAPACK: selected eigenvalues of a symmetric band matrix.
extern "C" void dsbevx_(const char *jobz, const char *range, const char *uplo, const int *n,
                        const int *kd, double *ab, const int *ldab, double *q, const int *ldq,
                        const double *vl, const double *vu, const int *il, const int *iu,
                        const double *abstol, int *m, double *w, double *z, const int *ldz,
                        double *work, int *iwork, int *ifail, int *info);

namespace cdea
{
  using namespace dealii;
  using Cell = DoFHandler<1>::active_cell_iterator;

  namespace
  {
    /// Element lengths of one ring: geometric, smallest at the ring's inner
    /// edge, the last @p grading times the first.
    std::vector<double> graded_steps(const double length, const unsigned int n,
                                     const double grading)
    {
      std::vector<double> steps(n, length / n);
      if (n > 1 && grading > 1.)
        {
          const double q  = std::pow(grading, 1. / (n - 1));
          const double h0 = length * (q - 1.) / (std::pow(q, n) - 1.);
          for (unsigned int k = 0; k < n; ++k)
            steps[k] = h0 * std::pow(q, k);
        }
      return steps;
    }

    /// Kinematics and stresses at one point of the meridian.
    struct PointState
    {
      double R, r, z, dr, dz, l1, l2;
      NominalStress s;
    };
  } // namespace

  class MembraneModel::Impl : public NonlinearProblem<Vector<double>>
  {
  public:
    Impl(const Scene &scene, const FeDiscretization &disc, const NewtonSettings &newton);

    Scene                          scene;
    FeDiscretization               disc;
    NewtonSettings                 newton_settings;
    Triangulation<1>               triangulation;
    FESystem<1>                    fe;
    DoFHandler<1>                  dof_handler;
    QGauss<1>                      quadrature;
    AffineConstraints<double>      constraints; ///< homogeneous: Newton updates
    SparsityPattern                sparsity;
    SparseMatrix<double>           tangent; ///< with the constraints applied
    /// Linear solver of the Newton and arc-length systems.
    LinearSolver                   linear_solver = LinearSolver::banded_lu;
    int                            bandwidth     = 0; ///< max |i - j| of a tangent entry
    std::vector<double>            band_lu;           ///< LAPACK band LU of the tangent
    std::vector<int>               pivots;
    bool                           factorized = false;
    /// Copy for Trilinos KLU, created on first use: constructing a Trilinos
    /// matrix needs MPI, which only this solver option starts.
    std::unique_ptr<TrilinosWrappers::SparseMatrix> trilinos_tangent;
    /// Factor the assembled tangent (banded LU), or copy it for Trilinos;
    /// false if it is singular.
    bool factorize();
    /// u = tangent^-1 b with the factorization; false if that failed.
    bool apply_inverse(const Vector<double> &b, Vector<double> &u);
    Vector<double>                 system_rhs;
    Vector<double>                 solution;
    FEValues<1>                    fe_values; ///< at the assembly quadrature, reused
    /// Per-cell work arrays of assemble_cell, sized once.
    struct Scratch
    {
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  dl1, dl2, value, grad;
      std::vector<unsigned int>            component; ///< of each cell dof
    };
    mutable Scratch scratch;
    Quadrature<1>                  edge_point; ///< the left end of a cell
    mutable FEValues<1>            fe_edge;    ///< at edge_point (ring inner edges), reused

    unsigned int r_inner, z_inner, r_outer, z_outer; ///< boundary dofs

    LoadState                   load;
    std::vector<GentDielectric> laws; ///< one per ring, at the load's voltages
    /// Tension-field relaxation of each ring's law (Wrinkling/Model = relaxed).
    bool                                                relaxed = false;
    std::vector<TensionFieldRelaxation<GentDielectric>> relaxed_laws;

    /// Energy, stresses and (if @p with_tangent) second derivatives of the
    /// ring's law at (l1, l2), relaxed or plain; false outside the law's range.
    bool respond(unsigned int ring, double l1, double l2, double &energy, NominalStress &s,
                 StressTangent *t) const;

    /// Assemble the tangent at @p x (and, if @p rhs, minus the residual);
    /// remembers what solve_tangent needs for the water's free surface.
    void assemble_tangent(const Vector<double> &x, Vector<double> *rhs);
    /// Solve (assembled tangent) u = rhs, homogeneous constraints.
    void solve_tangent(const Vector<double> &rhs, Vector<double> &u);
    Vector<double> volume_gradient; ///< of the last assembly, water load on
    double         free_surface_coupling = 0.; ///< rho g / tube area of the last assembly

    WaterLoad   water;
    QGauss<1>   volume_quadrature; ///< 2p points: exact for the volume integrands
    FEValues<1> fe_volume;         ///< at the volume quadrature, reused

    /// rho g of the water times the stage's share of gravity (0 if off).
    double water_weight() const;
    /// Enclosed volume of @p x and, if @p gradient, its gradient (dof order).
    double volume(const Vector<double> &x, Vector<double> *gradient);
    /// Adds the water load of one element at free-surface height @p head (held
    /// fixed) to the local residual and, if @p cell_matrix, to the tangent;
    /// returns the element's share of pi int r^2 z (-z') dR.
    double add_water_cell(const Cell &cell, const Vector<double> &x, double head,
                          FullMatrix<double> *cell_matrix, Vector<double> &cell_rhs);
    /// E_w of @p x (J).
    double water_energy(const Vector<double> &x);

    void set_load(const LoadState &new_load);
    void apply_boundary_values(Vector<double> &x) const;

    /// Local residual (and tangent if @p cell_matrix) of one element; returns
    /// the element's share of 2 pi H int W R dR.
    double assemble_cell(const Cell &cell, FEValues<1> &fe_values, const Vector<double> &x,
                         FullMatrix<double> *cell_matrix, Vector<double> &cell_rhs) const;

    void residual(const Vector<double> &x, Vector<double> &r) override;
    void newton_update(const Vector<double> &x, const Vector<double> &r,
                       Vector<double> &dx) override;
  };

  MembraneModel::Impl::Impl(const Scene &scene_in, const FeDiscretization &disc_in,
                            const NewtonSettings &newton)
    : scene(scene_in)
    , disc(disc_in)
    , newton_settings(newton)
    , fe(FE_Q<1>(disc_in.degree), 2)
    , dof_handler(triangulation)
    , quadrature(disc_in.degree + 1)
    , fe_values(fe, quadrature,
                update_values | update_gradients | update_quadrature_points | update_JxW_values)
    , edge_point(Point<1>(0.))
    , fe_edge(fe, edge_point, update_values | update_gradients | update_quadrature_points)
    , volume_quadrature(2 * disc_in.degree)
    , fe_volume(fe, volume_quadrature,
                update_values | update_gradients | update_quadrature_points | update_JxW_values)
  {
    const auto          edges = scene.reference_ring_edges();
    std::vector<double> steps;
    for (unsigned int ring = 0; ring < scene.n_rings(); ++ring)
      {
        const auto s =
          graded_steps(edges[ring + 1] - edges[ring], disc.elements_per_ring, disc.grading);
        steps.insert(steps.end(), s.begin(), s.end());
      }
    GridGenerator::subdivided_hyper_rectangle(triangulation, {steps}, Point<1>(edges.front()),
                                              Point<1>(edges.back()));
    for (auto &cell : triangulation.active_cell_iterators())
      cell->set_material_id(scene.ring_of(cell->center()[0]));
    triangulation.refine_global(disc.refinements);

    dof_handler.distribute_dofs(fe);
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);

    const auto first = dof_handler.begin_active();
    auto       last  = first;
    for (auto cell = first; cell != dof_handler.end(); ++cell)
      last = cell;
    r_inner = first->vertex_dof_index(0, 0);
    z_inner = first->vertex_dof_index(0, 1);
    r_outer = last->vertex_dof_index(1, 0);
    z_outer = last->vertex_dof_index(1, 1);
    for (const unsigned int dof : {r_inner, r_outer, z_outer})
      constraints.add_line(dof);
    constraints.close();
    const unsigned int n_cell = fe.n_dofs_per_cell();
    scratch.dofs.resize(n_cell);
    for (auto *v : {&scratch.dl1, &scratch.dl2, &scratch.value, &scratch.grad})
      v->resize(n_cell);
    for (unsigned int i = 0; i < n_cell; ++i)
      scratch.component.push_back(fe.system_to_component_index(i).first);
    sparsity.copy_from(dsp);
    tangent.reinit(sparsity);
    for (unsigned int i = 0; i < sparsity.n_rows(); ++i)
      for (auto entry = sparsity.begin(i); entry != sparsity.end(i); ++entry)
        bandwidth = std::max<int>(bandwidth, std::abs(int(entry->column()) - int(i)));

    solution.reinit(dof_handler.n_dofs());
    system_rhs.reinit(dof_handler.n_dofs());
  }

  void MembraneModel::Impl::set_load(const LoadState &new_load)
  {
    load = new_load;
    if (load.voltages.size() != scene.n_rings())
      load.voltages.assign(scene.n_rings(), 0.);
    laws.clear();
    relaxed_laws.clear();
    for (const double v : load.voltages)
      {
        laws.emplace_back(scene.material, v);
        relaxed_laws.emplace_back(laws.back());
      }
  }

  bool MembraneModel::Impl::respond(const unsigned int ring, const double l1, const double l2,
                                    double &energy, NominalStress &s, StressTangent *t) const
  {
    if (!(l1 > 0.) || !(l2 > 0.) || !(laws[ring].gent_margin(l1, l2) > 0.))
      return false;
    if (relaxed)
      {
        const RelaxedEvaluation e = relaxed_laws[ring].evaluate(l1, l2);
        if (e.state == TensionState::failed)
          return false;
        energy = e.energy;
        s      = e.stress;
        if (t)
          *t = e.tangent;
        return true;
      }
    energy = laws[ring].energy(l1, l2);
    s      = laws[ring].stress(l1, l2);
    if (t)
      *t = laws[ring].tangent(l1, l2);
    return true;
  }

  void MembraneModel::Impl::apply_boundary_values(Vector<double> &x) const
  {
    x(r_inner) = load.stretch * scene.inner_reference_radius();
    x(r_outer) = load.stretch * scene.outer_reference_radius();
    x(z_outer) = 0.;
  }

  double MembraneModel::Impl::assemble_cell(const Cell &cell, FEValues<1> &fe_values,
                                            const Vector<double> &x,
                                            FullMatrix<double> *cell_matrix,
                                            Vector<double> &cell_rhs) const
  {
    const unsigned int n = fe.n_dofs_per_cell();
    // Scratch reused across calls: this runs for every cell of every assembly.
    auto &dofs  = scratch.dofs;
    auto &dl1   = scratch.dl1;
    auto &dl2   = scratch.dl2;
    auto &value = scratch.value;
    auto &grad  = scratch.grad;
    auto &comp  = scratch.component;
    cell->get_dof_indices(dofs);
    fe_values.reinit(cell);
    const unsigned int ring     = cell->material_id();
    const double       two_pi_H = 2. * M_PI * scene.material.thickness;

    cell_rhs = 0.;
    if (cell_matrix)
      *cell_matrix = 0.;
    double energy = 0.;
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const double R = fe_values.quadrature_point(q)[0];
        double       r = 0., dr = 0., dz = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            value[i] = fe_values.shape_value(i, q);
            grad[i]  = fe_values.shape_grad(i, q)[0];
            if (comp[i] == 0)
              {
                r += x(dofs[i]) * value[i];
                dr += x(dofs[i]) * grad[i];
              }
            else
              dz += x(dofs[i]) * grad[i];
          }
        const double l1 = std::sqrt(dr * dr + dz * dz);
        const double l2 = r / R;
        const double w  = two_pi_H * R * fe_values.JxW(q);
        double        W = 0.;
        NominalStress s{0., 0.};
        StressTangent t{0., 0., 0.};
        if (!respond(ring, l1, l2, W, s, cell_matrix ? &t : nullptr))
          {
            // Outside the material's range: a non-finite residual tells the
            // line search to step back.
            cell_rhs = std::numeric_limits<double>::quiet_NaN();
            return std::numeric_limits<double>::quiet_NaN();
          }
        energy += w * W;
        // First variations: dl1 = (r' dr' + z' dz') / l1, dl2 = dr / R.
        for (unsigned int i = 0; i < n; ++i)
          {
            dl1[i] = (comp[i] == 0 ? dr : dz) * grad[i] / l1;
            dl2[i] = (comp[i] == 0 ? value[i] / R : 0.);
            cell_rhs(i) += w * (s.s1 * dl1[i] + s.s2 * dl2[i]);
          }
        if (cell_matrix)
          {
            // Second variation of l1: (dr'Dr' + dz'Dz')/l1 - dl1 Dl1 / l1.
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                {
                  const double ddl1 =
                    ((comp[i] == comp[j]) ? grad[i] * grad[j] : 0.) / l1 - dl1[i] * dl1[j] / l1;
                  (*cell_matrix)(i, j) +=
                    w * (t.s11 * dl1[i] * dl1[j] + t.s12 * (dl1[i] * dl2[j] + dl2[i] * dl1[j]) +
                         t.s22 * dl2[i] * dl2[j] + s.s1 * ddl1);
                }
          }
      }
    return energy;
  }

  void MembraneModel::Impl::residual(const Vector<double> &x, Vector<double> &r)
  {
    const unsigned int                   n = fe.n_dofs_per_cell();
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    r = 0.;
    const double c    = water_weight();
    const double head = c > 0. ? (water.water_volume - volume(x, nullptr)) / water.tube_area : 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        assemble_cell(cell, fe_values, x, nullptr, cell_rhs);
        if (c > 0.)
          add_water_cell(cell, x, head, nullptr, cell_rhs);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          r(dofs[i]) += cell_rhs(i);
      }
    r(z_inner) -= load.force;
    constraints.set_zero(r);
  }

  void MembraneModel::Impl::assemble_tangent(const Vector<double> &x, Vector<double> *rhs)
  {
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    tangent    = 0.;
    system_rhs = 0.;
    const double c        = water_weight();
    free_surface_coupling = c > 0. ? c / water.tube_area : 0.;
    const double head =
      c > 0. ? (water.water_volume - volume(x, &volume_gradient)) / water.tube_area : 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        assemble_cell(cell, fe_values, x, &cell_matrix, cell_rhs);
        if (c > 0.)
          add_water_cell(cell, x, head, &cell_matrix, cell_rhs);
        cell_rhs *= -1.;
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, tangent, system_rhs);
      }
    system_rhs(z_inner) += load.force;
    if (rhs)
      *rhs = system_rhs;
    if (c > 0.)
      constraints.set_zero(volume_gradient);
    factorized = factorize();
  }

  // Band storage for dgbtrf: ab(kl + ku + i - j, j) = K(i, j) with kl = ku =
  // bandwidth and ldab = 2 kl + ku + 1 (the extra kl rows take the fill-in of
  // the row pivoting).
  bool MembraneModel::Impl::factorize()
  {
    if (linear_solver == LinearSolver::trilinos_klu)
      {
        if (!trilinos_tangent)
          {
            mpi::ensure_initialized();
            trilinos_tangent = std::make_unique<TrilinosWrappers::SparseMatrix>();
          }
        trilinos_tangent->reinit(tangent);
        return true;
      }
    const int n = tangent.m(), kl = bandwidth, ku = bandwidth, ldab = 2 * kl + ku + 1;
    band_lu.assign(std::size_t(ldab) * n, 0.);
    pivots.resize(n);
    for (int i = 0; i < n; ++i)
      for (auto entry = tangent.begin(i); entry != tangent.end(i); ++entry)
        {
          const int j = entry->column();
          band_lu[(kl + ku + i - j) + std::size_t(j) * ldab] = entry->value();
        }
    int info = 0;
    dgbtrf_(&n, &n, &kl, &ku, band_lu.data(), &ldab, pivots.data(), &info);
    return info == 0;
  }

  bool MembraneModel::Impl::apply_inverse(const Vector<double> &b, Vector<double> &u)
  {
    if (!factorized)
      return false;
    u = b;
    if (linear_solver == LinearSolver::trilinos_klu)
      {
        try
          {
            SolverControl                  control(1, 0.);
            TrilinosWrappers::SolverDirect direct(control);
            direct.solve(*trilinos_tangent, u, b);
          }
        catch (const std::exception &)
          {
            // KLU refuses a singular tangent.
            return false;
          }
        return true;
      }
    const int  n = tangent.m(), kl = bandwidth, ku = bandwidth, ldab = 2 * kl + ku + 1;
    const int  nrhs = 1;
    const char trans = 'N';
    int        info  = 0;
    dgbtrs_(&trans, &n, &kl, &ku, &nrhs, band_lu.data(), &ldab, pivots.data(), u.begin(), &n,
            &info);
    return info == 0;
  }

  void MembraneModel::Impl::solve_tangent(const Vector<double> &rhs, Vector<double> &u)
  {
    u.reinit(rhs.size());
    Vector<double> v(rhs.size());
    // The free surface couples every dof: the tangent is K + k g g^T with g
    // the volume gradient and k = rho g / tube area (Sherman-Morrison).
    if (!apply_inverse(rhs, u) ||
        (free_surface_coupling > 0. && !apply_inverse(volume_gradient, v)))
      {
        // A singular tangent: a non-finite update makes Newton and the
        // arc-length corrector report a failed step, which the driver cuts
        // back or reports.
        u = std::numeric_limits<double>::quiet_NaN();
        return;
      }
    if (free_surface_coupling > 0.)
      {
        const double k = free_surface_coupling;
        u.add(-k * (volume_gradient * u) / (1. + k * (volume_gradient * v)), v);
      }
    constraints.distribute(u);
  }

  void MembraneModel::Impl::newton_update(const Vector<double> &x, const Vector<double> &,
                                          Vector<double> &dx)
  {
    assemble_tangent(x, nullptr);
    solve_tangent(system_rhs, dx);
  }

  double MembraneModel::Impl::water_weight() const
  {
    if (!water.enabled)
      return 0.;
    const double share = load.stage == Stage::prestretch ? 0. :
                         load.stage == Stage::dead_load  ? load.load_factor :
                                                           1.;
    return share * water.density * water.gravity;
  }

  double MembraneModel::Impl::volume(const Vector<double> &x, Vector<double> *gradient)
  {
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    if (gradient)
      gradient->reinit(dof_handler.n_dofs());
    double v = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        fe_volume.reinit(cell);
        for (unsigned int q = 0; q < fe_volume.n_quadrature_points; ++q)
          {
            double r = 0., dz = 0.;
            for (unsigned int i = 0; i < n; ++i)
              if (fe.system_to_component_index(i).first == 0)
                r += x(dofs[i]) * fe_volume.shape_value(i, q);
              else
                dz += x(dofs[i]) * fe_volume.shape_grad(i, q)[0];
            const double w = M_PI * fe_volume.JxW(q);
            v -= w * r * r * dz;
            if (gradient)
              for (unsigned int i = 0; i < n; ++i)
                (*gradient)(dofs[i]) -=
                  w * (fe.system_to_component_index(i).first == 0 ?
                         2. * r * dz * fe_volume.shape_value(i, q) :
                         r * r * fe_volume.shape_grad(i, q)[0]);
          }
      }
    return v;
  }

  // With the head h held fixed, the water's potential is locally
  // e = rho g pi int phi dR, phi = (h + z) r^2 z', whose gradient is the
  // pressure load -rho g (h grad V + grad Q); the variation of h with V
  // adds the rank-one part of the tangent (newton_update, tangent_matrix).
  double MembraneModel::Impl::add_water_cell(const Cell &cell, const Vector<double> &x,
                                             const double head,
                                             FullMatrix<double> *cell_matrix,
                                             Vector<double>     &cell_rhs)
  {
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    cell->get_dof_indices(dofs);
    fe_volume.reinit(cell);
    const double              c = water_weight();
    std::vector<double>       value(n), grad(n);
    std::vector<unsigned int> comp(n);
    for (unsigned int i = 0; i < n; ++i)
      comp[i] = fe.system_to_component_index(i).first;
    double moment = 0.;
    for (unsigned int q = 0; q < fe_volume.n_quadrature_points; ++q)
      {
        double r = 0., z = 0., dz = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            value[i] = fe_volume.shape_value(i, q);
            grad[i]  = fe_volume.shape_grad(i, q)[0];
            if (comp[i] == 0)
              r += x(dofs[i]) * value[i];
            else
              {
                z += x(dofs[i]) * value[i];
                dz += x(dofs[i]) * grad[i];
              }
          }
        const double w = M_PI * fe_volume.JxW(q);
        const double d = head + z; // depth below the free surface
        moment -= w * r * r * z * dz;
        // phi_r = 2 d r z', phi_z = r^2 z', phi_z' = d r^2.
        for (unsigned int i = 0; i < n; ++i)
          cell_rhs(i) += c * w *
                         (comp[i] == 0 ? 2. * d * r * dz * value[i] :
                                         r * r * dz * value[i] + d * r * r * grad[i]);
        if (cell_matrix)
          // phi_rr = 2 d z', phi_rz = 2 r z', phi_rz' = 2 d r, phi_zz' = r^2.
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              {
                double h = 0.;
                if (comp[i] == 0 && comp[j] == 0)
                  h = 2. * d * dz * value[i] * value[j];
                else if (comp[i] == 1 && comp[j] == 1)
                  h = r * r * (value[i] * grad[j] + grad[i] * value[j]);
                else
                  {
                    const unsigned int a = comp[i] == 0 ? i : j; // the r dof
                    const unsigned int b = comp[i] == 0 ? j : i; // the z dof
                    h = 2. * r * dz * value[a] * value[b] + 2. * d * r * value[a] * grad[b];
                  }
                (*cell_matrix)(i, j) += c * w * h;
              }
      }
    return moment;
  }

  double MembraneModel::Impl::water_energy(const Vector<double> &x)
  {
    const double c = water_weight();
    if (!(c > 0.))
      return 0.;
    const double   v = volume(x, nullptr);
    Vector<double> scratch(fe.n_dofs_per_cell());
    double         moment = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      moment += add_water_cell(cell, x, 0., nullptr, scratch);
    const double dv = water.water_volume - v;
    return c * (dv * dv / (2. * water.tube_area) - moment);
  }

  MembraneModel::MembraneModel(const Scene &scene, const FeDiscretization &discretization,
                               const NewtonSettings &newton)
    : impl(std::make_unique<Impl>(scene, discretization, newton))
  {
    set_reference_state();
  }


  unsigned int MembraneModel::n_dofs() const { return impl->dof_handler.n_dofs(); }

  unsigned int MembraneModel::n_elements() const
  {
    return impl->triangulation.n_active_cells();
  }

  unsigned int MembraneModel::disk_z_dof() const { return impl->z_inner; }

  void MembraneModel::set_reference_state()
  {
    LoadState reference;
    reference.stretch = 1.;
    impl->set_load(reference);
    // r = R, z = 0: interpolate the identity on the support points.
    const auto support = dof_support();
    for (unsigned int i = 0; i < support.size(); ++i)
      impl->solution(i) = support[i].second == 0 ? support[i].first : 0.;
  }

  std::vector<std::pair<double, unsigned int>> MembraneModel::dof_support() const
  {
    std::vector<std::pair<double, unsigned int>> support(n_dofs());
    const auto &unit_points = impl->fe.get_unit_support_points();
    std::vector<types::global_dof_index> dofs(impl->fe.n_dofs_per_cell());
    for (const auto &cell : impl->dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        const double x0 = cell->vertex(0)[0];
        const double h  = cell->vertex(1)[0] - x0;
        for (unsigned int i = 0; i < dofs.size(); ++i)
          support[dofs[i]] = {x0 + h * unit_points[i][0],
                              impl->fe.system_to_component_index(i).first};
      }
    return support;
  }

  SolveReport MembraneModel::solve(const LoadState &load)
  {
    const LoadState      old_load     = impl->load;
    const Vector<double> old_solution = impl->solution;

    // Predictor: the homogeneous part of a change of pre-stretch is exact
    // (r scales with the stretch); otherwise start from the current state.
    if (load.stretch != old_load.stretch)
      {
        const auto support = dof_support();
        for (unsigned int i = 0; i < support.size(); ++i)
          if (support[i].second == 0)
            impl->solution(i) *= load.stretch / old_load.stretch;
      }
    impl->set_load(load);
    impl->apply_boundary_values(impl->solution);

    NewtonSettings settings = impl->newton_settings;
    settings.residual_scale =
      std::max(load.force, 2. * M_PI * impl->scene.material.thickness *
                             impl->scene.material.shear_modulus * impl->scene.disk_radius);
    settings.update_scale = impl->scene.disk_radius;
    LineSearchNewton<Vector<double>> newton(settings);
    SolveReport                      report = newton.solve(*impl, impl->solution);
    if (report.converged && impl->water_weight() > 0. && free_surface_height() < 0.)
      {
        // The water model assumes a full cone under a free surface in the tube.
        report.converged = false;
        report.message   = "the water (WaterLoad) no longer fills the cone: its free surface "
                           "would lie below the frame plane";
      }
    if (!report.converged)
      {
        impl->set_load(old_load);
        impl->solution = old_solution;
      }
    return report;
  }

  double MembraneModel::energy() const
  {
    FEValues<1> &fe_values = impl->fe_values;
    Vector<double> cell_rhs(impl->fe.n_dofs_per_cell());
    double         pi = 0.;
    for (const auto &cell : impl->dof_handler.active_cell_iterators())
      pi += impl->assemble_cell(cell, fe_values, impl->solution, nullptr, cell_rhs);
    return pi - impl->load.force * impl->solution(impl->z_inner) +
           impl->water_energy(impl->solution);
  }

  std::vector<double> MembraneModel::residual_vector() const
  {
    FEValues<1> &fe_values = impl->fe_values;
    const unsigned int                   n = impl->fe.n_dofs_per_cell();
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  r(n_dofs(), 0.);
    const bool                           water = impl->water_weight() > 0.;
    const double                         head  = free_surface_height();
    for (const auto &cell : impl->dof_handler.active_cell_iterators())
      {
        impl->assemble_cell(cell, fe_values, impl->solution, nullptr, cell_rhs);
        if (water)
          impl->add_water_cell(cell, impl->solution, head, nullptr, cell_rhs);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          r[dofs[i]] += cell_rhs(i);
      }
    r[impl->z_inner] -= impl->load.force;
    return r;
  }

  std::vector<std::vector<double>> MembraneModel::tangent_matrix() const
  {
    FEValues<1> &fe_values = impl->fe_values;
    const unsigned int                   n = impl->fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<std::vector<double>>     K(n_dofs(), std::vector<double>(n_dofs(), 0.));
    const double                         c = impl->water_weight();
    Vector<double>                       g; // volume gradient
    if (c > 0.)
      impl->volume(impl->solution, &g);
    const double head = free_surface_height();
    for (const auto &cell : impl->dof_handler.active_cell_iterators())
      {
        impl->assemble_cell(cell, fe_values, impl->solution, &cell_matrix, cell_rhs);
        if (c > 0.)
          impl->add_water_cell(cell, impl->solution, head, &cell_matrix, cell_rhs);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            K[dofs[i]][dofs[j]] += cell_matrix(i, j);
      }
    if (c > 0.) // the free surface: rank one, couples every dof
      for (unsigned int i = 0; i < n_dofs(); ++i)
        for (unsigned int j = 0; j < n_dofs(); ++j)
          K[i][j] += c / impl->water.tube_area * g(i) * g(j);
    return K;
  }

  double MembraneModel::enclosed_volume() const
  {
    return impl->volume(impl->solution, nullptr);
  }

  void MembraneModel::set_water_load(const WaterLoad &water) { impl->water = water; }

  const WaterLoad &MembraneModel::water_load() const { return impl->water; }

  double MembraneModel::free_surface_height() const
  {
    return (impl->water.water_volume - enclosed_volume()) / impl->water.tube_area;
  }

  std::vector<double> MembraneModel::solution() const
  {
    return {impl->solution.begin(), impl->solution.end()};
  }

  void MembraneModel::set_solution(const std::vector<double> &x)
  {
    std::copy(x.begin(), x.end(), impl->solution.begin());
  }

  // The state: stretch, force, mass, one voltage per ring, then the unknowns.
  std::vector<double> MembraneModel::state() const
  {
    const LoadState    &l = impl->load;
    std::vector<double> s{double(l.stage), l.load_factor, l.stretch, l.force, l.mass};
    s.insert(s.end(), l.voltages.begin(), l.voltages.end());
    s.insert(s.end(), impl->solution.begin(), impl->solution.end());
    return s;
  }

  void MembraneModel::set_state(const std::vector<double> &s)
  {
    const unsigned int n_rings = impl->scene.n_rings();
    if (s.size() != 5 + n_rings + n_dofs())
      throw std::invalid_argument("MembraneModel::set_state: state of the wrong size");
    LoadState l;
    l.stage       = static_cast<Stage>(static_cast<int>(s[0]));
    l.load_factor = s[1];
    l.stretch     = s[2];
    l.force       = s[3];
    l.mass        = s[4];
    l.voltages.assign(s.begin() + 5, s.begin() + 5 + n_rings);
    impl->set_load(l);
    std::copy(s.begin() + 5 + n_rings, s.end(), impl->solution.begin());
  }

  void MembraneModel::profile_at(const std::vector<double> &R, std::vector<double> &r,
                                 std::vector<double> &z) const
  {
    r.assign(R.size(), 0.);
    z.assign(R.size(), 0.);
    std::vector<types::global_dof_index> dofs(impl->fe.n_dofs_per_cell());
    // Cells are ordered by radius in 1D: walk them once for sorted input,
    // restart the walk for a radius behind the current cell.
    auto cell = impl->dof_handler.begin_active();
    for (unsigned int k = 0; k < R.size(); ++k)
      {
        if (R[k] < cell->vertex(0)[0])
          cell = impl->dof_handler.begin_active();
        while (R[k] > cell->vertex(1)[0] && std::next(cell) != impl->dof_handler.end())
          ++cell;
        const double x0 = cell->vertex(0)[0];
        const double xi = std::clamp((R[k] - x0) / (cell->vertex(1)[0] - x0), 0., 1.);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const double v = impl->fe.shape_value(i, Point<1>(xi)) * impl->solution(dofs[i]);
            (impl->fe.system_to_component_index(i).first == 0 ? r[k] : z[k]) += v;
          }
      }
  }

  // The voltage stage as r(x, t) = 0 over the model's unknowns, for
  // arc-length continuation. Boundary values stay fixed in that stage, so the
  // unknown vector is the whole dof vector with zero updates where constrained.
  class MembraneModel::Continuation : public ContinuationProblem
  {
  public:
    Continuation(Impl &impl, std::function<LoadState(double)> path)
      : impl(impl)
      , path(std::move(path))
    {}

    void residual(const Eigen::VectorXd &x, const double t, Eigen::VectorXd &r) override
    {
      impl.set_load(path(t));
      Vector<double> xv(x.data(), x.data() + x.size()), rv(x.size());
      impl.residual(xv, rv);
      r = Eigen::Map<const Eigen::VectorXd>(rv.begin(), rv.size());
    }

    // The residual depends on t through the ring voltages squared, and they
    // are linear in t on a segment of the path: a central difference is exact
    // there (up to round-off).
    void residual_t(const Eigen::VectorXd &x, const double t, Eigen::VectorXd &r_t) override
    {
      const double    h = 1e-4;
      Eigen::VectorXd plus, minus;
      residual(x, t + h, plus);
      residual(x, t - h, minus);
      r_t = (plus - minus) / (2. * h);
      impl.set_load(path(t));
    }

    void factorize(const Eigen::VectorXd &x, const double t) override
    {
      impl.set_load(path(t));
      const Vector<double> xv(x.data(), x.data() + x.size());
      impl.assemble_tangent(xv, nullptr);
    }

    void solve(const Eigen::VectorXd &rhs, Eigen::VectorXd &solution) override
    {
      Vector<double> b(rhs.data(), rhs.data() + rhs.size()), u;
      impl.constraints.set_zero(b);
      impl.solve_tangent(b, u);
      solution = Eigen::Map<const Eigen::VectorXd>(u.begin(), u.size());
    }

    // Unknowns measured in units of the disk radius, averaged over the dofs.
    double dot(const Eigen::VectorXd &a, const Eigen::VectorXd &b) const override
    {
      const double a0 = impl.scene.disk_radius;
      return a.dot(b) / (a0 * a0 * a.size());
    }

    double residual_scale() const override
    {
      return std::max(impl.load.force, 2. * M_PI * impl.scene.material.thickness *
                                         impl.scene.material.shear_modulus *
                                         impl.scene.disk_radius);
    }

    double update_scale() const override { return impl.scene.disk_radius; }

    Eigen::VectorXd current() const override
    {
      return Eigen::Map<const Eigen::VectorXd>(impl.solution.begin(), impl.solution.size());
    }

    void set_current(const Eigen::VectorXd &x, const double t) override
    {
      std::copy(x.data(), x.data() + x.size(), impl.solution.begin());
      impl.set_load(path(t));
    }

  private:
    Impl                            &impl;
    std::function<LoadState(double)> path;
  };

  ContinuationProblem *MembraneModel::continuation(const std::function<LoadState(double)> &path)
  {
    continuation_problem = std::make_unique<Continuation>(*impl, path);
    return continuation_problem.get();
  }

  // The tangent with loads held (water coupling included), restricted to the
  // free dofs. Without water the matrix is banded (1D mesh, cell-wise dof
  // numbering) and LAPACK's dsbevx gives just the smallest eigenvalue in
  // O(n kd^2); the water's free surface couples every dof, and then the dense
  // symmetric solver is used.
  double MembraneModel::min_tangent_eigenvalue() const
  {
    std::vector<unsigned int> free;
    std::vector<int>          index_of(n_dofs(), -1); // position among the free dofs
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (!impl->constraints.is_constrained(i))
        {
          index_of[i] = free.size();
          free.push_back(i);
        }
    const int n = free.size();
    if (impl->water_weight() > 0.)
      {
        const auto      K = tangent_matrix();
        Eigen::MatrixXd Kf(n, n);
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j)
            Kf(i, j) = 0.5 * (K[free[i]][free[j]] + K[free[j]][free[i]]);
        return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Kf, Eigen::EigenvaluesOnly)
          .eigenvalues()(0);
      }
    // With homogeneous constraints the assembled sparse tangent, restricted to
    // the free rows and columns, is the tangent of the free dofs.
    impl->assemble_tangent(impl->solution, nullptr);
    const SparseMatrix<double> &K  = impl->tangent;
    int                         kd = 0;
    for (int i = 0; i < n; ++i)
      for (auto entry = K.begin(free[i]); entry != K.end(free[i]); ++entry)
        if (index_of[entry->column()] >= 0 && entry->value() != 0.)
          kd = std::max(kd, std::abs(index_of[entry->column()] - i));
    // Upper band storage: ab(kd + i - j, j) = K(i, j), column-major, ldab = kd + 1.
    const int           ldab = kd + 1;
    std::vector<double> ab(ldab * n, 0.);
    for (int i = 0; i < n; ++i)
      for (auto entry = K.begin(free[i]); entry != K.end(free[i]); ++entry)
        {
          const int j = index_of[entry->column()];
          if (j >= i)
            ab[(kd + i - j) + j * ldab] += 0.5 * entry->value();
          if (j >= 0 && j <= i)
            ab[(kd + j - i) + i * ldab] += 0.5 * entry->value();
        }
    const char          jobz = 'N', range = 'I', uplo = 'U';
    const int           il = 1, iu = 1, ldq = 1, ldz = 1;
    const double        vl = 0., vu = 0., abstol = 0.;
    int                 found = 0, info = 0;
    double              q = 0., z = 0., w_min = 0.;
    std::vector<double> w(n), work(7 * n);
    std::vector<int>    iwork(5 * n), ifail(n);
    dsbevx_(&jobz, &range, &uplo, &n, &kd, ab.data(), &ldab, &q, &ldq, &vl, &vu, &il, &iu,
            &abstol, &found, w.data(), &z, &ldz, work.data(), iwork.data(), ifail.data(), &info);
    w_min = w[0];
    return info == 0 && found == 1 ? w_min : std::numeric_limits<double>::quiet_NaN();
  }

  void MembraneModel::set_relaxed(const bool relaxed) { impl->relaxed = relaxed; }

  void MembraneModel::set_linear_solver(const LinearSolver solver)
  {
    impl->linear_solver = solver;
  }

  bool MembraneModel::relaxed() const { return impl->relaxed; }

  void MembraneModel::predict(const std::vector<double> &older, const double factor)
  {
    const unsigned int offset = 5 + impl->scene.n_rings();
    if (older.size() != offset + n_dofs())
      return;
    for (unsigned int i = 0; i < n_dofs(); ++i)
      impl->solution(i) += factor * (impl->solution(i) - older[offset + i]);
  }

  namespace
  {
    /// Evaluate the FE solution at the points of @p fe_values (already reinit'ed).
    PointState evaluate(const FEValues<1> &fe_values, const unsigned int q,
                        const std::vector<double> &local, const FiniteElement<1> &fe,
                        const GentDielectric &law)
    {
      PointState p{};
      p.R = fe_values.quadrature_point(q)[0];
      for (unsigned int i = 0; i < local.size(); ++i)
        {
          const double v = fe_values.shape_value(i, q);
          const double g = fe_values.shape_grad(i, q)[0];
          if (fe.system_to_component_index(i).first == 0)
            {
              p.r += local[i] * v;
              p.dr += local[i] * g;
            }
          else
            {
              p.z += local[i] * v;
              p.dz += local[i] * g;
            }
        }
      p.l1 = std::sqrt(p.dr * p.dr + p.dz * p.dz);
      p.l2 = p.r / p.R;
      p.s  = law.stress(p.l1, p.l2);
      return p;
    }
  } // namespace

  StepSummary MembraneModel::summary() const
  {
    StepSummary s;
    s.voltages     = impl->load.voltages;
    s.mass         = impl->load.mass;
    s.displacement = std::abs(impl->solution(impl->z_inner) - impl->solution(impl->z_outer));
    s.s2_ring_inner.assign(impl->scene.n_rings(), std::numeric_limits<double>::quiet_NaN());
    s.s2_min = std::numeric_limits<double>::infinity();

    // Hoop stress at the quadrature points and at each ring's inner edge,
    // evaluated on that ring's side (the first element of the ring).
    FEValues<1>        &fe_quad = impl->fe_values;
    FEValues<1>        &fe_edge = impl->fe_edge;
    std::vector<double> local(impl->fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(local.size());
    // Where the plain hoop stress is negative the relaxed law is wrinkled:
    // record the zone, and whether the relaxed law is still admissible there
    // (elliptic, natural width found).
    const auto note_wrinkled = [&](const PointState &p, const unsigned int ring) {
      if (!impl->relaxed || !(p.s.s2 < 0.))
        return;
      const RelaxedEvaluation e = impl->relaxed_laws[ring].evaluate(p.l1, p.l2);
      s.wrinkled_zone_inner =
        std::isnan(s.wrinkled_zone_inner) ? p.R : std::min(s.wrinkled_zone_inner, p.R);
      s.wrinkled_zone_outer =
        std::isnan(s.wrinkled_zone_outer) ? p.R : std::max(s.wrinkled_zone_outer, p.R);
      if (s.validity_limit.empty() && (e.state == TensionState::failed || e.loses_ellipticity))
        {
          std::ostringstream m;
          m << "the relaxed (tension-field) law "
            << (e.state == TensionState::failed ?
                  "has no natural width below the Gent limit" :
                  "loses ellipticity, ds1/dlambda1 <= 0 (pull-in)")
            << " at r = " << impl->scene.prestretch * p.R * 1e3 << " mm (r/a = "
            << impl->scene.prestretch * p.R / impl->scene.disk_radius << ", lambda1 = " << p.l1
            << ", lambda2 = " << p.l2 << ", natural width " << e.natural_width << ")";
          s.validity_limit = m.str();
        }
    };
    int previous_ring = -1;
    for (const auto &cell : impl->dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          local[i] = impl->solution(dofs[i]);
        const unsigned int    ring = cell->material_id();
        const GentDielectric &law  = impl->laws[ring];
        fe_quad.reinit(cell);
        for (unsigned int q = 0; q < impl->quadrature.size(); ++q)
          {
            const PointState p = evaluate(fe_quad, q, local, impl->fe, law);
            if (p.s.s2 < s.s2_min)
              {
                s.s2_min        = p.s.s2;
                s.s2_min_radius = p.R;
              }
            note_wrinkled(p, ring);
          }
        if (int(ring) != previous_ring)
          {
            fe_edge.reinit(cell);
            const PointState p    = evaluate(fe_edge, 0, local, impl->fe, law);
            s.s2_ring_inner[ring] = p.s.s2;
            note_wrinkled(p, ring);
            if (p.s.s2 < s.s2_min)
              {
                s.s2_min        = p.s.s2;
                s.s2_min_radius = p.R;
              }
            previous_ring = ring;
          }
      }
    return s;
  }

  StepFields MembraneModel::fields() const
  {
    StepFields          f;
    const unsigned int  m = impl->disc.samples_per_element;
    std::vector<Point<1>> points;
    for (unsigned int k = 0; k <= m; ++k)
      points.emplace_back(double(k) / m);
    const Quadrature<1> samples(points);
    FEValues<1>         fe_values(impl->fe, samples,
                                  update_values | update_gradients | update_quadrature_points);
    std::vector<double> local(impl->fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(local.size());
    const double H = impl->scene.material.thickness;
    int previous_ring = -1;
    for (const auto &cell : impl->dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          local[i] = impl->solution(dofs[i]);
        const int             ring = cell->material_id();
        const GentDielectric &law  = impl->laws[ring];
        fe_values.reinit(cell);
        // The left end is written only where a ring starts, so that the jump
        // of lambda1 at a ring edge shows as two samples at one radius.
        for (unsigned int k = (ring != previous_ring ? 0 : 1); k <= m; ++k)
          {
            PointState p = evaluate(fe_values, k, local, impl->fe, law);
            if (impl->relaxed && p.s.s2 < 0.)
              {
                const RelaxedEvaluation e = impl->relaxed_laws[ring].evaluate(p.l1, p.l2);
                if (e.state == TensionState::wrinkled)
                  p.s = e.stress;
              }
            f.R.push_back(p.R);
            f.r.push_back(p.r);
            f.z.push_back(p.z);
            f.theta.push_back(std::atan2(-p.dz, p.dr));
            f.lambda1.push_back(p.l1);
            f.lambda2.push_back(p.l2);
            f.s1.push_back(p.s.s1);
            f.s2.push_back(p.s.s2);
            f.Phi.push_back(law.voltage());
            f.E.push_back(law.voltage() * p.l1 * p.l2 / H);
            f.ring.push_back(ring);
          }
        previous_ring = ring;
      }
    return f;
  }
  // Defined here, where Continuation is a complete type.
  MembraneModel::~MembraneModel() = default;
} // namespace cdea
