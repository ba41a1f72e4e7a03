#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/material/gent_law.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/two_network_gent.h>

#include <Eigen/Dense>

#include <cmath>

namespace cdea
{
  namespace
  {
    using Vector2 = Eigen::Vector2d;
    using Matrix2 = Eigen::Matrix2d;

    /// Spring B at viscous log-strains e: its energy and the derivatives of
    /// W_B(l / exp(e)) with respect to l and e (formulas in the header's
    /// notation, t = dW_B/da and t_ij = d2W_B/da_i da_j at a = l / xi):
    ///   W_l  = t_i / xi_i,                 W_ll = t_ij / (xi_i xi_j),
    ///   W_e  = -a_i t_i  (= -sigma_i),     W_ee = delta_ij a_i t_i + a_i a_j t_ij,
    ///   W_le = -(delta_ij t_i + t_ij a_j) / xi_i.
    struct SpringB
    {
      double  energy = 0.;
      Vector2 W_l, W_e;
      Matrix2 W_ll, W_ee, W_le;

      bool evaluate(const GentDielectric &gent, const double l1, const double l2, const Vector2 &e,
                    const bool with_energy)
      {
        const Vector2 xi(std::exp(e[0]), std::exp(e[1]));
        const Vector2 al(l1 / xi[0], l2 / xi[1]);
        if (!(gent.gent_margin(al[0], al[1]) > 0.))
          return false;
        const NominalStress s = gent.stress(al[0], al[1]);
        const StressTangent k = gent.tangent(al[0], al[1]);
        const Vector2       t(s.s1, s.s2);
        Matrix2             tt;
        tt << k.s11, k.s12, k.s12, k.s22;
        energy = with_energy ? gent.energy(al[0], al[1]) : 0.;
        for (int i = 0; i < 2; ++i)
          {
            W_l[i] = t[i] / xi[i];
            W_e[i] = -al[i] * t[i];
            for (int j = 0; j < 2; ++j)
              {
                W_ll(i, j) = tt(i, j) / (xi[i] * xi[j]);
                W_ee(i, j) = (i == j ? al[i] * t[i] : 0.) + al[i] * al[j] * tt(i, j);
                W_le(i, j) = -((i == j ? t[i] : 0.) + tt(i, j) * al[j]) / xi[i];
              }
          }
        return true;
      }
    };

    /// H^-1 b for a symmetric 2 x 2 H (NaN if singular).
    Vector2 solve(const Matrix2 &H, const Vector2 &b)
    {
      const double det = H(0, 0) * H(1, 1) - H(0, 1) * H(1, 0);
      return Vector2(H(1, 1) * b[0] - H(0, 1) * b[1], H(0, 0) * b[1] - H(1, 0) * b[0]) / det;
    }

    /// M = [[2, -1], [-1, 2]] / (6 eta) and its inverse 2 eta [[2, 1], [1, 2]].
    Matrix2 mobility(const double eta)
    {
      Matrix2 m;
      m << 2., -1., -1., 2.;
      return m / (6. * eta);
    }

    Matrix2 mobility_inverse(const double eta)
    {
      Matrix2 m;
      m << 2., 1., 1., 2.;
      return 2. * eta * m;
    }
  } // namespace

  TwoNetworkGentLaw::TwoNetworkGentLaw(const MaterialConstants &network_a,
                                       const ViscousNetwork    &network_b)
    : MembraneLaw({{"xi1", "1", "viscous (dashpot) stretch xi1", RelaxedValue::meridian_stretch},
                   {"xi2", "1", "viscous (dashpot) stretch xi2", RelaxedValue::hoop_stretch},
                   {"q1", "1/s", "rate of ln xi1 at the end of the step", RelaxedValue::zero, false},
                   {"q2", "1/s", "rate of ln xi2 at the end of the step", RelaxedValue::zero, false}})
    , a(network_a)
    , b(network_b)
    , spring_b{network_b.shear_modulus, network_b.jlim, network_a.permittivity,
               network_a.thickness}
  {}

