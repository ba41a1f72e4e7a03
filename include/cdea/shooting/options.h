#pragma once
// Numerical parameters of the shooting model.

namespace cdea::shooting
{
  struct ShootingOptions
  {
    /// Relative tolerance of the embedded Runge-Kutta error control.
    double tolerance = 1e-10;
    /// Absolute tolerance of the error control, in the integrator's units
    /// (lengths scaled by the inner reference radius A, angles in rad, stretches);
    /// a value <= 0 means "equal to tolerance".
    double absolute_tolerance = 0.;
    /// Convergence of the shooting: |r(B) - b| <= root_tolerance * b.
    double root_tolerance = 1e-12;
    /// Largest number of shooting integrations in one root solve.
    unsigned int max_root_iterations = 60;
    /// Field samples per ring, both ring edges included (at least 2).
    unsigned int samples_per_ring = 100;
    /// Largest number of accepted + rejected Runge-Kutta steps per ring.
    unsigned int max_steps_per_ring = 100000;
    /// Tension-field (relaxed) membrane law where the hoop stress would be
    /// negative, as Wrinkling/Model = relaxed in the FE model.
    bool relaxed = false;

    double effective_absolute_tolerance() const
    {
      return absolute_tolerance > 0. ? absolute_tolerance : tolerance;
    }
  };
} // namespace cdea::shooting
