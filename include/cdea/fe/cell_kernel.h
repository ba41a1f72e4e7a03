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
// membrane energy and the dead load; water_term.h: the enclosed volume and the
// water load). A term with a global coupling (the water's head depends on the
// enclosed volume) finishes its part after the loop in finish().

#include <cdea/fe/discretization.h>
#include <cdea/solver/band_matrix.h>

#include <Eigen/Core>

#include <memory>
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
  /// order: the voltage of each ring, then shear modulus, Jlim, permittivity.
  struct ParameterLayout
  {
    unsigned int n_rings = 1;
    unsigned int size() const { return n_rings + 3; }
    unsigned int voltage(unsigned int ring) const { return ring; }
    unsigned int shear_modulus() const { return n_rings; }
    unsigned int jlim() const { return n_rings + 1; }
    unsigned int permittivity() const { return n_rings + 2; }
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
    const Discretization *mesh  = nullptr;
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
    /// state lies outside the term's range (the material's, say).
    virtual bool add_cell(const CellInput &cell, unsigned int flags, CellScratch &scratch,
                          CellContribution &contribution) = 0;
    /// After the loop over cells: add what couples the whole system.
    virtual void finish(unsigned int flags, AssembledSystem &system) const
    {
      (void)flags;
      (void)system;
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

    /// The one loop over cells: every term on every cell at @p x, assembled
    /// into @p system as @p flags ask (plus what the terms require). Returns
    /// false, with a NaN residual, if a term was outside its range.
    bool assemble(const Eigen::VectorXd &x, unsigned int flags, AssembledSystem &system);

    const ParameterLayout &parameters() const { return layout; }

  private:
    const Discretization                  &mesh;
    ParameterLayout                        layout;
    std::vector<std::unique_ptr<CellTerm>> terms;
    CellScratch                            scratch;
    CellContribution                       local;
    std::vector<double>                    local_x;
  };
} // namespace cdea