  namespace
  {
    /// The viscous log-strains e at the end of a step dt > 0 from e0 (and the
    /// rate q0 for the trapezoidal rule): G(e) = c M^-1 (e - e0) - f + W_e =
    /// 0, c = 1/dt (backward Euler) or 2/dt (trapezoidal, with f = M^-1 q0);
    /// H = c M^-1 + W_ee. Newton from @p e with step halving while outside
    /// spring B's Gent limit, until the update is below 1e-13 (then e and
    /// spring B there, @p w, are kept). False if it fails.
    bool update_viscous_strain(const GentDielectric &spring, const LawInput &in,
                               const InternalStep &step, const Matrix2 &M_inv,
                               const Vector2 &e0, const Vector2 &q0, Vector2 &e, SpringB &w)
    {
      const bool    trapezoidal = step.scheme == TimeScheme::trapezoidal;
      const double  c           = (trapezoidal ? 2. : 1.) / step.dt;
      const Vector2 f           = trapezoidal ? Vector2(M_inv * q0) : Vector2::Zero();
      for (unsigned int it = 0; it < 60; ++it)
        {
          if (!w.evaluate(spring, in.l1, in.l2, e, false))
            return false;
          const Vector2 G  = c * M_inv * (e - e0) - f + w.W_e;
          const Matrix2 H  = c * M_inv + w.W_ee;
          Vector2       de = -solve(H, G);
          if (!de.allFinite())
            return false;
          // e is within |de| of the root: keep it and its spring B.
          if (de.lpNorm<Eigen::Infinity>() <= 1e-13)
            return true;
          double lambda = 1.;
          for (unsigned int k = 0; k < 40; ++k, lambda *= 0.5)
            {
              const Vector2 trial = e + lambda * de;
              const double  a1 = in.l1 / std::exp(trial[0]), a2 = in.l2 / std::exp(trial[1]);
              if (spring.gent_margin(a1, a2) > 0.)
                break;
            }
          e += lambda * de;
        }
      return false;
    }

    /// Network B at the updated e: the internal variables xi = exp(e) and
    /// the rate at the end of the step, de/dt = M sigma = -M W_e, into
    /// step.current; its part of the incremental potential, of the stress
    /// and of the condensed tangent W_ll - W_le H^-1 W_el added to @p out.
    void add_network_b(const SpringB &w, const Vector2 &e, const Vector2 &e0, const Vector2 &q0,
                       const InternalStep &step, const Matrix2 &M, const Matrix2 &M_inv,
                       LawResponse &out)
    {
      const Vector2 q = -M * w.W_e;
      step.current[0] = std::exp(e[0]);
      step.current[1] = std::exp(e[1]);
      step.current[2] = q[0];
      step.current[3] = q[1];

      double  energy = w.energy;
      Matrix2 K      = w.W_ll;
      if (step.dt > 0.)
        {
          const Vector2 de = e - e0;
          if (step.scheme == TimeScheme::trapezoidal)
            energy += de.dot(M_inv * de) / step.dt - (M_inv * q0).dot(de);
          else
            energy += 0.5 * de.dot(M_inv * de) / step.dt;
          const Matrix2 H =
            (step.scheme == TimeScheme::trapezoidal ? 2. : 1.) / step.dt * M_inv + w.W_ee;
          K -= w.W_le * H.inverse() * w.W_le.transpose();
        }
      out.energy += energy;
      out.stress.s1 += w.W_l[0];
      out.stress.s2 += w.W_l[1];
      // The condensed tangent is symmetric up to round-off: take its mean.
      out.tangent.s11 += K(0, 0);
      out.tangent.s12 += 0.5 * (K(0, 1) + K(1, 0));
      out.tangent.s22 += K(1, 1);
    }
  } // namespace

