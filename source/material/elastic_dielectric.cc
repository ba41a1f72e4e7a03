#include <cdea/material/elastic_dielectric.h>

#include <cmath>

namespace cdea
{
  std::pair<double, double> membrane_invariants(const double l1, const double l2)
  {
    const double q = 1. / (l1 * l1 * l2 * l2); // l3^2
    return {l1 * l1 + l2 * l2 + q, 1. / (l1 * l1) + 1. / (l2 * l2) + 1. / q};
  }

  // With q = l3^2 = l1^-2 l2^-2 and p = l1^2 l2^2 = 1/q:
  //   I1_1 = 2 (l1 - q / l1),            I2_1 = 2 (l1 l2^2 - l1^-3),
  //   I1_11 = 2 + 6 q / l1^2,            I2_11 = 2 l2^2 + 6 l1^-4,
  //   I1_12 = 4 q / (l1 l2),             I2_12 = 4 l1 l2,
  // (and 1 <-> 2), so that s_i = W1 I1_i + W2 I2_i and
  //   s_ij = W1 I1_ij + W2 I2_ij + W11 I1_i I1_j + W12 (I1_i I2_j + I2_i I1_j) + W22 I2_i I2_j.
  StrainEnergy strain_energy_of_invariants(const double l1, const double l2,
                                           const InvariantDerivatives &d,
                                           const unsigned int request)
  {
    StrainEnergy e;
    e.energy = d.W;
    if (!(request & (law_stress | law_tangent)))
      return e;
    const double q   = 1. / (l1 * l1 * l2 * l2);
    const double a1  = 2. * (l1 - q / l1), a2 = 2. * (l2 - q / l2);         // I1_i
    const double b1  = 2. * (l1 * l2 * l2 - 1. / (l1 * l1 * l1));           // I2_1
    const double b2  = 2. * (l2 * l1 * l1 - 1. / (l2 * l2 * l2));           // I2_2
    e.stress         = {d.W1 * a1 + d.W2 * b1, d.W1 * a2 + d.W2 * b2};
    if (!(request & law_tangent))
      return e;
    const double a11 = 2. + 6. * q / (l1 * l1), a22 = 2. + 6. * q / (l2 * l2);
    const double a12 = 4. * q / (l1 * l2);
    const double b11 = 2. * l2 * l2 + 6. / (l1 * l1 * l1 * l1);
    const double b22 = 2. * l1 * l1 + 6. / (l2 * l2 * l2 * l2);
    const double b12 = 4. * l1 * l2;
    const auto   second = [&](const double aij, const double bij, const double ai,
                            const double aj, const double bi, const double bj) {
      return d.W1 * aij + d.W2 * bij + d.W11 * ai * aj + d.W12 * (ai * bj + bi * aj) +
             d.W22 * bi * bj;
    };
    e.tangent = {second(a11, b11, a1, a1, b1, b1), second(a12, b12, a1, a2, b1, b2),
                 second(a22, b22, a2, a2, b2, b2)};
    return e;
  }

  bool invariant_parameter_derivative(const double l1, const double l2,
                                      const InvariantDerivatives &d, double &d_energy,
                                      NominalStress &d_stress)
  {
    const StrainEnergy e = strain_energy_of_invariants(l1, l2, d, law_stress);
    d_energy             = e.energy;
    d_stress             = e.stress;
    return true;
  }

  // The voltage term -(e / 2) (l1 l2)^2 with e = eps Phi^2 / H^2 gives
  //   -e l1 l2^2 and -e l1^2 l2 to the stresses,
  //   -e l2^2, -2 e l1 l2, -e l1^2 to the tangent.
  bool ElasticDielectricLaw::evaluate(const LawInput &in, const InternalStep &,
                                      const unsigned int request, LawResponse &out) const
  {
    const double l1 = in.l1, l2 = in.l2;
    StrainEnergy w;
    if (!(l1 > 0.) || !(l2 > 0.) || !strain_energy(l1, l2, request, w))
      return false;
    const double e = c.permittivity * in.voltage * in.voltage / (c.thickness * c.thickness);
    if (request & law_energy)
      out.energy = w.energy - 0.5 * e * l1 * l1 * l2 * l2;
    if (request & (law_stress | law_tangent))
      out.stress = {w.stress.s1 - e * l1 * l2 * l2, w.stress.s2 - e * l1 * l1 * l2};
    if (request & law_tangent)
      out.tangent = {w.tangent.s11 - e * l2 * l2, w.tangent.s12 - 2. * e * l1 * l2,
                     w.tangent.s22 - e * l1 * l1};
    out.tension       = TensionState::taut;
    out.natural_width = l2;
    return true;
  }

  // dW/deps = -(Phi^2 / H^2) (l1 l2)^2 / 2, dW/dPhi = -eps Phi (l1 l2 / H)^2,
  // and their stresses as in evaluate().
  bool ElasticDielectricLaw::parameter_derivative(const LawInput &in, const InternalStep &,
                                                  const LawParameter parameter,
                                                  double &d_energy, NominalStress &d_stress) const
  {
    const double l1 = in.l1, l2 = in.l2, J = l1 * l2;
    if (!(l1 > 0.) || !(l2 > 0.) || !(range_margin(l1, l2) > 0.))
      return false;
    const double H2 = c.thickness * c.thickness;
    switch (parameter)
      {
        case LawParameter::permittivity:
          {
            const double e = in.voltage * in.voltage / H2;
            d_energy       = -0.5 * e * J * J;
            d_stress       = {-e * J * l2, -e * J * l1};
            return true;
          }
        case LawParameter::voltage:
          {
            const double k = -2. * c.permittivity * in.voltage / H2;
            d_energy       = 0.5 * k * J * J;
            d_stress       = {k * J * l2, k * J * l1};
            return true;
          }
        default:
          return strain_energy_derivative(l1, l2, parameter, d_energy, d_stress);
      }
  }
} // namespace cdea
