// The Ogden ideal dielectric with up to three terms (Ogden 1972;
// doc/materials.md), in the principal stretches (l3 = 1 / (l1 l2)):
//
//   W_e = sum_p (mu_p / alpha_p) (l1^alpha_p + l2^alpha_p + l3^alpha_p - 3),
//
// mu_1 = Material/Shear modulus, alpha_1 = Material/Ogden alpha 1, and the
// terms 2 and 3 of Material/Ogden mu 2 (kPa), Ogden alpha 2, Ogden mu 3
// (kPa), Ogden alpha 3 (mu = 0: no term). Each term satisfies Ogden's
// condition mu_p alpha_p > 0 (or has mu_p = 0); the small-strain shear
// modulus is sum_p mu_p alpha_p / 2. One term with alpha_1 = 2 is the
// neo-Hookean law; alpha 1 = 2, alpha 2 = -2 is Mooney-Rivlin with
// C2 = -mu_2 / 2. Registered as Material/Model = ogden.

#include <cdea/base/units.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/material/elastic_dielectric.h>
#include <cdea/material/law_factory.h>

#include <array>
#include <cmath>
#include <limits>

namespace cdea
{
  /// One term of the Ogden series.
  struct OgdenTerm
  {
    double mu    = 0.; ///< Pa
    double alpha = 2.;
  };

  class OgdenLaw final : public ElasticDielectricLaw
  {
  public:
    OgdenLaw(const MaterialConstants &film, const std::array<OgdenTerm, 3> &terms)
      : ElasticDielectricLaw(film)
      , terms(terms)
    {}

    static void declare_parameters(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Material");
      prm.add_number("Ogden alpha 1", "2",
                     "Exponent alpha_1 of the Ogden law's first term, whose modulus mu_1 is "
                     "Shear modulus; above 0.");
      for (const char *p : {"2", "3"})
        {
          prm.add_number(std::string("Ogden mu ") + p + " (kPa)", "0",
                         std::string("Modulus mu_") + p + " of the Ogden law's term " + p +
                           " (0: no such term); mu_" + p + " alpha_" + p + " >= 0.");
          prm.add_number(std::string("Ogden alpha ") + p, p == std::string("2") ? "-2" : "5",
                         std::string("Exponent alpha_") + p + " of the Ogden law's term " + p +
                           "; not 0.");
        }
      prm.leave_subsection();
    }

    static std::shared_ptr<const MembraneLaw> create(const LawSettings &settings)
    {
      std::array<OgdenTerm, 3> t;
      t[0] = {settings.material.shear_modulus, settings.constant("Ogden alpha 1")};
      if (!(t[0].alpha > 0. && t[0].alpha <= 100.))
        throw InputError("Material/Ogden alpha 1 must be above 0 and at most 100 (Ogden's "
                         "mu_1 alpha_1 > 0 with mu_1 = Shear modulus), got " +
                         format_number(t[0].alpha));
      for (unsigned int p = 1; p < 3; ++p)
        {
          const std::string k     = std::to_string(p + 1);
          const double      mu    = settings.constant("Ogden mu " + k + " (kPa)");
          const double      alpha = settings.constant("Ogden alpha " + k);
          if (!(alpha != 0. && std::abs(alpha) <= 100.))
            throw InputError("Material/Ogden alpha " + k +
                             " must not be 0 and at most 100 in size, got " +
                             format_number(alpha));
          if (!(std::abs(mu) <= 1e9) || mu * alpha < 0.)
            throw InputError("Material/Ogden mu " + k + " (kPa) must have the sign of Ogden alpha " +
                             k + " (Ogden's condition mu_p alpha_p >= 0) and be at most 1e9 in "
                             "size, got " + format_number(mu) + " with alpha " + format_number(alpha));
          t[p] = {units::kPa.in_si(mu), alpha};
        }
      return std::make_shared<OgdenLaw>(settings.material, t);
    }

    double max_hoop_stretch(double) const override
    {
      return std::numeric_limits<double>::infinity();
    }

    bool depends_on(const LawParameter p) const override { return p != LawParameter::jlim; }

