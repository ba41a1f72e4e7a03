#include <cdea/base/units.h>
#include <cdea/base/format.h>
#include <cdea/base/parameter_declarations.h>
#include <cdea/base/text.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/viscosity.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <string>

namespace cdea
{
  namespace
  {
    /// N = 2 [[2, 1], [1, 2]]: M^-1 = eta N for the mobility M of the dashpot.
    Eigen::Matrix2d n_matrix()
    {
      Eigen::Matrix2d m;
      m << 4., 2., 2., 4.;
      return m;
    }

    double second_invariant(const Eigen::Vector2d &s)
    {
      return (s[0] * s[0] + s[1] * s[1] - s[0] * s[1]) / 3.;
    }

    /// k1 (I1v^beta1 - 3^beta1) and its derivative in e (d I1v/de_i =
    /// 2 xi_i^2 - 2 xi3^2).
    double stiffening(const ShearThinning &t, const Eigen::Vector2d &e, Eigen::Vector2d *d_e)
    {
      const double x1 = std::exp(2. * e[0]), x2 = std::exp(2. * e[1]),
                   x3 = std::exp(-2. * (e[0] + e[1]));
      const double i1 = x1 + x2 + x3;
      if (d_e)
        *d_e = t.k1 * t.beta1 * std::pow(i1, t.beta1 - 1.) *
               Eigen::Vector2d(2. * (x1 - x3), 2. * (x2 - x3));
      return t.k1 * (std::pow(i1, t.beta1) - std::pow(3., t.beta1));
    }
  } // namespace

  double ShearThinning::factor(const Eigen::Vector2d &e, const Eigen::Vector2d &sigma,
                               Eigen::Vector2d *d_e, Eigen::Vector2d *d_sigma) const
  {
    const double j2 = second_invariant(sigma);
    const double p  = k2 > 0. && j2 > 0. ? std::pow(k2 * j2, beta2) : 0.;
    const double D  = 1. + p;
    const double A  = 1. - r + stiffening(*this, e, d_e);
    if (d_e)
      *d_e /= D;
    if (d_sigma)
      {
        // d phi/dJ2 = -A beta2 (K2 J2)^beta2 / (J2 D^2), dJ2/ds = (2 s1 - s2, 2 s2 - s1) / 3.
        const double d_j2 = p > 0. ? -A * beta2 * p / (j2 * D * D) : 0.;
        *d_sigma = d_j2 * Eigen::Vector2d(2. * sigma[0] - sigma[1], 2. * sigma[1] - sigma[0]) / 3.;
      }
    return r + A / D;
  }

  double ShearThinning::factor_at_rate(const Eigen::Vector2d &e, const Eigen::Vector2d &q,
                                       const double eta0) const
  {
    const double A    = 1. - r + stiffening(*this, e, nullptr);
    const double j2_q = second_invariant(n_matrix() * q) * eta0 * eta0;
    if (!(k2 > 0.) || !(j2_q > 0.))
      return r + A;
    // h(phi) = phi - r - A / (1 + (K2 phi^2 J2(eta_0 N q))^beta2) grows with phi.
    double lo = r, hi = r + A;
    for (unsigned int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        const double h   = mid - r - A / (1. + std::pow(k2 * mid * mid * j2_q, beta2));
        (h > 0. ? hi : lo) = mid;
      }
    return 0.5 * (lo + hi);
  }

  std::vector<LawConstant> ShearThinning::own_constants()
  {
    // Open lower ends (r, the exponents above 0) kept a little above 0.
    return {{"Shear thinning eta_inf/eta_0", 1e-12, 1.},
            {"Shear thinning K1/eta_0", 0., 1e6},
            {"Shear thinning beta1", 1e-3, 10.},
            {"Shear thinning K2 (1/kPa^2)", 0., 1e6},
            {"Shear thinning beta2", 1e-3, 10.}};
  }

  double ShearThinning::factor_derivative(const unsigned int k, const Eigen::Vector2d &e,
                                          const Eigen::Vector2d &sigma) const
  {
    const double x1 = std::exp(2. * e[0]), x2 = std::exp(2. * e[1]),
                 x3 = std::exp(-2. * (e[0] + e[1]));
    const double i1 = x1 + x2 + x3, S = std::pow(i1, beta1) - std::pow(3., beta1);
    const double j2 = second_invariant(sigma);
    const double p  = k2 > 0. && j2 > 0. ? std::pow(k2 * j2, beta2) : 0.;
    const double D = 1. + p, A = 1. - r + k1 * S;
    switch (k)
      {
        case 0:
          return 1. - 1. / D;
        case 1:
          return S / D;
        case 2:
          return k1 * (std::pow(i1, beta1) * std::log(i1) - std::pow(3., beta1) * std::log(3.)) / D;
        case 3:
          {
            // dp/dK2 = beta2 p / K2; at K2 = 0 it is J2 (beta2 = 1), 0 (beta2
            // > 1) or infinite (beta2 < 1).
            double dp = 0.;
            if (k2 > 0.)
              dp = beta2 * p / k2;
            else if (j2 > 0. && beta2 <= 1.)
              dp = beta2 == 1. ? j2 : std::numeric_limits<double>::quiet_NaN();
            return -1e-6 * A * dp / (D * D);
          }
        case 4:
          return p > 0. ? -A * p * std::log(k2 * j2) / (D * D) : 0.;
        default:
          break;
      }
    return std::numeric_limits<double>::quiet_NaN();
  }

