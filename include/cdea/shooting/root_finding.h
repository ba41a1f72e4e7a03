#pragma once
// Local scalar root finding for the shooting unknown.
//
// The equilibrium branch is followed by continuation, so the root is sought
// near a guess only: secant steps of bounded size from the guess; as soon as
// two iterates bracket a sign change, the project's bracketed root finder
// (numerics/bracketed_root.h) takes over. If the secant phase stalls, a
// bracket is grown symmetrically around the guess (half-width doubling up to a
// limit) and then closed the same way. There is deliberately no global scan: a far root may belong to a
// non-physical branch.

#include <cdea/numerics/bracketed_root.h>

#include <functional>
#include <optional>
#include <string>

namespace cdea::shooting
{
  struct RootOptions
  {
    double       residual_tolerance = 1e-12; ///< converged when |f| <= this
    /// When a bracket has shrunk to rounding level, accept |f| up to this
    /// (the residual of an adaptive integration is only piecewise smooth).
    double       collapse_tolerance = 1e-8;
    unsigned int max_evaluations    = 60;
    unsigned int max_secant_steps   = 20;
    double       first_step         = 1e-4; ///< second secant point x0 + first_step
    double       max_step           = 0.25; ///< largest secant step
    double       max_half_width     = 0.5;  ///< largest bracket half-width around x0
    double       lower = -1e300, upper = 1e300; ///< open domain of x
  };

  struct RootResult
  {
    bool         converged   = false;
    RootStatus   status      = RootStatus::not_converged;
    double       x           = 0.;
    double       f           = 0.;
    unsigned int evaluations = 0;
    std::string  message; ///< why it failed (empty on success)
  };

  /// @p f returns nullopt where it cannot be evaluated (integration failed).
  RootResult find_root_local(const std::function<std::optional<double>(double)> &f,
                             double x0, const RootOptions &options);
} // namespace cdea::shooting
