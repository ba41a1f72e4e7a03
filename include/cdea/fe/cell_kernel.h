#pragma once
// The one cell kernel of the FE model, in the manner of deal.II step-44's
// assemble_system_one_cell: every term of the total potential Pi adds its
// share of one cell (energy, residual dPi/dx, tangent d2Pi/dx2, residual
// derivatives with respect to parameters, enclosed volume) into a
// CellContribution from work arrays that live across calls (CellScratch), and
// one loop over the cells (CellKernel::assemble) scatters the contributions
// into the global system for every caller: Newton, the arc-length corrector,
// the energy and finite-difference checks, the stability eigenvalue.
//
// A term is a CellTerm registered once with the kernel (membrane_term.h: the
// membrane energy, the dead load and the enclosed volume; the load terms of
// load_term.h, such as the water load of water_term.h). A term with a global
// coupling (the water's head depends on the enclosed volume) finishes its part
// after the loop in finish().

#include <cdea/fe/discretization.h>
#include <cdea/numerics/band_matrix.h>
#include <cdea/model/equilibrium_model.h>

#include <Eigen/Core>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace cdea
{
  /// What an assembly computes (bit flags).
  enum AssemblyFlag : unsigned int
  {
    assemble_energy                = 1,
    assemble_residual              = 2,
    assemble_tangent               = 4,
    assemble_parameter_derivatives = 8,
    assemble_volume                = 16
  };

  /// The parameters of dR/dp (assemble_parameter_derivatives), in this
  /// order: the voltage of each ring (V), shear modulus (Pa), Jlim,
  /// permittivity (F/m), the law's own constants (MembraneLaw::own_constants(),
  /// in their entries' units), the dead load F (N), then the shape
  /// parameters: a scale s of every reference radius (taken at s = 1) and
  /// the reference radius R_k (m) of each interior ring edge k = 1 .. n_rings - 1.
  struct ParameterLayout
  {
    unsigned int n_rings         = 1;
    unsigned int n_law_constants = 0; ///< the law's own constants
    unsigned int size() const { return 2 * n_rings + 4 + n_law_constants; }
    unsigned int voltage(unsigned int ring) const { return ring; }
    unsigned int shear_modulus() const { return n_rings; }
    unsigned int jlim() const { return n_rings + 1; }
    unsigned int permittivity() const { return n_rings + 2; }
    unsigned int law_constant(unsigned int k) const { return n_rings + 3 + k; }
    unsigned int dead_load() const { return n_rings + 3 + n_law_constants; }
    unsigned int mesh_scale() const { return n_rings + 4 + n_law_constants; }
    unsigned int ring_edge(unsigned int edge) const { return mesh_scale() + edge; }
    /// The first shape parameter: those from here on move the cells.
    unsigned int first_shape_parameter() const { return mesh_scale(); }
  };

  /// How a cell moves with a shape parameter: d x0/dp and d h/dp.
  struct CellMotion
  {
    double dx0 = 0.;
    double dh  = 0.;
  };

  /// Work arrays of one cell, sized once (step-44's ScratchData).
  struct CellScratch
  {
    std::vector<double> value, gradient; ///< shape values, d/dR at one point
    std::vector<double> dl1, dl2;        ///< first variations of the stretches
  };

  /// What one cell gives the global system (step-44's copy data); local dof order.
  struct CellContribution
  {
    double              energy = 0.;
    std::vector<double> residual;           ///< n
    std::vector<double> tangent;            ///< n x n, row-major
    std::vector<double> parameter_residual; ///< [p * n + i]
    /// Shape derivative of the residual: d/dx0 in [i], d/dh in [n + i], at
    /// fixed nodal values (the nodes move with the cell).
    std::vector<double> geometry_residual;
    double              volume = 0.;
    std::vector<double> volume_gradient; ///< n
    std::vector<double> volume_hessian;  ///< n x n
  };

  /// The assembled global system at one state.
  struct AssembledSystem
  {
    unsigned int    flags  = 0;
    double          energy = 0.;
    Eigen::VectorXd residual;
    BandMatrix      tangent;
    /// The tangent is tangent + rank_one_coupling g g^T with g = volume_gradient.
    double                       rank_one_coupling = 0.;
    std::vector<Eigen::VectorXd> parameter_residual; ///< dR/dp, one per parameter
    double                       volume = 0.;
    Eigen::VectorXd              volume_gradient;
    BandMatrix                   volume_hessian;
  };

  /// The cell, its unknowns and its place in the mesh.
  struct CellInput
  {
    unsigned int          index = 0; ///< in Discretization::cells
    const MeshCell       *cell  = nullptr;
    const double         *x     = nullptr; ///< local dof values
    const Discretization  *mesh   = nullptr;
    const ParameterLayout *layout = nullptr;
  };

  class CellTerm
  {
  public:
    virtual ~CellTerm() = default;
    /// Further flags this term needs for @p flags (the water needs the volume).
    virtual unsigned int extra_flags(unsigned int flags) const
    {
      (void)flags;
      return 0;
    }
    /// Add this term's share of one cell as @p flags ask; false where the
    /// state lies outside the term's range (the material's, say). With
    /// assemble_parameter_derivatives a term whose contribution depends on
    /// the cell's position and length also adds its shape derivative
    /// (CellContribution::geometry_residual); a term written in the nodal
    /// values alone (dead load, enclosed volume, water) has none.
    virtual bool add_cell(const CellInput &cell, unsigned int flags, CellScratch &scratch,
                          CellContribution &contribution) = 0;
    /// After the loop over cells: add what couples the whole system.
    virtual void finish(unsigned int flags, AssembledSystem &system) const
    {
      (void)flags;
      (void)system;
    }
    /// The load changed: take from it what the term needs (voltages, force,
    /// the stage's share of gravity).
    virtual void set_load(const LoadState &load) { (void)load; }
    /// After a converged solve, with the assembly of the converged state: why
    /// that state lies outside the term's model (empty if it does not).
    virtual std::string reject_state(const AssembledSystem &system) const
    {
      (void)system;
      return {};
    }
  };

  class CellKernel
  {
  public:
    CellKernel(const Discretization &mesh, unsigned int n_rings);

    /// Register a term; the kernel owns it and calls it on every cell.
    template <typename Term>
    Term &add_term(std::unique_ptr<Term> term)
    {
      Term &t = *term;
      terms.push_back(std::move(term));
      return t;
    }

    /// The number of registered terms.
    std::size_t n_terms() const { return terms.size(); }

    /// Replace the @p count terms from position @p first on by @p replacement,
    /// in its order (the load terms between the model's own).
    void replace_terms(std::size_t first, std::size_t count,
                       std::vector<std::unique_ptr<CellTerm>> replacement);

    /// The one loop over cells: every term on every cell at @p x, assembled
    /// into @p system as @p flags ask (plus what the terms require). Returns
    /// false, with a NaN residual, if a term was outside its range.
    bool assemble(const Eigen::VectorXd &x, unsigned int flags, AssembledSystem &system);

    /// The registered term of type @p Term (the first, if several).
    template <typename Term>
    Term &term() const
    {
      for (const auto &t : terms)
        if (auto *found = dynamic_cast<Term *>(t.get()))
          return *found;
      throw std::logic_error("CellKernel::term: no such term registered");
    }

    /// Pass the load to every term.
    void set_load(const LoadState &load);
    /// The first term's reason to reject the converged state in @p system
    /// (empty if every term accepts it).
    std::string reject_state(const AssembledSystem &system) const;

    const ParameterLayout &parameters() const { return layout; }
    /// The number of the law's own constants among the parameters.
    void set_law_constants(unsigned int n);

    /// How cell @p cell moves with parameter @p parameter of the layout
    /// (zero for the non-shape parameters). The cells of a ring keep their
    /// fractions of the ring: x0 = E_j + f0 (E_j+1 - E_j), h = fh (E_j+1 - E_j).
    CellMotion cell_motion(unsigned int cell, unsigned int parameter) const;

  private:
    const Discretization                  &mesh;
    ParameterLayout                        layout;
    std::vector<std::unique_ptr<CellTerm>> terms;
    CellScratch                            scratch;
    CellContribution                       local;
    std::vector<double>                    local_x;
    /// Reference radii of the ring edges (n_rings + 1) and, per cell, the
    /// fractions f0, fh of its ring.
    std::vector<double> ring_edges, fraction_x0, fraction_h;

    /// The steps of assemble(): zero what @p flags ask for in @p system; the
    /// unknowns of cell @p c into local_x and the local contribution zeroed;
    /// the shape-parameter derivatives of cell @p c by the chain rule; the
    /// local contribution added into @p system at @p dofs.
    void start(unsigned int flags, AssembledSystem &system) const;
    void gather(unsigned int c, const Eigen::VectorXd &x, unsigned int flags);
    void add_shape_derivatives(unsigned int c);
    void scatter(const unsigned int *dofs, unsigned int flags, AssembledSystem &system) const;
  };
} // namespace cdea