  BranchResidual branch_residual(const ShearThinning &thinning, const double eta0, const double c,
                                 const Eigen::Vector2d &e, const Eigen::Vector2d &e0,
                                 const Eigen::Vector2d &q0, const Eigen::Vector2d &W_e,
                                 const Eigen::Matrix2d &W_ee)
  {
    Eigen::Vector2d phi_e, phi_s;
    BranchResidual  out;
    out.eta                 = eta0 * thinning.factor(e, -W_e, &phi_e, &phi_s);
    const Eigen::Matrix2d N = n_matrix();
    const Eigen::Vector2d a = c * (e - e0) - q0;
    out.G                   = out.eta * (N * a) + W_e;
    out.frozen              = c * out.eta * N + W_ee;
    // d s/de = -W_ee (symmetric), so d eta/de = eta_0 (phi_e - W_ee phi_s).
    out.jacobian = out.frozen + (N * a) * (eta0 * (phi_e - W_ee * phi_s)).transpose();
    return out;
  }

  void ShearThinning::declare_parameters(ParameterDeclarations &prm)
  {
    prm.enter_subsection("Material");
    prm.add_text("Viscosity", "newtonian",
                 "The dashpots of network B (viscoelastic model): 'newtonian' (eta_k = "
                 "mu_k tau_k) or 'shear thinning', the viscosity of Kumar and Lopez-Pamies "
                 "2016, eta = eta_inf + (eta_0 - eta_inf + K1 (I1v^beta1 - 3^beta1)) / "
                 "(1 + (K2 J2)^beta2), with eta_0 = mu_k tau_k of each branch and the "
                 "Shear thinning entries, one set for every branch.");
    prm.add_number("Shear thinning eta_inf/eta_0", "1.4257e-5",
                   "eta_inf / eta_0 (0 < r <= 1; VHB 4910: 0.1 / 7014 kPa s).");
    prm.add_number("Shear thinning K1/eta_0", "0.5",
                   "K1 / eta_0, the strain stiffening (>= 0; VHB 4910: 3507 / 7014).");
    prm.add_number("Shear thinning beta1", "1.852", "Exponent beta1 of I1v (VHB 4910: 1.852).");
    prm.add_number("Shear thinning K2 (1/kPa^2)", "1e-6",
                   "K2 (>= 0), the inverse square of the stress where the thinning sets "
                   "in (VHB 4910: 1e-6).");
    prm.add_number("Shear thinning beta2", "0.26", "Exponent beta2 of K2 J2 (VHB 4910: 0.26).");
    prm.leave_subsection();
  }

  namespace
  {
    /// Entry @p name of subsection Material, checked to lie in [lo, hi]
    /// (lo excluded if @p open_low).
    double checked(const LawSettings &settings, const std::string &name, const double lo,
                   const double hi, const bool open_low)
    {
      const double v = settings.constant(name);
      if (!(open_low ? v > lo : v >= lo) || !(v <= hi))
        throw InputError("Material/" + name + " must be " + (open_low ? "above " : "at least ") +
                         format_number(lo) + " and at most " + format_number(hi) + ", got " +
                         format_number(v));
      return v;
    }
  } // namespace

  ShearThinning ShearThinning::parse(const LawSettings &settings)
  {
    const std::string choice = trim_blanks(settings.text("Viscosity", "newtonian"));
    ShearThinning     t;
    if (choice == "newtonian")
      return t;
    if (choice != "shear thinning")
      throw InputError("Material/Viscosity must be 'newtonian' or 'shear thinning', got '" +
                       choice + "'");
    // Bounds that keep eta between eta_inf > 0 and a finite value: r in
    // (0, 1] (thinning, not thickening, at high stress), the exponents
    // positive and small enough that I1v^beta1 stays finite.
    t.enabled = true;
    t.r       = checked(settings, "Shear thinning eta_inf/eta_0", 0., 1., true);
    t.k1      = checked(settings, "Shear thinning K1/eta_0", 0., 1e6, false);
    t.beta1   = checked(settings, "Shear thinning beta1", 0., 10., true);
    t.k2      = units::per_kPa2.in_si(
      checked(settings, "Shear thinning K2 (1/kPa^2)", 0., 1e6, false));
    t.beta2   = checked(settings, "Shear thinning beta2", 0., 10., true);
    return t;
  }
} // namespace cdea
