#pragma once
// The FE space of the membrane as plain arrays: mesh cells along R with their
// ring, the dofs of each cell (renumbered by Cuthill-McKee for a narrow band),
// and the shape functions of the reference cell tabulated at the quadrature
// rules the terms use. deal.II builds it (mesh, FESystem of two FE_Q of degree
// p for r and z, dof numbering) in discretization.cc, the one FE source file
// that includes deal.II; everything that loops over cells reads these arrays.
//
// In 1D the shape functions of a cell [x0, x0 + h] are those of [0, 1]
// composed with R = x0 + h xi: values are the reference values, derivatives
// the reference derivatives over h, and the weights scale with h.

#include <cdea/model/scene.h>
#include <cdea/numerics/fixed_size.h>

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace cdea
{
  struct FeDiscretization
  {
    unsigned int degree              = 4;
    unsigned int elements_per_ring   = 4;
    double       grading             = 4.;
    unsigned int refinements         = 0;
    unsigned int samples_per_element = 16;
  };

  /// The shape functions of the reference cell at the points of one rule.
  struct ShapeTable
  {
    std::vector<double> points;     ///< xi in [0, 1]
    std::vector<double> weights;    ///< sum 1 (empty for sample points)
    std::vector<double> value;      ///< [q * dofs_per_cell + i]
    std::vector<double> derivative; ///< d/dxi, same layout
    unsigned int        size() const { return points.size(); }
  };

  struct MeshCell
  {
    double       x0   = 0.; ///< left end (m, reference radius R)
    double       h    = 0.; ///< length (m)
    unsigned int ring = 0;
  };

  class Discretization
  {
  public:
    Discretization(const Scene &scene, const FeDiscretization &settings);
    ~Discretization();

    unsigned int n_dofs() const { return n_dofs_; }
    unsigned int n_cells() const { return cells.size(); }
    unsigned int dofs_per_cell() const { return dofs_per_cell_; }
    unsigned int degree() const { return settings.degree; }
    /// Largest |i - j| over dofs coupled by a cell.
    unsigned int bandwidth() const { return bandwidth_; }

    /// Cells from the disk edge (R = A) to the frame (R = B).
    std::vector<MeshCell> cells;
    /// Global dof of local dof i of cell c: cell_dofs[c * dofs_per_cell + i].
    std::vector<unsigned int> cell_dofs;
    const unsigned int *dofs_of(unsigned int cell) const
    {
      return cell_dofs.data() + std::size_t(cell) * dofs_per_cell_;
    }
    /// Component of each local dof: 0 for r, 1 for z.
    std::vector<unsigned int> component;

    /// Gauss rules: p + 1 points (membrane energy), 2p points (exact for the
    /// volume and water integrands of the FE solution); the cell's left end
    /// (a ring's inner edge); samples_per_element + 1 equidistant points.
    ShapeTable energy_rule, volume_rule, left_end, samples;

    /// Reference radius and component of every dof's support point.
    std::vector<double>       support_radius;
    std::vector<unsigned int> support_component;

    /// Boundary dofs: r and z at the disk edge and at the frame.
    unsigned int r_inner = 0, z_inner = 0, r_outer = 0, z_outer = 0;
    /// Dofs with a prescribed value: r at both ends, z at the frame.
    std::vector<unsigned int> constrained;

    /// The shape functions of the reference cell at any xi (for profiles at
    /// arbitrary radii): @p value and @p derivative get dofs_per_cell entries.
    void shape_at(double xi, std::vector<double> &value, std::vector<double> &derivative) const;

    const FeDiscretization settings;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
    unsigned int          n_dofs_ = 0, dofs_per_cell_ = 0, bandwidth_ = 0;
  };

  /// The FE solution and its first derivatives at one point of a cell.
  struct PointKinematics
  {
    double R, r, z, dr, dz; ///< dr = dr/dR, dz = dz/dR
    double l1, l2;          ///< sqrt(dr^2 + dz^2), r / R
  };

  /// At point @p q of @p table on @p cell with local dof values @p x; N =
  /// the dofs per cell at compile time (with_dofs_per_cell()) or 0.
  template <unsigned int N = 0>
  inline PointKinematics kinematics(const Discretization &mesh, const ShapeTable &table,
                                    const unsigned int q, const MeshCell &cell,
                                    const double *x)
  {
    const unsigned int n = N == 0 ? mesh.dofs_per_cell() : N;
    const double      *v = &table.value[q * n], *d = &table.derivative[q * n];
    PointKinematics    p{cell.x0 + cell.h * table.points[q], 0., 0., 0., 0., 0., 0.};
    for (unsigned int i = 0; i < n; ++i)
      if (mesh.component[i] == 0)
        {
          p.r += x[i] * v[i];
          p.dr += x[i] * d[i];
        }
      else
        {
          p.z += x[i] * v[i];
          p.dz += x[i] * d[i];
        }
    p.dr /= cell.h;
    p.dz /= cell.h;
    p.l1 = std::sqrt(p.dr * p.dr + p.dz * p.dz);
    p.l2 = p.r / p.R;
    return p;
  }

  /// f(std::integral_constant<unsigned int, n>{}) for the n = 2 (p + 1) dofs
  /// per cell of the degrees p = 1..8 the input allows, else f with 0: cell
  /// loops written for a compile-time n (numerics/fixed_size.h).
  template <typename F>
  void with_dofs_per_cell(const unsigned int n, F &&f)
  {
    with_fixed_size<4, 6, 8, 10, 12, 14, 16, 18>(n, std::forward<F>(f));
  }

  /// Calls f(c, q, kinematics) at every point q of @p rule in every cell c,
  /// cell by cell, for the global dof values @p x (any vector with x[i]).
  template <typename Vector, typename F>
  void for_each_point(const Discretization &mesh, const ShapeTable &rule, const Vector &x, F &&f)
  {
    std::vector<double> local(mesh.dofs_per_cell());
    for (unsigned int c = 0; c < mesh.n_cells(); ++c)
      {
        const unsigned int *dofs = mesh.dofs_of(c);
        for (unsigned int i = 0; i < local.size(); ++i)
          local[i] = x[dofs[i]];
        for (unsigned int q = 0; q < rule.size(); ++q)
          f(c, q, kinematics(mesh, rule, q, mesh.cells[c], local.data()));
      }
  }
} // namespace cdea
