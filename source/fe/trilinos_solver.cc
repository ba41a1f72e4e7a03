#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <cdea/base/mpi_session.h>
#include <cdea/fe/trilinos_solver.h>

#include <algorithm>

namespace cdea
{
  namespace
  {
    class TrilinosKlu final : public TangentSolver
    {
    public:
      bool factorize(const BandMatrix &K) override
      {
        const unsigned int n = K.size(), bw = K.bandwidth();
        if (!matrix || matrix->m() != n)
          {
            mpi::ensure_initialized(); // a Trilinos matrix needs MPI
            dealii::DynamicSparsityPattern pattern(n, n);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = (i > bw ? i - bw : 0); j <= std::min(n - 1, i + bw); ++j)
                pattern.add(i, j);
            matrix = std::make_unique<dealii::TrilinosWrappers::SparseMatrix>();
            matrix->reinit(pattern);
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = (i > bw ? i - bw : 0); j <= std::min(n - 1, i + bw); ++j)
            matrix->set(i, j, K.entry(i, j));
        matrix->compress(dealii::VectorOperation::insert);
        try
          {
            direct = std::make_unique<dealii::TrilinosWrappers::SolverDirect>(control);
            direct->initialize(*matrix);
          }
        catch (const std::exception &)
          {
            // KLU refuses a singular tangent.
            direct.reset();
            return false;
          }
        return true;
      }

      bool solve(Eigen::VectorXd &b) const override
      {
        if (!direct)
          return false;
        dealii::LinearAlgebra::distributed::Vector<double> rhs(b.size()), u(b.size());
        std::copy(b.data(), b.data() + b.size(), rhs.begin());
        try
          {
            direct->solve(u, rhs);
          }
        catch (const std::exception &)
          {
            return false;
          }
        std::copy(u.begin(), u.end(), b.data());
        return true;
      }

    private:
      dealii::SolverControl                                    control{1, 0.};
      std::unique_ptr<dealii::TrilinosWrappers::SparseMatrix>  matrix;
      std::unique_ptr<dealii::TrilinosWrappers::SolverDirect>  direct;
    };
  } // namespace

  std::unique_ptr<TangentSolver> make_tangent_solver(const LinearSolver choice)
  {
    if (choice == LinearSolver::trilinos_klu)
      return std::make_unique<TrilinosKlu>();
    return std::make_unique<BandedLU>();
  }
} // namespace cdea
