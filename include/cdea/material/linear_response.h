#pragma once
// The small-signal response of a law with internal variables: stretches
// oscillating as dl exp(i omega t) about a state at rest (the evolving
// variables' rates zero, e.g. network B relaxed) move the evolving variables
// by i omega dy = rate_y dy + rate_l dl, so the stress answers with the
// complex tangent
//
//   C(omega) = instantaneous + stress_y (i omega I - rate_y)^-1 rate_l
//
// (InternalLinearization, membrane_law.h). For the two-network film this is
// W_ll - W_le (i omega M^-1 + W_ee)^-1 W_el: each viscous branch as its
// complex modulus, the backward Euler tangent with 1/dt = i omega; a law with
// several branches sums them through the same formula. omega -> infinity
// gives the instantaneous (glassy) tangent, omega = 0 the relaxed one.

#include <cdea/material/membrane_law.h>

#include <complex>

namespace cdea
{
  /// A symmetric 2 x 2 complex stress tangent (Pa).
  struct ComplexTangent
  {
    std::complex<double> s11, s12, s22;
  };

  /// C(omega) of @p linearization at angular frequency @p omega (rad/s).
  ComplexTangent frequency_tangent(const InternalLinearization &linearization, double omega);
} // namespace cdea
