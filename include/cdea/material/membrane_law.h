#pragma once
// A membrane material law as an object (energy, stresses, tangent), in the
// principal stretches of an axisymmetric membrane: l1 along the meridian, l2
// around the hoop (l3 = 1 / (l1 l2), incompressible), with the voltage across
// the film as a further input. The FE kernel evaluates one law object at every
// quadrature point; laws are immutable, so one object serves every ring.
//
// A law may carry internal variables per material point (a viscous stretch,
// say), and declares them (internal_variables(): name, unit, description,
// the value a relaxed point has, whether the results hold them). The FE model
// stores them, n_internal_variables() numbers per quadrature point in the
// declared order, for two times: `old` (the last accepted time step, read
// only) and `current` (written by evaluate(): the update rule of the law for
// the step from old to current, and the stresses and the consistent tangent
// at the updated values). Everything outside the law (fields, results file,
// journal, Python) takes them from the declaration, never by index. An
// elastic law has none and ignores the step.

#include <cdea/material/gent_dielectric.h>

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  class ParameterDeclarations;

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

  /// The material constants a law depends on, for parameter derivatives:
  /// the film's (Material/Shear modulus, Jlim, Permittivity, SI units), the
  /// voltage, and after them the law's own constants (own_constant(k), in the
  /// units of their entries).
  enum class LawParameter : int
  {
    shear_modulus = 0,
    jlim          = 1,
    permittivity  = 2,
    voltage       = 3
  };

  /// The law's own constant k (MembraneLaw::own_constants()[k]) as a parameter.
  constexpr LawParameter own_constant(const unsigned int k)
  {
    return static_cast<LawParameter>(int(LawParameter::voltage) + 1 + int(k));
  }

  /// Whether @p p is one of a law's own constants, and which (-1: none).
  constexpr int own_constant_index(const LawParameter p)
  {
    return int(p) > int(LawParameter::voltage) ? int(p) - int(LawParameter::voltage) - 1 : -1;
  }

  /// One of a law's own constants (beyond the film's shear modulus, Jlim and
  /// permittivity): its entry of subsection Material and the interval, in the
  /// entry's units, that a fit keeps it in (the law's own checks, run when it
  /// is built, may ask more: Ogden's mu_p alpha_p > 0).
  struct LawConstant
  {
    std::string entry; ///< "Mooney-Rivlin C2 (kPa)"
    double      lower = -std::numeric_limits<double>::infinity();
    double      upper = std::numeric_limits<double>::infinity();
    /// The law's value of a constant that is no number entry of its own (an
    /// element of a list entry, such as a branch's modulus); NaN: the entry
    /// holds it.
    double value = std::numeric_limits<double>::quiet_NaN();
  };

  /// The limit of a law's range as messages name it ("the Gent limit") and
  /// the symbol of its margin ("g"); empty for a law without one.
  struct LawLimit
  {
    std::string name;
    std::string margin;
  };

  /// The value an internal variable has at a point held long enough at its
  /// stretches to be in equilibrium with them (relaxed), which is also where
  /// a run starts. A variable that relaxes to a stretch is interpolated
  /// between quadrature points as the log of its ratio to that stretch (so
  /// that it stays relaxed where it is); one that relaxes to zero linearly.
  enum class RelaxedValue
  {
    meridian_stretch, ///< l1
    hoop_stretch,     ///< l2
    zero
  };

  /// One internal variable of a law, as the law declares it.
  struct InternalVariable
  {
    std::string  name;        ///< its /steps dataset of a time run (if written)
    std::string  unit;        ///< of the stored value, which the file holds as it is
    std::string  description;
    RelaxedValue relaxed = RelaxedValue::zero;
    bool         written = true; ///< a /steps field (false: state only, e.g. a rate)
  };

  /// The law linearized at a point whose evolving internal variables y
  /// (n_evolving() of them, MembraneLaw::evolving_state()) are held:
  ///   ds = instantaneous dl + stress_y dy,   d(rate) = rate_y dy + rate_l dl,
  /// with the rate dy/dt of the law's evolution equation. Matrices are row
  /// major: stress_y 2 x n, rate_y n x n, rate_l n x 2.
  struct InternalLinearization
  {
    StressTangent       instantaneous{0., 0., 0.}; ///< d(stress)/d(stretches), y held
    unsigned int        n = 0;                     ///< evolving variables
    std::vector<double> stress_y, rate_y, rate_l;
  };

  class MembraneLaw
  {
  public:
    /// @p internal_variables: the law's declaration, in the order of the
    /// numbers it stores per point (none for an elastic law).
    explicit MembraneLaw(std::vector<InternalVariable> internal_variables = {})
      : internal(std::move(internal_variables))
    {}
    virtual ~MembraneLaw() = default;

    /// A registered law's entries of subsection Material (law_factory.h):
    /// none, unless the law declares its own constants.
    static void declare_parameters(ParameterDeclarations &prm) { (void)prm; }

    /// The internal variables per material point, in their stored order.
    const std::vector<InternalVariable> &internal_variables() const { return internal; }

    /// Numbers stored per material point (0: an elastic law).
    unsigned int n_internal_variables() const { return static_cast<unsigned int>(internal.size()); }

    /// Internal variables of a point held long enough at (l1, l2) to be in
    /// equilibrium with them (RelaxedValue of each).
    void relaxed_internal_variables(const LawInput &input, double *values) const
    {
      for (std::size_t i = 0; i < internal.size(); ++i)
        values[i] = internal[i].relaxed == RelaxedValue::meridian_stretch ? input.l1 :
                    internal[i].relaxed == RelaxedValue::hoop_stretch     ? input.l2 :
                                                                            0.;
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
    /// (a relaxation searches the natural width below it; infinity for a
    /// law without a limit).
    virtual double max_hoop_stretch(double l1) const = 0;

    /// Whether evaluate()'s tangent is the exact derivative of its stress
    /// (false: an approximation, with which Newton converges linearly).
    virtual bool tangent_is_exact() const { return true; }

    /// Whether the shooting model and the design studies (sweep, optimize,
    /// fit) can use the law: it is elastic, states its range below and gives
    /// parameter_derivative() for every constant it depends on. A law that
    /// gives only evaluate() and max_hoop_stretch() serves the FE model's
    /// runs, and the others refuse it by name.
    virtual bool serves_every_model() const { return false; }

    /// How far (l1, l2) lies inside the law's range: positive inside, <= 0
    /// outside (the Gent law: g = 1 - (I1 - 3) / Jlim); 1 without a limit.
    virtual double range_margin(double l1, double l2) const
    {
      (void)l1;
      (void)l2;
      return 1.;
    }

    /// The open interval of l1 where range_margin(l1, l2) > 0 at hoop
    /// stretch @p l2 ((0, infinity) without a limit; first >= second if none).
    virtual std::pair<double, double> meridian_stretch_range(double l2) const
    {
      (void)l2;
      return {0., std::numeric_limits<double>::infinity()};
    }

    /// The limit of the range as messages name it (empty: none).
    virtual LawLimit limit() const { return {}; }

    /// The law's own constants, in the order of own_constant(k): what
    /// parameter_derivative() differentiates beyond the film's constants.
    virtual std::vector<LawConstant> own_constants() const { return {}; }

    /// Whether the law depends on the film's constant @p p (the Gent limit
    /// Jlim only matters to Gent-type laws).
    virtual bool depends_on(LawParameter p) const
    {
      (void)p;
      return true;
    }

    /// Energy dissipated per reference volume over @p step (old to current
    /// internal variables in dt), for energy budgets; 0 for an elastic law.
    virtual double dissipation(const InternalStep &step) const
    {
      (void)step;
      return 0.;
    }

    // The evolving internal variables, for Runge-Kutta stages, error
    // estimates and the small-signal response. A law whose
    // internal variables follow a rate equation dy/dt = f(l, y) names y (say,
    // the log viscous stretches) and keeps the rate of the last evaluate()
    // among its stored numbers; evaluate() with InternalStep{old, current, dt,
    // backward_euler} then solves y = y_old + dt f(l, y) (any stage of a
    // diagonally implicit method is such a step from a shifted start).

    /// Evolving variables per point (0: none, as for an elastic law).
    virtual unsigned int n_evolving() const { return 0; }
    /// y and its rate dy/dt from the @p stored numbers of a point.
    virtual void evolving_state(const double *stored, double *y, double *rate) const
    {
      (void)stored;
      (void)y;
      (void)rate;
    }
    /// The stored numbers of a point with y replaced by @p y (the rest kept).
    virtual void set_evolving_state(const double *y, double *stored) const
    {
      (void)y;
      (void)stored;
    }
    /// Dissipation rate per reference volume (W/m^3) of a point's stored state.
    virtual double dissipation_rate(const double *stored) const
    {
      (void)stored;
      return 0.;
    }
    /// The linearization at @p input with the @p stored internal variables held
    /// (InternalLinearization); false outside the law's range. The default:
    /// the tangent with the internal variables held, no evolving variables.
    virtual bool linearize(const LawInput &input, const double *stored,
                           InternalLinearization &out) const;
    /// At the point linearize() sees (stretches and @p stored internal
    /// variables held): d(stress)/dp and the n_evolving() values d(rate)/dp
    /// of the evolution equation's rate (into @p d_rate), for sensitivities
    /// through time; false if the law cannot tell. The default serves a law
    /// without evolving variables (parameter_derivative() at dt = 0, no rate)
    /// and refuses one with them.
    virtual bool evolving_parameter_derivative(const LawInput &input, const double *stored,
                                               LawParameter parameter, NominalStress &d_stress,
                                               double *d_rate) const;

  private:
    std::vector<InternalVariable> internal;
  };

} // namespace cdea
