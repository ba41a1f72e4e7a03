#include <cdea/fe/cell_kernel.h>

#include <iterator>
#include <limits>

namespace cdea
{
  CellKernel::CellKernel(const Discretization &mesh_in, const unsigned int n_rings)
    : mesh(mesh_in)
  {
    layout.n_rings     = n_rings;
    const unsigned int n = mesh.dofs_per_cell();
    for (auto *v : {&scratch.value, &scratch.gradient, &scratch.dl1, &scratch.dl2, &local_x,
                    &local.residual, &local.volume_gradient})
      v->resize(n);
    local.tangent.resize(n * n);
    local.volume_hessian.resize(n * n);
    local.parameter_residual.resize(layout.size() * n);
    local.geometry_residual.resize(2 * n);

    // The ring edges are the ends of the rings' first and last cells.
    ring_edges.assign(n_rings + 1, 0.);
    for (const MeshCell &cell : mesh.cells)
      ring_edges[cell.ring + 1] = cell.x0 + cell.h;
    for (auto c = mesh.cells.rbegin(); c != mesh.cells.rend(); ++c)
      ring_edges[c->ring] = c->x0;
    for (const MeshCell &cell : mesh.cells)
      {
        const double length = ring_edges[cell.ring + 1] - ring_edges[cell.ring];
        fraction_x0.push_back((cell.x0 - ring_edges[cell.ring]) / length);
        fraction_h.push_back(cell.h / length);
      }
  }

  void CellKernel::set_law_constants(const unsigned int n)
  {
    layout.n_law_constants = n;
    local.parameter_residual.resize(layout.size() * mesh.dofs_per_cell());
  }

  CellMotion CellKernel::cell_motion(const unsigned int c, const unsigned int parameter) const
  {
    const MeshCell &cell = mesh.cells[c];
    if (parameter == layout.mesh_scale())
      return {cell.x0, cell.h};
    // The outer edge of the cell's ring (if interior) moves x0 by f0 and h
    // by fh per unit, the inner edge (if interior) by 1 - f0 and -fh.
    if (parameter > layout.mesh_scale())
      {
        const unsigned int edge = parameter - layout.mesh_scale();
        if (edge == cell.ring + 1 && edge < layout.n_rings)
          return {fraction_x0[c], fraction_h[c]};
        if (edge == cell.ring && edge > 0)
          return {1. - fraction_x0[c], -fraction_h[c]};
      }
    return {};
  }

  void CellKernel::replace_terms(const std::size_t first, const std::size_t count,
                                 std::vector<std::unique_ptr<CellTerm>> replacement)
  {
    if (first + count > terms.size())
      throw std::logic_error("CellKernel::replace_terms: no such terms");
    terms.erase(terms.begin() + first, terms.begin() + first + count);
    terms.insert(terms.begin() + first, std::make_move_iterator(replacement.begin()),
                 std::make_move_iterator(replacement.end()));
  }

  void CellKernel::set_load(const LoadState &load)
  {
    for (const auto &term : terms)
      term->set_load(load);
  }

  std::string CellKernel::reject_state(const AssembledSystem &system) const
  {
    for (const auto &term : terms)
      if (std::string why = term->reject_state(system); !why.empty())
        return why;
    return {};
  }

  void CellKernel::start(const unsigned int flags, AssembledSystem &system) const
  {
    const unsigned int N = mesh.n_dofs(), bw = mesh.bandwidth();
    system.flags             = flags;
    system.energy            = 0.;
    system.volume            = 0.;
    system.rank_one_coupling = 0.;
    if (flags & assemble_residual)
      system.residual.setZero(N);
    if (flags & assemble_tangent)
      {
        if (system.tangent.size() != N || system.tangent.bandwidth() != bw)
          system.tangent.reinit(N, bw);
        else
          system.tangent.set_zero();
      }
    if (flags & assemble_parameter_derivatives)
      {
        // Kept across calls: zeroed, not reallocated.
        system.parameter_residual.resize(layout.size());
        for (Eigen::VectorXd &column : system.parameter_residual)
          column.setZero(N);
      }
    if (flags & assemble_volume)
      {
        system.volume_gradient.setZero(N);
        if (flags & assemble_tangent)
          {
            if (system.volume_hessian.size() != N)
              system.volume_hessian.reinit(N, bw);
            else
              system.volume_hessian.set_zero();
          }
      }
  }