    std::vector<LawConstant> own_constants() const override
    {
      return {{"Ogden alpha 1", 1e-3, 100.}, {"Ogden mu 2 (kPa)", -1e9, 1e9},
              {"Ogden alpha 2", -100., 100.}, {"Ogden mu 3 (kPa)", -1e9, 1e9},
              {"Ogden alpha 3", -100., 100.}};
    }

  private:
    std::array<OgdenTerm, 3> terms;

    // Per term, with P_i = l_i^alpha:
    //   W = (mu / alpha) (P1 + P2 + P3 - 3),  s_i = (mu / l_i) (P_i - P3),
    //   s_ii = (mu / l_i^2) ((alpha - 1) P_i + (alpha + 1) P3),  s12 = mu alpha P3 / (l1 l2).
    bool strain_energy(const double l1, const double l2, const unsigned int request,
                       StrainEnergy &e) const override
    {
      e                = StrainEnergy{};
      const double l3  = 1. / (l1 * l2);
      for (const OgdenTerm &t : terms)
        {
          if (t.mu == 0.)
            continue;
          const double a = t.alpha, m = t.mu;
          const double P1 = std::pow(l1, a), P2 = std::pow(l2, a), P3 = std::pow(l3, a);
          e.energy += m / a * (P1 + P2 + P3 - 3.);
          if (!(request & (law_stress | law_tangent)))
            continue;
          e.stress.s1 += m / l1 * (P1 - P3);
          e.stress.s2 += m / l2 * (P2 - P3);
          if (!(request & law_tangent))
            continue;
          e.tangent.s11 += m / (l1 * l1) * ((a - 1.) * P1 + (a + 1.) * P3);
          e.tangent.s12 += m * a * P3 / (l1 * l2);
          e.tangent.s22 += m / (l2 * l2) * ((a - 1.) * P2 + (a + 1.) * P3);
        }
      return std::isfinite(e.energy);
    }

    // d/dmu: the term over mu (per Pa; per kPa for mu_2, mu_3);
    // d/dalpha: dW = -W / alpha + (mu / alpha) sum P_i log l_i,
    //           ds_i = (mu / l_i) (P_i log l_i - P3 log l3).
    bool strain_energy_derivative(const double l1, const double l2, const LawParameter p,
                                  double &dW, NominalStress &ds) const override
    {
      const int k = p == LawParameter::shear_modulus ? -1 : own_constant_index(p);
      if (p != LawParameter::shear_modulus && (k < 0 || k > 4))
        return false;
      // Constant k: alpha_1 (0), mu_2 (1), alpha_2 (2), mu_3 (3), alpha_3 (4).
      const unsigned int term = k < 0 ? 0 : unsigned(k + 1) / 2;
      const bool         by_mu = k < 0 || k % 2 == 1;
      const OgdenTerm   &t     = terms[term];
      const double       a = t.alpha, l3 = 1. / (l1 * l2);
      const double P1 = std::pow(l1, a), P2 = std::pow(l2, a), P3 = std::pow(l3, a);
      if (by_mu)
        {
          const double unit = k < 0 ? 1. : 1e3;
          dW                = unit / a * (P1 + P2 + P3 - 3.);
          ds                = {unit / l1 * (P1 - P3), unit / l2 * (P2 - P3)};
          return true;
        }
      const double L1 = std::log(l1), L2 = std::log(l2), L3 = std::log(l3);
      dW = -t.mu / (a * a) * (P1 + P2 + P3 - 3.) + t.mu / a * (P1 * L1 + P2 * L2 + P3 * L3);
      ds = {t.mu / l1 * (P1 * L1 - P3 * L3), t.mu / l2 * (P2 * L2 - P3 * L3)};
      return true;
    }
  };

  CDEA_REGISTER_PLUGIN(MembraneLaws, OgdenLaw, "ogden", 0,
                       "the Ogden law of up to three terms sum (mu_p / alpha_p) (l1^alpha_p "
                       "+ l2^alpha_p + l3^alpha_p - 3), mu_1 = Shear modulus (Ogden 1972).")
} // namespace cdea
