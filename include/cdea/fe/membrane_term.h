#pragma once
// The membrane's share of the total potential, cell by cell:
//
//   Pi_m = 2 pi H int_A^B W(l1, l2; Phi_ring) R dR,   l1 = sqrt(r'^2 + z'^2), l2 = r / R,
//
// with W the material law (plain or relaxed, any MembraneLaw) at the voltage
// of the cell's ring, at the p + 1 Gauss points of each cell. First variations
// dl1 = (r' dr' + z' dz') / l1 and dl2 = dr / R give the residual
// w (s1 dl1 + s2 dl2); the tangent adds the second variation of l1,
// (dr' Dr' + dz' Dz' - dl1 Dl1) / l1, times s1 (doc/theory.md).
//
// Internal variables of the law live here, per quadrature point, for the last
// accepted time ("old") and the current iterate ("current").

#include <cdea/fe/cell_kernel.h>
#include <cdea/material/membrane_law.h>

#include <memory>
#include <utility>
#include <vector>

namespace cdea
{
  /// The law's parameters at a point of @p ring and their columns in @p
  /// layout: the voltage, the film's constants, then the law's own.
  inline std::vector<std::pair<LawParameter, unsigned int>>
  law_parameter_columns(const ParameterLayout &layout, const unsigned int ring)
  {
    std::vector<std::pair<LawParameter, unsigned int>> columns{
      {LawParameter::voltage, layout.voltage(ring)},
      {LawParameter::shear_modulus, layout.shear_modulus()},
      {LawParameter::jlim, layout.jlim()},
      {LawParameter::permittivity, layout.permittivity()}};
    for (unsigned int k = 0; k < layout.n_law_constants; ++k)
      columns.emplace_back(own_constant(k), layout.law_constant(k));
    return columns;
  }

  class MembraneTerm final : public CellTerm
  {
  public:
    MembraneTerm(const Scene &scene, const Discretization &mesh,
                 std::shared_ptr<const MembraneLaw> law);

    void               set_law(std::shared_ptr<const MembraneLaw> law);
    const MembraneLaw &law() const { return *law_; }

    /// The voltage of each ring (V).
    void set_voltages(const std::vector<double> &voltages);
    void set_load(const LoadState &load) override { set_voltages(load.voltages); }
    /// The time step of the internal variables (0: they stay as they are).
    void set_time_step(double dt, TimeScheme scheme);
    double     time_step() const { return dt; }
    TimeScheme time_scheme() const { return scheme; }

    bool add_cell(const CellInput &cell, unsigned int flags, CellScratch &scratch,
                  CellContribution &contribution) override;

    /// Internal variables: n_internal() per quadrature point, cell by cell.
    unsigned int        n_internal() const { return law_->n_internal_variables(); }
    std::vector<double> internal_old, internal_current;
    /// Make the current internal variables the accepted ones.
    void accept_internal() { internal_old = internal_current; }

    /// The law's input at a point of @p ring.
    LawInput law_input(const PointKinematics &p, unsigned int ring) const
    {
      return {p.l1, p.l2, voltages[ring]};
    }
    /// The internal-variable step of quadrature point @p q of cell @p c.
    InternalStep internal_step(unsigned int c, unsigned int q);

  private:
    /// Shape derivative of the residual at one point of weight @p w at
    /// R = x0 + h xi (CellContribution::geometry_residual).
    void add_geometry_derivative(const PointKinematics &p, double h, double w, double xi,
                                 const LawResponse &law, const CellScratch &scratch,
                                 CellContribution &out) const;

    /// add_cell() at every point for the @p request of the law; N = the
    /// dofs per cell at compile time or 0 (with_dofs_per_cell()).
    template <unsigned int N>
    bool add_cell_points(const CellInput &cell, unsigned int flags, unsigned int request,
                         CellScratch &scratch, CellContribution &contribution);

    /// The tangent of one point added into @p K (local, row-major).
    template <unsigned int N>
    void add_point_tangent(const LawResponse &law, const PointKinematics &p, double w,
                           const CellScratch &s, double *K) const;

    const Discretization              &mesh;
    const double                       two_pi_H;
    /// The shape gradients masked by component (r dofs, then z dofs), work
    /// storage of add_point_tangent().
    mutable std::vector<double> g_masked;
    /// Per point of energy_rule, cell by cell ([(c * points + q) * n + i]):
    /// the shape gradients d/dR and the shape values over R.
    std::vector<double> shape_gradient, shape_over_R;
    std::shared_ptr<const MembraneLaw> law_;
    std::vector<double>                voltages;
    double                             dt     = 0.;
    TimeScheme                         scheme = TimeScheme::backward_euler;
  };

  /// The dead load F on the disk: Pi_F = -F z(A), on the first cell.
  class DeadLoadTerm final : public CellTerm
  {
  public:
    void set_force(const double f) { force = f; }
    void set_load(const LoadState &load) override { set_force(load.force); }
    bool add_cell(const CellInput &cell, unsigned int flags, CellScratch &scratch,
                  CellContribution &contribution) override;

  private:
    double force = 0.;
  };

  /// The enclosed volume V = pi int_A^B r^2 (-z') dR (between the frame plane
  /// and the deformed membrane with the disk), with its gradient and Hessian,
  /// at the 2p Gauss points of each cell (exact for the FE solution), when
  /// assemble_volume asks for it: the postprocessors' volume and what the
  /// water load and the water's inertia couple through.
  class EnclosedVolumeTerm final : public CellTerm
  {
  public:
    bool add_cell(const CellInput &cell, unsigned int flags, CellScratch &scratch,
                  CellContribution &contribution) override;
  };
} // namespace cdea
