#include <cdea/base/units.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/material/gent_law.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/two_network_gent.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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
      Vector2 xi; ///< exp(e) where it was evaluated
      Vector2 W_l, W_e;
      Matrix2 W_ll, W_ee, W_le;

      bool evaluate(const MembraneLaw &spring, const double l1, const double l2, const Vector2 &e,
                    const bool with_energy)
      {
        xi = Vector2(std::exp(e[0]), std::exp(e[1]));
        const Vector2 al(l1 / xi[0], l2 / xi[1]);
        LawResponse   r;
        if (!spring.evaluate({al[0], al[1], 0.}, InternalStep{},
                             law_stress | law_tangent | (with_energy ? law_energy : 0u), r))
          return false;
        const Vector2 t(r.stress.s1, r.stress.s2);
        Matrix2       tt;
        tt << r.tangent.s11, r.tangent.s12, r.tangent.s12, r.tangent.s22;
        energy = with_energy ? r.energy : 0.;
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

  namespace
  {
    /// xi1, xi2, q1, q2 of each of @p n branches (branch k >= 2: suffix _bk).
    std::vector<InternalVariable> branch_variables(const std::size_t n)
    {
      std::vector<InternalVariable> v;
      for (std::size_t k = 0; k < n; ++k)
        {
          const std::string of     = k == 0 ? "" : " of branch " + std::to_string(k + 1);
          const std::string suffix = k == 0 ? "" : "_b" + std::to_string(k + 1);
          v.push_back({"xi1" + suffix, "1", "viscous (dashpot) stretch xi1" + of,
                       RelaxedValue::meridian_stretch});
          v.push_back({"xi2" + suffix, "1", "viscous (dashpot) stretch xi2" + of,
                       RelaxedValue::hoop_stretch});
          v.push_back({"q1" + suffix, "1/s", "rate of ln xi1 at the end of the step" + of,
                       RelaxedValue::zero, false});
          v.push_back({"q2" + suffix, "1/s", "rate of ln xi2 at the end of the step" + of,
                       RelaxedValue::zero, false});
        }
      return v;
    }

    /// @p springs, or if there are none the Gent law of each branch's mu
    /// and Jlim (at the film's permittivity; used at 0 V).
    std::vector<SpringLaw> springs_of(const std::vector<ViscousNetwork> &branches,
                                      std::vector<SpringLaw> springs, const MaterialConstants &film)
    {
      if (branches.empty())
        throw std::invalid_argument("TwoNetworkGentLaw: network B needs at least one branch");
      if (springs.empty())
        for (const ViscousNetwork &n : branches)
          springs.push_back(std::make_shared<GentDielectricLaw>(
            MaterialConstants{n.shear_modulus, n.jlim, film.permittivity, film.thickness}));
      if (springs.size() != branches.size())
        throw std::invalid_argument("TwoNetworkGentLaw: one spring per branch");
      return springs;
    }
  } // namespace

  TwoNetworkGentLaw::TwoNetworkGentLaw(const MaterialConstants &network_a,
                                       const ViscousNetwork    &network_b)
    : TwoNetworkGentLaw(network_a, std::vector<ViscousNetwork>{network_b})
  {}

  TwoNetworkGentLaw::TwoNetworkGentLaw(const MaterialConstants    &network_a,
                                       std::vector<ViscousNetwork> branches,
                                       std::vector<SpringLaw>      springs,
                                       ShearThinning               thinning)
    : MembraneLaw(branch_variables(branches.size()))
    , a(network_a)
    , b(std::move(branches))
    , spring(springs_of(b, std::move(springs), network_a))
    , thinning(thinning)
  {}

  namespace
  {
    /// The viscous log-strains e at the end of a step dt > 0 from e0 (and the
    /// rate q0 for the trapezoidal rule): G(e) = c M^-1 (e - e0) - f + W_e =
    /// 0, c = 1/dt (backward Euler) or 2/dt (trapezoidal, with f = M^-1 q0);
    /// H = c M^-1 + W_ee, M of the viscosity @p eta (eta_0 = mu tau, or with
    /// @p thinning its value at e, and H the exact unsymmetric dG/de of
    /// branch_residual()). Newton from @p e with step halving while outside
    /// the spring's range, until the update is below 1e-13 (then e, eta and
    /// the spring there, @p w, with its energy if @p with_energy, are kept).
    /// False if it fails.
    bool update_viscous_strain(const MembraneLaw &spring, const ShearThinning &thinning,
                               const LawInput &in, const InternalStep &step, const Vector2 &e0,
                               const Vector2 &q0, const bool with_energy, Vector2 &e, SpringB &w,
                               double &eta)
    {
      const bool    trapezoidal = step.scheme == TimeScheme::trapezoidal;
      const double  c           = (trapezoidal ? 2. : 1.) / step.dt;
      const double  eta0        = eta;
      const Matrix2 M_inv       = mobility_inverse(eta0);
      const Vector2 f           = trapezoidal ? Vector2(M_inv * q0) : Vector2::Zero();
      if (!w.evaluate(spring, in.l1, in.l2, e, with_energy))
        return false;
      for (unsigned int it = 0; it < 60; ++it)
        {
          Vector2 G;
          Matrix2 H;
          if (thinning.enabled)
            {
              const BranchResidual r = branch_residual(
                thinning, eta0, c, e, e0, trapezoidal ? q0 : Vector2::Zero(), w.W_e, w.W_ee);
              G   = r.G;
              H   = r.jacobian;
              eta = r.eta;
            }
          else
            {
              G = c * M_inv * (e - e0) - f + w.W_e;
              H = c * M_inv + w.W_ee;
            }
          Vector2 de = -solve(H, G);
          if (!de.allFinite())
            return false;
          // e is within |de| of the root: keep it and its spring.
          if (de.lpNorm<Eigen::Infinity>() <= 1e-13)
            return true;
          // The spring is evaluated at the trial point, which is where the
          // next iteration starts if it lies inside the range.
          bool   inside = false;
          double lambda = 1.;
          for (unsigned int k = 0; k < 40 && !inside; ++k, lambda *= 0.5)
            {
              const Vector2 trial = e + lambda * de;
              inside              = w.evaluate(spring, in.l1, in.l2, trial, with_energy);
              if (inside)
                e = trial;
            }
          if (!inside)
            return false;
        }
      return false;
    }

    /// Network B at the updated e: the internal variables xi = exp(e) and
    /// the rate at the end of the step, de/dt = M sigma = -M W_e, into
    /// step.current; its part of the incremental potential, of the stress
    /// and of the condensed tangent W_ll - W_le H^-1 W_el added to @p out
    /// (the tangent only if @p with_tangent).
    void add_network_b(const SpringB &w, const Vector2 &e, const Vector2 &e0, const Vector2 &q0,
                       const InternalStep &step, const Matrix2 &M, const Matrix2 &M_inv,
                       const bool with_tangent, LawResponse &out)
    {
      const Vector2 q = -M * w.W_e;
      step.current[0] = w.xi[0]; // exp(e)
      step.current[1] = w.xi[1];
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
          if (with_tangent)
            {
              const Matrix2 H =
                (step.scheme == TimeScheme::trapezoidal ? 2. : 1.) / step.dt * M_inv + w.W_ee;
              K -= w.W_le * H.inverse() * w.W_le.transpose();
            }
        }
      out.energy += energy;
      out.stress.s1 += w.W_l[0];
      out.stress.s2 += w.W_l[1];
      if (!with_tangent)
        return;
      // The condensed tangent is symmetric up to round-off: take its mean.
      out.tangent.s11 += K(0, 0);
      out.tangent.s12 += 0.5 * (K(0, 1) + K(1, 0));
      out.tangent.s22 += K(1, 1);
    }
  } // namespace

  namespace
  {
    /// Branch @p n of network B over @p step (its four stored numbers at
    /// step.old and step.current), added to @p out; false if its update fails.
    bool add_branch(const ViscousNetwork &n, const MembraneLaw &spring,
                    const ShearThinning &thinning, const LawInput &in, const InternalStep &step,
                    const unsigned int request, LawResponse &out)
    {
      double        eta = n.shear_modulus * n.relaxation_time;
      const Vector2 e0(std::log(step.old[0]), std::log(step.old[1]));
      const Vector2 q0(step.old[2], step.old[3]);
      // Start from the last update at this point (the previous Newton iterate
      // of the same step, or e0 after accepting), if it is one.
      Vector2 e = e0;
      if (step.dt > 0. && step.current[0] > 0. && step.current[1] > 0. &&
          std::isfinite(step.current[0]) && std::isfinite(step.current[1]))
        e = Vector2(std::log(step.current[0]), std::log(step.current[1]));
      SpringB w;
      if (step.dt > 0.)
        {
          if (!update_viscous_strain(spring, thinning, in, step, e0, q0, request & law_energy, e,
                                     w, eta))
            return false;
        }
      else if (!w.evaluate(spring, in.l1, in.l2, e, request & law_energy))
        return false;
      else if (thinning.enabled)
        eta *= thinning.factor(e, -w.W_e);
      add_network_b(w, e, e0, q0, step, mobility(eta), mobility_inverse(eta),
                    request & law_tangent, out);
      return true;
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
    law_a.stress_and_tangent(in.l1, in.l2, out.stress, out.tangent);
    out.tension       = TensionState::taut;
    out.natural_width = in.l2;

    if (std::isinf(step.dt))
      {
        // Fully relaxed: xi = l, every spring unstrained.
        relaxed_internal_variables(in, step.current);
        return true;
      }
    if (!step.old)
      return false;
    for (std::size_t k = 0; k < b.size(); ++k)
      {
        const InternalStep branch{step.old + 4 * k, step.current + 4 * k, step.dt, step.scheme};
        if (!add_branch(b[k], *spring[k], thinning, in, branch, request, out))
          return false;
      }
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
    double sum = 0.;
    for (std::size_t k = 0; k < b.size(); ++k)
      {
        const double *o = step.old + 4 * k, *c = step.current + 4 * k;
        const Vector2 de(std::log(c[0] / o[0]), std::log(c[1] / o[1]));
        if (!thinning.enabled)
          sum += de.dot(mobility_inverse(b[k].shear_modulus * b[k].relaxation_time) * de) / step.dt;
        else if (step.scheme == TimeScheme::trapezoidal) // the mean of the end powers
          sum += 0.5 * step.dt * (branch_power(k, o) + branch_power(k, c));
        else // backward Euler: de / dt is the end rate
          sum += branch_power(k, c) * step.dt;
      }
    return sum;
  }

  void TwoNetworkGentLaw::evolving_state(const double *stored, double *y, double *rate) const
  {
    for (std::size_t k = 0; k < b.size(); ++k)
      {
        const double *s = stored + 4 * k;
        y[2 * k]        = std::log(s[0]);
        y[2 * k + 1]    = std::log(s[1]);
        rate[2 * k]     = s[2];
        rate[2 * k + 1] = s[3];
      }
  }

  void TwoNetworkGentLaw::set_evolving_state(const double *y, double *stored) const
  {
    for (std::size_t k = 0; k < b.size(); ++k)
      {
        stored[4 * k]     = std::exp(y[2 * k]);
        stored[4 * k + 1] = std::exp(y[2 * k + 1]);
      }
  }

  double TwoNetworkGentLaw::dissipation_rate(const double *stored) const
  {
    double sum = 0.;
    for (std::size_t k = 0; k < b.size(); ++k)
      sum += branch_power(k, stored + 4 * k);
    return sum;
  }

  // q^T M^-1 q with eta = eta_0 phi, phi the one consistent with the rate q
  // (ShearThinning::factor_at_rate()).
  double TwoNetworkGentLaw::branch_power(const std::size_t k, const double *stored) const
  {
    const Vector2 q(stored[2], stored[3]);
    double        eta = b[k].shear_modulus * b[k].relaxation_time;
    if (thinning.enabled)
      eta *= thinning.factor_at_rate(Vector2(std::log(stored[0]), std::log(stored[1])), q, eta);
    return q.dot(mobility_inverse(eta) * q);
  }

  // Branch k's evolving variables are y[2k], y[2k + 1]: its 2 x 2 blocks of
  // W_le and -M_k W_ee, -M_k W_el go to columns (rows) 2k, 2k + 1.
  bool TwoNetworkGentLaw::linearize(const LawInput &in, const double *stored,
                                    InternalLinearization &out) const
  {
    const GentDielectric law_a(a, in.voltage);
    if (!(in.l1 > 0.) || !(in.l2 > 0.) || !(law_a.gent_margin(in.l1, in.l2) > 0.))
      return false;
    const unsigned int n = n_evolving();
    out.n                = n;
    out.stress_y.assign(2 * n, 0.);
    out.rate_y.assign(n * n, 0.);
    out.rate_l.assign(2 * n, 0.);
    StressTangent t = law_a.tangent(in.l1, in.l2);
    for (std::size_t k = 0; k < b.size(); ++k)
      {
        SpringB w;
        if (!w.evaluate(*spring[k], in.l1, in.l2,
                        Vector2(std::log(stored[4 * k]), std::log(stored[4 * k + 1])), false))
          return false;
        t.s11 += w.W_ll(0, 0);
        t.s12 += 0.5 * (w.W_ll(0, 1) + w.W_ll(1, 0));
        t.s22 += w.W_ll(1, 1);
        const double eta0 = b[k].shear_modulus * b[k].relaxation_time;
        const Vector2 e(std::log(stored[4 * k]), std::log(stored[4 * k + 1]));
        Vector2       phi_e, phi_s;
        const double  phi = thinning.enabled ? thinning.factor(e, -w.W_e, &phi_e, &phi_s) : 1.;
        const Matrix2 M   = mobility(eta0 * phi);
        Matrix2       rate_y = -M * w.W_ee, rate_l = -M * w.W_le.transpose();
        if (thinning.enabled)
          {
            // q = -M W_e with M ~ 1/eta: dq = -M dW_e - q d(eta) / eta, with
            // d(phi)/de = phi_e - W_ee phi_s and d(phi)/dl = -W_le phi_s (s = -W_e).
            const Vector2 q = -M * w.W_e;
            rate_y -= q * (phi_e - w.W_ee * phi_s).transpose() / phi;
            rate_l += q * (w.W_le * phi_s).transpose() / phi;
          }
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            {
              const std::size_t row = 2 * k + i, column = 2 * k + j;
              out.stress_y[i * n + column] = w.W_le(i, j);
              out.rate_y[row * n + column] = rate_y(i, j);
              out.rate_l[row * 2 + j]      = rate_l(i, j);
            }
      }
    out.instantaneous = t;
    return true;
  }

  void TwoNetworkGentLaw::declare_parameters(ParameterDeclarations &prm)
  {
    prm.enter_subsection("Material");
    prm.add_number("Network B shear modulus (kPa)", "45",
                   "Shear modulus mu_B of network B's spring (viscoelastic model).");
    prm.add_number("Network B Jlim", "270", "Gent limit Jlim_B of network B's spring.");
    prm.add_number("Relaxation time (s)", "2",
                   "tau = eta / mu_B of network B (eta: the dashpot's viscosity).");
    prm.add_text("Branch shear moduli (kPa)", "",
                 "A relaxation spectrum (viscoelastic model): the shear moduli mu_k of "
                 "network B's parallel branches, e.g. '30, 10, 5'; empty: one branch, "
                 "Network B shear modulus, Network B Jlim and Relaxation time (s).");
    prm.add_text("Branch relaxation times (s)", "",
                 "tau_k = eta_k / mu_k of the branches, as many as Branch shear moduli "
                 "(kPa).");
    prm.add_text("Branch Jlim", "",
                 "Jlim_k of the branches' springs, as many as Branch shear moduli (kPa); "
                 "empty: Network B Jlim for every branch.");
    prm.add_text("Branch law", "elastic",
                 "The elastic law of every branch's spring (and of network B's one "
                 "spring): a Material/Model value without internal variables ('elastic' "
                 "is Gent), with Shear modulus mu_k, Jlim Jlim_k and the law's other "
                 "constants from subsection Material.");
    prm.leave_subsection();
    ShearThinning::declare_parameters(prm);
  }

  namespace
  {
    /// A list entry of subsection Material (empty text: no value).
    std::vector<double> branch_list(const LawSettings &settings, const std::string &entry)
    {
      const std::string text = settings.text(entry, "");
      if (trim_blanks(text).empty())
        return {};
      return parse_number_list(text, "Material/" + entry);
    }

    /// Checks one branch's constants; @p what names the entries ("Material/
    /// Network B shear modulus (kPa)" or the list entry with the branch).
    void check_branch(const double mu_a_kPa, const double mu_kPa, const double jlim,
                      const double tau, const std::string names[3])
    {
      // Bounds the solver can meet: network B more than 1e4 times as stiff
      // as network A leaves no equilibrium under the dead load (measured at
      // 1e5), and relaxation times outside 1e-12..1e12 s are below the
      // smallest time step or beyond any run's duration.
      if (!(mu_kPa >= 1e-6 * mu_a_kPa && mu_kPa <= 1e4 * mu_a_kPa))
        throw InputError(names[0] + " must be between 1e-6 and 1e4 times Material/Shear modulus "
                         "(kPa) (" + format_number(1e-6 * mu_a_kPa) + " to " +
                         format_number(1e4 * mu_a_kPa) + " kPa), got " + format_number(mu_kPa));
      if (!(jlim >= 1e-12 && jlim <= 1e12))
        throw InputError(names[1] + " must be between 1e-12 and 1e12, got " +
                         format_number(jlim));
      if (!(tau >= 1e-12 && tau <= 1e12))
        throw InputError(names[2] + " must be between 1e-12 and 1e12 s, got " +
                         format_number(tau));
    }

    /// The branches of the list entries (empty if Branch shear moduli is).
    std::vector<ViscousNetwork> listed_branches(const LawSettings &settings)
    {
      const std::string   moduli = "Branch shear moduli (kPa)", times = "Branch relaxation times (s)",
                          limits = "Branch Jlim";
      const std::vector<double> mu = branch_list(settings, moduli), tau = branch_list(settings, times);
      std::vector<double>       jlim = branch_list(settings, limits);
      if (mu.empty() && tau.empty() && jlim.empty())
        return {};
      if (mu.empty() || mu.size() > max_viscous_branches)
        throw InputError("Material/" + moduli + " must list 1 to " +
                         std::to_string(max_viscous_branches) + " shear moduli when Material/" +
                         times + " or Material/" + limits + " is set, got " +
                         std::to_string(mu.size()));
      if (tau.size() != mu.size())
        throw InputError("Material/" + times + " must list as many relaxation times as Material/" +
                         moduli + " lists moduli (" + std::to_string(mu.size()) + "), got " +
                         std::to_string(tau.size()));
      if (jlim.empty())
        jlim.assign(mu.size(), settings.constant("Network B Jlim"));
      if (jlim.size() != mu.size())
        throw InputError("Material/" + limits + " must be empty or list as many values as "
                         "Material/" + moduli + " (" + std::to_string(mu.size()) + "), got " +
                         std::to_string(jlim.size()));
      std::vector<ViscousNetwork> branches;
      for (std::size_t k = 0; k < mu.size(); ++k)
        {
          const std::string of = " (branch " + std::to_string(k + 1) + ")";
          const std::string names[3] = {"Material/" + moduli + of, "Material/" + limits + of,
                                        "Material/" + times + of};
          check_branch(units::kPa_divided.from_si(settings.material.shear_modulus), mu[k], jlim[k], tau[k], names);
          branches.push_back({units::kPa.in_si(mu[k]), jlim[k], tau[k]});
        }
      return branches;
    }

    /// Every branch's spring, the law of Material/Branch law with the
    /// branch's mu and Jlim (none for the Gent law: the constructor's).
    std::vector<SpringLaw> make_springs(const LawSettings                 &settings,
                                       const std::vector<ViscousNetwork> &branches)
    {
      const std::string law = trim_blanks(settings.text("Branch law", "elastic"));
      if (law == "elastic")
        return {};
      const std::vector<std::string> names = MembraneLaws::names();
      if (std::find(names.begin(), names.end(), law) == names.end() || law == settings.model)
        throw InputError("Material/Branch law must name an elastic law of Material/Model "
                         "other than '" + settings.model + "', got '" + law + "'");
      std::vector<SpringLaw> springs;
      for (const ViscousNetwork &n : branches)
        {
          LawSettings s                = settings;
          s.model                      = law;
          s.material.shear_modulus     = n.shear_modulus;
          s.material.jlim              = n.jlim;
          springs.push_back(make_membrane_law(s));
          if (springs.back()->n_internal_variables() != 0)
            throw InputError("Material/Branch law must name a law without internal variables, "
                             "got '" + law + "'");
        }
      return springs;
    }
  } // namespace

  std::shared_ptr<const MembraneLaw> TwoNetworkGentLaw::create(const LawSettings &settings)
  {
    std::vector<ViscousNetwork> branches = listed_branches(settings);
    if (branches.empty())
      {
        const double      mu_b = settings.constant("Network B shear modulus (kPa)");
        const double      jlim = settings.constant("Network B Jlim");
        const double      tau  = settings.constant("Relaxation time (s)");
        const std::string names[3] = {"Material/Network B shear modulus (kPa)",
                                      "Material/Network B Jlim", "Material/Relaxation time (s)"};
        check_branch(units::kPa_divided.from_si(settings.material.shear_modulus), mu_b, jlim, tau, names);
        branches.push_back({units::kPa.in_si(mu_b), jlim, tau});
      }
    set_branch_constants(settings.constants, settings.material.shear_modulus, branches);
    std::vector<SpringLaw> springs = make_springs(settings, branches);
    return std::make_shared<TwoNetworkGentLaw>(settings.material, std::move(branches),
                                               std::move(springs), ShearThinning::parse(settings));
  }

  CDEA_REGISTER_PLUGIN(MembraneLaws, TwoNetworkGentLaw, "viscoelastic", 0,
                       "the 'elastic' law is network A (the long-time response), in "
                       "parallel with "
                       "network B, a Gent spring in series with a dashpot (two-network "
                       "model of Hong 2011 and Zhao, Koh, Suo 2011); needs Time/Enabled = "
                       "true.")
} // namespace cdea
