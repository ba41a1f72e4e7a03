#pragma once
// Shooting solves: find the unknown at the disk edge so that r(B) = stretch B
// (= b once pre-stretched), by local root finding from a continuation guess.
//
// Under a dead load the unknown is the meridian angle theta0 (l1(A) follows
// from the force); without one the film is flat and the unknown is l1(A).
// The residual is r(B) / (stretch B) - 1.

#include <cdea/shooting/meridian.h>

#include <string>

namespace cdea::shooting
{
  struct ShootingSolution
  {
    bool          converged = false;
    std::string   message;             ///< why it failed (empty on success)
    unsigned int  integrations    = 0; ///< shooting integrations of the root solve
    unsigned long rhs_evaluations = 0; ///< all of them, final sampled pass included
    double        residual        = 0.; ///< r(B) / (stretch B) - 1 at the solution
    Profile       profile;             ///< the equilibrium (samples on request)
  };

  /// F > 0: solve for theta0 from @p theta0_guess; @p lambda1_guess seeds the
  /// disk-edge l1 solve (<= 0: the stretch).
  ShootingSolution solve_cone(const MeridianIntegrator &integrator,
                              const MeridianLoad &load, double theta0_guess,
                              double lambda1_guess, bool with_samples);

  /// F = 0: solve the flat in-plane problem for l1(A) from @p lambda1_guess.
  ShootingSolution solve_flat(const MeridianIntegrator &integrator,
                              const MeridianLoad &load, double lambda1_guess,
                              bool with_samples);
} // namespace cdea::shooting