  bool TwoNetworkGentLaw::evaluate(const LawInput &in, const InternalStep &step,
                                   const unsigned int request, LawResponse &out) const
  {
    const GentDielectric law_a(a, in.voltage);
    if (!(in.l1 > 0.) || !(in.l2 > 0.) || !(law_a.gent_margin(in.l1, in.l2) > 0.) ||
        !step.current)
      return false;
    out.energy        = request & law_energy ? law_a.energy(in.l1, in.l2) : 0.;
    out.stress        = law_a.stress(in.l1, in.l2);
    out.tangent       = law_a.tangent(in.l1, in.l2);
    out.tension       = TensionState::taut;
    out.natural_width = in.l2;

    if (std::isinf(step.dt))
      {
        // Fully relaxed: xi = l, spring B unstrained.
        relaxed_internal_variables(in, step.current);
        return true;
      }
    if (!step.old)
      return false;

    const GentDielectric spring(spring_b, 0.);
    const double         eta = b.shear_modulus * b.relaxation_time;
    const Vector2        e0(std::log(step.old[0]), std::log(step.old[1]));
    const Vector2        q0(step.old[2], step.old[3]);
    // Start from the last update at this point (the previous Newton iterate
    // of the same step, or e0 after accepting), if it is one.
    Vector2 e = e0;
    if (step.dt > 0. && step.current[0] > 0. && step.current[1] > 0. &&
        std::isfinite(step.current[0]) && std::isfinite(step.current[1]))
      e = Vector2(std::log(step.current[0]), std::log(step.current[1]));
    SpringB w;
    if (step.dt > 0.)
      {
        if (!update_viscous_strain(spring, in, step, mobility_inverse(eta), e0, q0, e, w))
          return false;
        if (request & law_energy)
          w.energy = spring.energy(in.l1 / std::exp(e[0]), in.l2 / std::exp(e[1]));
      }
    else if (!w.evaluate(spring, in.l1, in.l2, e, request & law_energy))
      return false;
    add_network_b(w, e, e0, q0, step, mobility(eta), mobility_inverse(eta), out);
    return true;
  }

  bool TwoNetworkGentLaw::parameter_derivative(const LawInput &in, const InternalStep &step,
                                               const LawParameter parameter, double &d_energy,
                                               NominalStress &d_stress) const
  {
    return GentDielectricLaw(a).parameter_derivative(in, step, parameter, d_energy, d_stress);
  }

  double TwoNetworkGentLaw::max_hoop_stretch(const double l1) const
  {
    return GentDielectricLaw(a).max_hoop_stretch(l1);
  }

  double TwoNetworkGentLaw::dissipation(const InternalStep &step) const
  {
    if (!(step.dt > 0.) || std::isinf(step.dt) || !step.old || !step.current)
      return 0.;
    const Vector2 de(std::log(step.current[0] / step.old[0]),
                     std::log(step.current[1] / step.old[1]));
    return de.dot(mobility_inverse(b.shear_modulus * b.relaxation_time) * de) / step.dt;
  }
  void TwoNetworkGentLaw::evolving_state(const double *stored, double *y, double *rate) const
  {
    y[0]    = std::log(stored[0]);
    y[1]    = std::log(stored[1]);
    rate[0] = stored[2];
    rate[1] = stored[3];
  }

  void TwoNetworkGentLaw::set_evolving_state(const double *y, double *stored) const
  {
    stored[0] = std::exp(y[0]);
    stored[1] = std::exp(y[1]);
  }

  double TwoNetworkGentLaw::dissipation_rate(const double *stored) const
  {
    const Vector2 q(stored[2], stored[3]);
    return q.dot(mobility_inverse(b.shear_modulus * b.relaxation_time) * q);
  }

