#include <cdea/material/gent_dielectric.h>

#include <cmath>

namespace cdea
{
  double GentDielectric::electric_field(const double l1, const double l2) const
  {
    return phi * l1 * l2 / c.thickness;
  }

  namespace
  {
    // The terms the stress and the tangent share: g = 1 - (I - 3)/Jlim,
    // q = l3^2 = l1^-2 l2^-2 and I_i = dI/dl_i = 2 (l_i - q / l_i).
    struct GentTerms
    {
      double g, q, I_1, I_2;
    };

    GentTerms gent_terms(const GentDielectric::Invariants &v, const double l1, const double l2)
    {
      return {v.g, v.q, 2. * (l1 - v.q / l1), 2. * (l2 - v.q / l2)};
    }

    // dW_gent/dl_i = (mu / 2) I_i / g; the electrostatic part gives
    //   -eps Phi^2/H^2 l1 l2^2 (e = eps Phi^2/H^2).
    NominalStress gent_stress(const GentTerms &t, const double mu, const double e,
                              const double l1, const double l2)
    {
      return {0.5 * mu * t.I_1 / t.g - e * l1 * l2 * l2, 0.5 * mu * t.I_2 / t.g - e * l1 * l1 * l2};
    }

    // d2W_gent/dl_i dl_j = (mu / 2) (I_ij / g + I_i I_j / (Jlim g^2)), with
    // I_11 = 2 + 6 q / l1^2, I_22 = 2 + 6 q / l2^2, I_12 = 4 q / (l1 l2).
    StressTangent gent_tangent(const GentTerms &t, const double mu, const double jlim,
                               const double e, const double l1, const double l2)
    {
      const double I_11 = 2. + 6. * t.q / (l1 * l1);
      const double I_22 = 2. + 6. * t.q / (l2 * l2);
      const double I_12 = 4. * t.q / (l1 * l2);
      const double k    = 0.5 * mu / t.g;
      const double kk   = 0.5 * mu / (jlim * t.g * t.g);
      return {k * I_11 + kk * t.I_1 * t.I_1 - e * l2 * l2,
              k * I_12 + kk * t.I_1 * t.I_2 - 2. * e * l1 * l2,
              k * I_22 + kk * t.I_2 * t.I_2 - e * l1 * l1};
    }
  } // namespace

  NominalStress GentDielectric::stress(const double l1, const double l2) const
  {
    return stress(l1, l2, invariants(l1, l2));
  }

  NominalStress GentDielectric::stress(const double l1, const double l2, const Invariants &v) const
  {
    return gent_stress(gent_terms(v, l1, l2), mu, eps_phi2_h2, l1, l2);
  }

  StressTangent GentDielectric::tangent(const double l1, const double l2) const
  {
    return gent_tangent(gent_terms(invariants(l1, l2), l1, l2), mu, jlim, eps_phi2_h2, l1, l2);
  }

  void GentDielectric::stress_and_tangent(const double l1, const double l2, NominalStress &s,
                                          StressTangent &t) const
  {
    stress_and_tangent(l1, l2, invariants(l1, l2), s, t);
  }

  // Both from one evaluation of the shared terms (the same expressions, so
  // the same numbers as stress() and tangent()).
  void GentDielectric::stress_and_tangent(const double l1, const double l2, const Invariants &v,
                                          NominalStress &s, StressTangent &t) const
  {
    const GentTerms terms = gent_terms(v, l1, l2);
    s                     = gent_stress(terms, mu, eps_phi2_h2, l1, l2);
    t                     = gent_tangent(terms, mu, jlim, eps_phi2_h2, l1, l2);
  }
} // namespace cdea
