#pragma once
// The common part of the elastic laws of the law library (neo-Hooke,
// Mooney-Rivlin, Ogden, Gent-Gent; doc/materials.md): an incompressible
// ideal dielectric under voltage control,
//
//   W(l1, l2) = W_e(l1, l2) - (eps / 2) (Phi l1 l2 / H)^2,   l3 = 1 / (l1 l2),
//
// where a law gives only its strain energy W_e with its first and second
// derivatives in (l1, l2) and its derivatives in its constants; the voltage
// term, the request bits, the film's permittivity and the voltage as
// parameters are here. Laws of the invariants
//
//   I1 = l1^2 + l2^2 + l3^2,   I2 = l1^-2 + l2^-2 + l3^-2
//
// give W_e(I1, I2) and its derivatives, and strain_energy_of_invariants()
// applies the chain rule (doc/materials.md, "The invariants of a membrane").

#include <cdea/material/gent_dielectric.h>
#include <cdea/material/membrane_law.h>

namespace cdea
{
  /// The strain energy W_e at a point with its derivatives in (l1, l2).
  struct StrainEnergy
  {
    double        energy = 0.;          ///< W_e (J/m^3)
    NominalStress stress{0., 0.};       ///< dW_e/dl_i (Pa)
    StressTangent tangent{0., 0., 0.};  ///< d2W_e/dl_i dl_j (Pa)
  };

  /// W_e(I1, I2) and its derivatives W_a = dW_e/dI_a, W_ab = d2W_e/dI_a dI_b.
  struct InvariantDerivatives
  {
    double W   = 0.;
    double W1  = 0., W2 = 0.;
    double W11 = 0., W12 = 0., W22 = 0.;
  };

  /// I1 and I2 of the incompressible membrane at (l1, l2).
  std::pair<double, double> membrane_invariants(double l1, double l2);

  /// The derivatives in (l1, l2) of an energy of the invariants (@p request:
  /// LawRequest bits; the stress also for law_tangent, as evaluate() gives it).
  StrainEnergy strain_energy_of_invariants(double l1, double l2, const InvariantDerivatives &d,
                                           unsigned int request);

  /// The derivative in one of a law's constants of an energy of the
  /// invariants, @p d holding the derivatives in it of W, W1 and W2: the
  /// energy's into @p d_energy, the stresses' into @p d_stress (the chain
  /// rule of strain_energy_of_invariants()). True, for
  /// ElasticDielectricLaw::strain_energy_derivative() to return.
  bool invariant_parameter_derivative(double l1, double l2, const InvariantDerivatives &d,
                                      double &d_energy, NominalStress &d_stress);

  class ElasticDielectricLaw : public MembraneLaw
  {
  public:
    /// @p film: the film's Shear modulus, Jlim, permittivity and thickness (SI).
    explicit ElasticDielectricLaw(const MaterialConstants &film)
      : c(film)
    {}

    bool evaluate(const LawInput &input, const InternalStep &step, unsigned int request,
                  LawResponse &response) const final;

    /// The permittivity and the voltage here, every other constant by
    /// strain_energy_derivative().
    bool parameter_derivative(const LawInput &input, const InternalStep &step,
                              LawParameter parameter, double &d_energy,
                              NominalStress &d_stress) const final;

    bool serves_every_model() const final { return true; }

    const MaterialConstants &film() const { return c; }

  protected:
    /// W_e at (l1, l2) as @p request asks (LawRequest bits); false outside
    /// the law's range (the stretches are positive).
    virtual bool strain_energy(double l1, double l2, unsigned int request,
                               StrainEnergy &e) const = 0;

    /// dW_e/dp and d(dW_e/dl_i)/dp for the shear modulus, Jlim or one of the
    /// law's own constants; false if W_e does not depend on @p parameter.
    virtual bool strain_energy_derivative(double l1, double l2, LawParameter parameter,
                                          double &d_energy, NominalStress &d_stress) const = 0;

  private:
    MaterialConstants c;
  };
} // namespace cdea