  bool TwoNetworkGentLaw::linearize(const LawInput &in, const double *stored,
                                    InternalLinearization &out) const
  {
    const GentDielectric law_a(a, in.voltage);
    if (!(in.l1 > 0.) || !(in.l2 > 0.) || !(law_a.gent_margin(in.l1, in.l2) > 0.))
      return false;
    SpringB w;
    if (!w.evaluate(GentDielectric(spring_b, 0.), in.l1, in.l2,
                    Vector2(std::log(stored[0]), std::log(stored[1])), false))
      return false;
    const StressTangent ta = law_a.tangent(in.l1, in.l2);
    out.instantaneous      = {ta.s11 + w.W_ll(0, 0), ta.s12 + 0.5 * (w.W_ll(0, 1) + w.W_ll(1, 0)),
                              ta.s22 + w.W_ll(1, 1)};
    const Matrix2 M      = mobility(b.shear_modulus * b.relaxation_time);
    const Matrix2 rate_y = -M * w.W_ee, rate_l = -M * w.W_le.transpose();
    out.n                = 2;
    out.stress_y         = {w.W_le(0, 0), w.W_le(0, 1), w.W_le(1, 0), w.W_le(1, 1)};
    out.rate_y           = {rate_y(0, 0), rate_y(0, 1), rate_y(1, 0), rate_y(1, 1)};
    out.rate_l           = {rate_l(0, 0), rate_l(0, 1), rate_l(1, 0), rate_l(1, 1)};
    return true;
  }

  void TwoNetworkGentLaw::declare_parameters(ParameterDeclarations &prm)
  {
    prm.declare_number("Material", "Network B shear modulus (kPa)", "45",
                       "Shear modulus mu_B of network B's spring (viscoelastic model).");
    prm.declare_number("Material", "Network B Jlim", "270",
                       "Gent limit Jlim_B of network B's spring.");
    prm.declare_number("Material", "Relaxation time (s)", "2",
                       "tau = eta / mu_B of network B (eta: the dashpot's viscosity).");
  }

  std::shared_ptr<const MembraneLaw> TwoNetworkGentLaw::parse_parameters(const LawSettings &settings)
  {
    // Bounds the solver can meet: network B more than 1e4 times as stiff
    // as network A leaves no equilibrium under the dead load (measured at
    // 1e5), and relaxation times outside 1e-12..1e12 s are below the
    // smallest time step or beyond any run's duration.
    const double mu_a = settings.material.shear_modulus / 1e3; // kPa, as the file has it
    const double mu_b = settings.constant("Network B shear modulus (kPa)");
    const double jlim = settings.constant("Network B Jlim");
    const double tau  = settings.constant("Relaxation time (s)");
    if (!(mu_b >= 1e-6 * mu_a && mu_b <= 1e4 * mu_a))
      throw InputError("Material/Network B shear modulus (kPa) must be between 1e-6 and 1e4 "
                       "times Material/Shear modulus (kPa) (" + format_number(1e-6 * mu_a) +
                       " to " + format_number(1e4 * mu_a) + " kPa), got " + format_number(mu_b));
    if (!(jlim >= 1e-12 && jlim <= 1e12))
      throw InputError("Material/Network B Jlim must be between 1e-12 and 1e12, got " +
                       format_number(jlim));
    if (!(tau >= 1e-12 && tau <= 1e12))
      throw InputError("Material/Relaxation time (s) must be between 1e-12 and 1e12 s, got " +
                       format_number(tau));
    return std::make_shared<TwoNetworkGentLaw>(settings.material,
                                               ViscousNetwork{mu_b * 1e3, jlim, tau});
  }

  CDEA_REGISTER_MEMBRANE_LAW(TwoNetworkGentLaw, "viscoelastic",
                             "the 'elastic' law is network A (the long-time response), in "
                             "parallel with "
                             "network B, a Gent spring in series with a dashpot (two-network "
                             "model of Hong 2011 and Zhao, Koh, Suo 2011); needs Time/Enabled = "
                             "true.")
} // namespace cdea