  void CellKernel::gather(const unsigned int c, const Eigen::VectorXd &x, const unsigned int flags)
  {
    const unsigned int  n    = mesh.dofs_per_cell();
    const unsigned int *dofs = mesh.dofs_of(c);
    for (unsigned int i = 0; i < n; ++i)
      local_x[i] = x[dofs[i]];
    local.energy = 0.;
    local.volume = 0.;
    std::fill(local.residual.begin(), local.residual.end(), 0.);
    if (flags & assemble_tangent)
      std::fill(local.tangent.begin(), local.tangent.end(), 0.);
    if (flags & assemble_parameter_derivatives)
      {
        std::fill(local.parameter_residual.begin(), local.parameter_residual.end(), 0.);
        std::fill(local.geometry_residual.begin(), local.geometry_residual.end(), 0.);
      }
    if (flags & assemble_volume)
      {
        std::fill(local.volume_gradient.begin(), local.volume_gradient.end(), 0.);
        if (flags & assemble_tangent)
          std::fill(local.volume_hessian.begin(), local.volume_hessian.end(), 0.);
      }
  }

  void CellKernel::add_shape_derivatives(const unsigned int c)
  {
    const unsigned int n = mesh.dofs_per_cell();
    for (unsigned int p = layout.first_shape_parameter(); p < layout.size(); ++p)
      {
        const CellMotion m = cell_motion(c, p);
        if (m.dx0 != 0. || m.dh != 0.)
          for (unsigned int i = 0; i < n; ++i)
            local.parameter_residual[p * n + i] +=
              m.dx0 * local.geometry_residual[i] + m.dh * local.geometry_residual[n + i];
      }
  }

  namespace
  {
    /// A(dofs[i], dofs[j]) += K[i n + j] for a local n x n matrix K
    /// (row-major), column by column of the band storage; N = n at compile
    /// time (with_dofs_per_cell()) or 0. One addition per entry, as before:
    /// the dofs of a cell differ, so no entry is added twice.
    template <unsigned int N>
    void add_local_matrix(const unsigned int n_run, const unsigned int *dofs, const double *K,
                          BandMatrix &A)
    {
      const unsigned int n = N == 0 ? n_run : N;
      for (unsigned int j = 0; j < n; ++j)
        {
          double *column = A.column(dofs[j]);
          for (unsigned int i = 0; i < n; ++i)
            column[dofs[i]] += K[i * n + j];
        }
    }
  } // namespace

  void CellKernel::scatter(const unsigned int *dofs, const unsigned int flags,
                           AssembledSystem &system) const
  {
    const unsigned int n = mesh.dofs_per_cell();
    system.energy += local.energy;
    system.volume += local.volume;
    if (flags & assemble_residual)
      for (unsigned int i = 0; i < n; ++i)
        system.residual[dofs[i]] += local.residual[i];
    if (flags & assemble_parameter_derivatives)
      for (unsigned int p = 0; p < layout.size(); ++p)
        for (unsigned int i = 0; i < n; ++i)
          system.parameter_residual[p][dofs[i]] += local.parameter_residual[p * n + i];
    if (flags & assemble_volume)
      for (unsigned int i = 0; i < n; ++i)
        system.volume_gradient[dofs[i]] += local.volume_gradient[i];
    if (!(flags & assemble_tangent))
      return;
    with_dofs_per_cell(n, [&](auto n_fixed) {
      add_local_matrix<n_fixed()>(n, dofs, local.tangent.data(), system.tangent);
      if (flags & assemble_volume)
        add_local_matrix<n_fixed()>(n, dofs, local.volume_hessian.data(), system.volume_hessian);
    });
  }

  bool CellKernel::assemble(const Eigen::VectorXd &x, unsigned int flags,
                            AssembledSystem &system)
  {
    for (const auto &term : terms)
      flags |= term->extra_flags(flags);
    start(flags, system);
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        gather(c, x, flags);
        const CellInput input{c, &mesh.cells[c], local_x.data(), &mesh, &layout};
        for (const auto &term : terms)
          if (!term->add_cell(input, flags, scratch, local))
            {
              // Outside a term's range: a non-finite residual tells the line
              // search or the corrector to step back.
              system.energy = std::numeric_limits<double>::quiet_NaN();
              if (flags & assemble_residual)
                system.residual.setConstant(std::numeric_limits<double>::quiet_NaN());
              return false;
            }
        if (flags & assemble_parameter_derivatives)
          add_shape_derivatives(c);
        scatter(mesh.dofs_of(c), flags, system);
      }
    for (const auto &term : terms)
      term->finish(flags, system);
    return true;
  }
} // namespace cdea
