// MembraneModel's voltage stage as a ContinuationProblem for arc-length
// continuation.

#include "membrane_model_impl.h"

#include <cdea/numerics/arc_length.h>

namespace cdea
{
  // The voltage stage as r(x, t) = 0 over the model's unknowns. Boundary
  // values stay fixed in that stage, so the unknown vector is the whole dof
  // vector with zero updates where constrained.
  class MembraneModel::Continuation : public ContinuationProblem
  {
  public:
    Continuation(Impl &impl, std::function<LoadState(double)> path)
      : impl(impl)
      , path(std::move(path))
    {}

    void residual(const Eigen::VectorXd &x, const double t, Eigen::VectorXd &r) override
    {
      at(x, t, assemble_residual);
      r = impl.system.residual;
    }

    // dr/dt = sum over rings of dr/dPhi_k dPhi_k/dt; the voltages are linear
    // in t on a segment of the path, so the central difference of the path is
    // exact there. The tangent is assembled with it for factorize().
    void residual_t(const Eigen::VectorXd &x, const double t, Eigen::VectorXd &r_t) override
    {
      at(x, t, assemble_residual | assemble_tangent | assemble_parameter_derivatives);
      const double     h = 1e-4;
      const LoadState  a = path(t + h), b = path(t - h);
      const auto      &layout = impl.kernel.parameters();
      r_t.setZero(x.size());
      for (unsigned int k = 0; k < impl.scene.n_rings(); ++k)
        r_t += (a.voltages[k] - b.voltages[k]) / (2. * h) *
               impl.system.parameter_residual[layout.voltage(k)];
      for (const unsigned int i : impl.mesh.constrained)
        r_t[i] = 0.;
    }

    void factorize(const Eigen::VectorXd &x, const double t) override
    {
      if (!(assembled_at_t == t && assembled_at_x.size() == x.size() && assembled_at_x == x &&
            (impl.system.flags & assemble_tangent)))
        at(x, t, assemble_residual | assemble_tangent);
      impl.factorize();
    }

    void solve(const Eigen::VectorXd &rhs, Eigen::VectorXd &solution) override
    {
      impl.solve_tangent(rhs, solution);
    }

    // Unknowns measured in units of the disk radius, averaged over the dofs.
    double dot(const Eigen::VectorXd &a, const Eigen::VectorXd &b) const override
    {
      const double a0 = impl.scene.disk_radius;
      return a.dot(b) / (a0 * a0 * a.size());
    }

    double residual_scale() const override { return impl.residual_scale(); }

    double update_scale() const override { return impl.scene.disk_radius; }

    Eigen::VectorXd current() const override { return impl.solution; }

    void set_current(const Eigen::VectorXd &x, const double t) override
    {
      impl.set_load(path(t));
      impl.solution = x;
      // The corrector's last factorization may be of this very state.
      impl.tangent_is_current = t == assembled_at_t && x.size() == assembled_at_x.size() &&
                                x == assembled_at_x && (impl.system.flags & assemble_tangent);
    }

  private:
    Impl                            &impl;
    std::function<LoadState(double)> path;
    Eigen::VectorXd                  assembled_at_x;
    double                           assembled_at_t = std::numeric_limits<double>::quiet_NaN();

    void at(const Eigen::VectorXd &x, const double t, const unsigned int flags)
    {
      impl.set_load(path(t));
      impl.assemble_constrained(x, flags);
      assembled_at_x = x;
      assembled_at_t = t;
    }
  };

  ContinuationProblem *MembraneModel::continuation(const std::function<LoadState(double)> &path)
  {
    continuation_problem = std::make_unique<Continuation>(*impl, path);
    return continuation_problem.get();
  }
} // namespace cdea
