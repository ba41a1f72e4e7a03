#pragma once
// A membrane material law as an object (energy, stresses, tangent), in the
// principal stretches of an axisymmetric membrane: l1 along the meridian, l2
// around the hoop (l3 = 1 / (l1 l2), incompressible), with the voltage across
// the film as a further input. The FE kernel evaluates one law object at every
// quadrature point; laws are immutable, so one object serves every ring.
//
// A law may carry internal variables per material point (a viscous stretch,
// say). The FE model stores them, n_internal_variables() numbers per
// quadrature point, for two times: `old` (the last accepted time step, read
// only) and `current` (written by evaluate(): the update rule of the law for
// the step from old to current, and the stresses and the consistent tangent
// at the updated values). An elastic law has none and ignores the step.

#include <cdea/material/gent_dielectric.h>

#include <memory>

namespace cdea
{
  /// Where the tension-field relaxation finds a material point.
  enum class TensionState : int
  {
    taut     = 0,
    wrinkled = 1,
    failed   = 2 ///< no natural width below the law's limit
  };

  /// What a law is asked at one material point.
  struct LawInput
  {
    double l1      = 1.; ///< meridian stretch
    double l2      = 1.; ///< hoop stretch
    double voltage = 0.; ///< V across the film
  };

  /// How internal variables are integrated over a time step.
  enum class TimeScheme : int
  {
    backward_euler = 0,
    trapezoidal    = 1 ///< second order (Crank-Nicolson)
  };

  /// The time step of one evaluation and the internal variables of the point.
  struct InternalStep
  {
    const double *old     = nullptr; ///< at the start of the step (read)
    double       *current = nullptr; ///< at the end of the step (written)
    double        dt      = 0.;      ///< s; 0: the internal variables stay as they are
    TimeScheme    scheme  = TimeScheme::backward_euler;
  };

  /// What evaluate() should compute (bit flags).
  enum LawRequest : unsigned int
  {
    law_energy  = 1,
    law_stress  = 2,
    law_tangent = 4
  };

  /// The law's answer at one point. `tension`, `natural_width` and
  /// `loses_ellipticity` are only set by a relaxation.
  struct LawResponse
  {
    double        energy = 0.; ///< W per reference volume (J/m^3)
    NominalStress stress{0., 0.};
    StressTangent tangent{0., 0., 0.}; ///< consistent: d(stress)/d(stretches)
    TensionState  tension           = TensionState::taut;
    double        natural_width     = 0.;
    bool          loses_ellipticity = false;
  };

  /// The material constants a law depends on, for parameter derivatives.
  enum class LawParameter : int
  {
    shear_modulus = 0,
    jlim          = 1,
    permittivity  = 2,
    voltage       = 3
  };

  class MembraneLaw
  {
  public:
    virtual ~MembraneLaw() = default;

    /// Numbers stored per material point (0: an elastic law).
    virtual unsigned int n_internal_variables() const { return 0; }

    /// Internal variables of a point held long enough at (l1, l2) to be in
    /// equilibrium with them (for a viscous network: relaxed).
    virtual void relaxed_internal_variables(const LawInput &input, double *values) const
    {
      (void)input;
      (void)values;
    }

    /// Energy, stresses and tangent as @p request asks (LawRequest bits);
    /// false outside the law's range (then @p response is unspecified).
    virtual bool evaluate(const LawInput &input, const InternalStep &step, unsigned int request,
                          LawResponse &response) const = 0;

    /// d(energy)/dp and d(stress)/dp at fixed stretches (and fixed internal
    /// variables); false if the law does not depend on p this way or cannot tell.
    virtual bool parameter_derivative(const LawInput &input, const InternalStep &step,
                                      LawParameter parameter, double &d_energy,
                                      NominalStress &d_stress) const
    {
      (void)input;
      (void)step;
      (void)parameter;
      (void)d_energy;
      (void)d_stress;
      return false;
    }

    /// Largest hoop stretch inside the law's range at meridian stretch l1
    /// (a relaxation searches the natural width below it).
    virtual double max_hoop_stretch(double l1) const = 0;

    /// Energy dissipated per reference volume over @p step (old to current
    /// internal variables in dt), for energy budgets; 0 for an elastic law.
    virtual double dissipation(const InternalStep &step) const
    {
      (void)step;
      return 0.;
    }
  };

} // namespace cdea
