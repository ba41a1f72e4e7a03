// Exact sensitivities through time (analysis/creep_sensitivity.h,
// doc/materials.md "Sensitivities through time"):
//  - the viscoelastic law's derivatives at a fixed state (stress and rate of
//    the evolving variables) with respect to network A's constants and each
//    branch's mu_k and tau_k against central differences of evaluate(), for
//    Gent and Mooney-Rivlin springs;
//  - creep_with_sensitivities' Jacobian against central differences of its
//    own displacement (fixed steps, so that both runs take the same steps):
//    a small film (one ring, 3 elements of degree 2) under a voltage step
//    and a 2-step staircase, 1 and 3 branches, ESDIRK4, backward Euler and
//    the trapezoidal rule, every parameter;
//  - the refusals name what is wrong.

#include <cdea/analysis/creep_sensitivity.h>
#include <cdea/base/format.h>
#include <cdea/input/parameter_input.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/two_network_gent.h>

#include "check.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using namespace cdea;
using cdea_test::check;

namespace
{
  using Overrides = std::vector<std::pair<std::string, std::string>>;

  // ---------------------------------------------------------------- the law

  struct LawCase
  {
    std::vector<double> mu_kPa, tau;
    std::string         spring;
  };

  std::shared_ptr<const MembraneLaw> make_law(const LawCase &c, const MaterialConstants &film)
  {
    LawSettings s;
    s.model     = "viscoelastic";
    s.material  = film;
    s.constants = {{"Network B shear modulus (kPa)", 45.},
                   {"Network B Jlim", 60.},
                   {"Relaxation time (s)", 2.},
                   {"Mooney-Rivlin C2 (kPa)", 3.}};
    std::string mu, tau;
    for (std::size_t k = 0; k < c.mu_kPa.size(); ++k)
      {
        mu += (k ? ", " : "") + format_number(c.mu_kPa[k], 17);
        tau += (k ? ", " : "") + format_number(c.tau[k], 17);
      }
    s.texts = {{"Branch shear moduli (kPa)", mu},
               {"Branch relaxation times (s)", tau},
               {"Branch law", c.spring}};
    return make_membrane_law(s);
  }

  /// Stress and rates of @p law at (l1, l2, voltage) with @p stored held.
  std::vector<double> stress_and_rate(const MembraneLaw &law, const LawInput &in,
                                      const std::vector<double> &stored)
  {
    std::vector<double> current = stored;
    LawResponse         r;
    law.evaluate(in, {stored.data(), current.data(), 0., TimeScheme::backward_euler}, law_stress,
                 r);
    std::vector<double> y(law.n_evolving()), rate(law.n_evolving());
    law.evolving_state(current.data(), y.data(), rate.data());
    std::vector<double> v = {r.stress.s1, r.stress.s2};
    v.insert(v.end(), rate.begin(), rate.end());
    return v;
  }

  void check_law(const LawCase &c)
  {
    const MaterialConstants film{25.1e3, 90., 3.98e-11, 1e-3};
    const auto              law = make_law(c, film);
    const LawInput          in{2.7, 2.2, 3.5e3};
    std::vector<double>     stored;
    const double            xi[3][2] = {{1.9, 2.4}, {2.3, 1.7}, {2.6, 2.1}};
    for (std::size_t k = 0; k < c.mu_kPa.size(); ++k)
      stored.insert(stored.end(), {xi[k][0], xi[k][1], 0., 0.});
    const unsigned int        nb = c.mu_kPa.size();
    std::vector<LawParameter> list = {LawParameter::shear_modulus, LawParameter::jlim,
                                      LawParameter::permittivity, LawParameter::voltage};
    for (unsigned int k = 0; k < 2 * nb; ++k)
      list.push_back(own_constant(k));
    double worst = 0.;
    for (const LawParameter parameter : list)
      {
        NominalStress       ds{0., 0.};
        std::vector<double> d_rate(law->n_evolving());
        if (!check(law->evolving_parameter_derivative(in, stored.data(), parameter, ds,
                                                      d_rate.data()),
                   "a derivative with respect to parameter " + std::to_string(int(parameter))))
          continue;
        std::vector<double> exact = {ds.s1, ds.s2};
        exact.insert(exact.end(), d_rate.begin(), d_rate.end());
        // Central differences of the law rebuilt with the parameter moved.
        std::vector<double> value[2];
        for (int side = 0; side < 2; ++side)
          {
            const double      sign = side == 0 ? 1. : -1.;
            MaterialConstants f    = film;
            LawCase           moved = c;
            LawInput          at    = in;
            const int         own   = own_constant_index(parameter);
            double            step  = 0.;
            if (parameter == LawParameter::shear_modulus)
              f.shear_modulus += sign * (step = 1e-4 * film.shear_modulus);
            else if (parameter == LawParameter::jlim)
              f.jlim += sign * (step = 1e-4 * film.jlim);
            else if (parameter == LawParameter::permittivity)
              f.permittivity += sign * (step = 1e-4 * film.permittivity);
            else if (parameter == LawParameter::voltage)
              at.voltage += sign * (step = 1e-4 * in.voltage);
            else if (own % 2 == 0)
              {
                step = 1e-4 * c.mu_kPa[own / 2] * 1e3;
                moved.mu_kPa[own / 2] += sign * step / 1e3;
              }
            else
              moved.tau[own / 2] += sign * (step = 1e-4 * c.tau[own / 2]);
            value[side] = stress_and_rate(*make_law(moved, f), at, stored);
            for (double &v : value[side])
              v /= 2. * step;
          }
        double scale = 0.;
        for (std::size_t i = 0; i < exact.size(); ++i)
          scale = std::max(scale, std::abs(value[0][i] - value[1][i]));
        for (std::size_t i = 0; i < exact.size(); ++i)
          worst = std::max(worst, std::abs(exact[i] - (value[0][i] - value[1][i])) / scale);
      }
    cdea_test::check_close(worst, 0., 1e-7,
                           "law derivatives against central differences (" +
                             std::to_string(nb) + " branches, spring '" + c.spring +
                             "'), largest error over the largest entry");
  }

  // ---------------------------------------------------------- the creep run

  struct RunCase
  {
    std::string         name;
    std::vector<double> mu_kPa, tau;
    std::string         scheme;
    bool                staircase = false;
    std::string         control   = "fixed";
  };

  /// The overrides of @p c, with the entry of parameter @p moved (-1: none)
  /// moved by @p step (SI).
  Overrides overrides(const RunCase &c, const std::string &table, const int moved,
                      const double step)
  {
    std::vector<double> mu = c.mu_kPa, tau = c.tau;
    double              mu_a = 25.1, jlim = 90., eps = 3.98e-11, volts = 4.;
    const int           own  = moved - int(LawParameter::voltage) - 1;
    if (moved == int(LawParameter::shear_modulus))
      mu_a += step / 1e3;
    else if (moved == int(LawParameter::jlim))
      jlim += step;
    else if (moved == int(LawParameter::permittivity))
      eps += step;
    else if (moved == int(LawParameter::voltage))
      volts += step / 1e3;
    else if (own >= 0 && own % 2 == 0)
      mu[own / 2] += step / 1e3;
    else if (own >= 0)
      tau[own / 2] += step;
    std::string mu_list, tau_list;
    for (std::size_t k = 0; k < mu.size(); ++k)
      {
        mu_list += (k ? ", " : "") + format_number(mu[k], 17);
        tau_list += (k ? ", " : "") + format_number(tau[k], 17);
      }
    Overrides o = {{"Discretization/Elements per ring", "3"},
                   {"Discretization/Polynomial degree", "2"},
                   {"Material/Model", mu.empty() ? "elastic" : "viscoelastic"},
                   {"Material/Shear modulus (kPa)", format_number(mu_a, 17)},
                   {"Material/Jlim", format_number(jlim, 17)},
                   {"Material/Permittivity (F/m)", format_number(eps, 17)},
                   {"Material/Branch shear moduli (kPa)", mu_list},
                   {"Material/Branch relaxation times (s)", tau_list},
                   {"Electrodes/Voltage path (kV)", format_number(volts, 17)},
                   {"Solver/Residual tolerance", "1e-13"},
                   {"Time/Enabled", "true"},
                   {"Time/Scheme", c.scheme},
                   {"Time/Step control", c.control},
                   {"Time/Time step (s)", "0.05"}};
    if (c.staircase)
      o.insert(o.end(), {{"Time/Waveform", "table"}, {"Time/Table file", table}});
    else
      o.insert(o.end(), {{"Time/Ramp time (s)", "0.05"}, {"Time/Hold time (s)", "0.35"}});
    return o;
  }

  CreepSensitivity creep(const Overrides &o, const std::vector<LawParameter> &list,
                         const std::vector<double> &times)
  {
    ParameterInput input = ParameterInput::text("");
    input.overrides      = o;
    CreepSensitivity out;
    std::string      message;
    if (!creep_with_sensitivities(read_parameters(input), list, times, out, message))
      check(false, "creep run: " + message);
    return out;
  }

  /// The SI value of parameter @p j of @p c (its finite-difference step is
  /// 1e-4 of it).
  double value_of(const RunCase &c, const LawParameter j)
  {
    const int own = own_constant_index(j);
    if (own >= 0)
      return own % 2 == 0 ? c.mu_kPa[own / 2] * 1e3 : c.tau[own / 2];
    return j == LawParameter::shear_modulus ? 25.1e3 :
           j == LawParameter::jlim          ? 90. :
           j == LawParameter::permittivity  ? 3.98e-11 :
                                              4e3;
  }

  /// The largest |exact - central difference| over the largest |column entry|.
  double check_run(const RunCase &c, const std::string &table)
  {
    std::vector<LawParameter> list = {LawParameter::shear_modulus, LawParameter::jlim,
                                      LawParameter::permittivity};
    if (!c.staircase)
      list.push_back(LawParameter::voltage);
    for (unsigned int k = 0; k < 2 * c.mu_kPa.size(); ++k)
      list.push_back(own_constant(k));
    const std::vector<double> times = {0.05, 0.1, 0.2, 0.4};
    const CreepSensitivity    exact = creep(overrides(c, table, -1, 0.), list, times);
    double                    worst = 0.;
    for (std::size_t j = 0; j < list.size() && exact.displacement.size() == times.size(); ++j)
      {
        const double step = 1e-4 * value_of(c, list[j]);
        const auto   plus = creep(overrides(c, table, int(list[j]), step), {}, times);
        const auto   minus = creep(overrides(c, table, int(list[j]), -step), {}, times);
        double       scale = 0., error = 0.;
        for (std::size_t i = 0; i < times.size() && plus.displacement.size() == times.size() &&
                                minus.displacement.size() == times.size();
             ++i)
          {
            const double fd = (plus.displacement[i] - minus.displacement[i]) / (2. * step);
            scale           = std::max(scale, std::abs(fd));
            error           = std::max(error, std::abs(exact.jacobian(i, j) - fd));
          }
        cdea_test::out() << "    parameter " << int(list[j]) << ": " << error / scale << '\n';
        worst = std::max(worst, error / scale);
      }
    return worst;
  }
} // namespace

CDEA_TEST_MAIN()
{
  check_law({{45.}, {2.}, "elastic"});
  check_law({{25., 15., 5.}, {0.2, 2., 20.}, "elastic"});
  check_law({{25., 15., 5.}, {0.2, 2., 20.}, "mooney-rivlin"});

  const std::string table = "creep_staircase.csv";
  {
    std::ofstream csv(table);
    csv << "time_s, V_kV\n0, 0\n0.05, 3\n0.2, 3\n0.25, 4.5\n0.4, 4.5\n";
  }
  const std::vector<RunCase> cases = {
    {"1 branch, step, ESDIRK4", {45.}, {0.2}, "ESDIRK4", false},
    {"3 branches, step, ESDIRK4", {25., 15., 5.}, {0.05, 0.2, 1.}, "ESDIRK4", false},
    {"1 branch, staircase, ESDIRK4", {45.}, {0.2}, "ESDIRK4", true},
    {"3 branches, staircase, ESDIRK4", {25., 15., 5.}, {0.05, 0.2, 1.}, "ESDIRK4", true},
    {"3 branches, step, backward Euler", {25., 15., 5.}, {0.05, 0.2, 1.}, "backward Euler", false},
    {"3 branches, staircase, trapezoidal", {25., 15., 5.}, {0.05, 0.2, 1.}, "trapezoidal", true},
    {"elastic film, staircase, ESDIRK3", {}, {}, "ESDIRK3", true}};
  for (const RunCase &c : cases)
    cdea_test::check_close(check_run(c, table), 0., 1e-6,
                           c.name + ": Jacobian against central differences, largest error "
                                    "over the column's largest entry");
  std::remove(table.c_str());

  // Under error control the steps differ from run to run, so the Jacobian
  // is checked against the fixed-step one (both approximate the sensitivity
  // of the time-continuous solution) rather than by differences.
  {
    RunCase c = cases[1];
    const std::vector<LawParameter> list = {LawParameter::shear_modulus, own_constant(0),
                                            own_constant(1), own_constant(5)};
    const std::vector<double>       times = {0.1, 0.4};
    Overrides fixed = overrides(c, table, -1, 0.);
    fixed.push_back({"Time/Time step (s)", "0.0125"});
    c.control        = "error";
    Overrides error  = overrides(c, table, -1, 0.);
    error.push_back({"Time/Relative tolerance", "1e-8"});
    const CreepSensitivity a = creep(fixed, list, times), b = creep(error, list, times);
    double                 worst = 0.;
    for (Eigen::Index j = 0; j < a.jacobian.cols() && b.jacobian.size() == a.jacobian.size(); ++j)
      worst = std::max(worst, (a.jacobian.col(j) - b.jacobian.col(j)).cwiseAbs().maxCoeff() /
                                a.jacobian.col(j).cwiseAbs().maxCoeff());
    cdea_test::check_close(worst, 0., 1e-4,
                           "error control (relative 1e-8) against fixed steps of 0.0125 s");
  }

  // Refusals.
  CreepSensitivity out;
  std::string      message;
  ParameterInput   input = ParameterInput::text("");
  bool refused = !creep_with_sensitivities(read_parameters(input), {}, {0.1}, out, message);
  check(refused && message.find("Time/Enabled") != std::string::npos,
        "a run without Time/Enabled is refused: " + message);
  input.overrides = {{"Material/Model", "viscoelastic"},
                     {"Time/Enabled", "true"},
                     {"Discretization/Elements per ring", "2"}};
  refused = !creep_with_sensitivities(read_parameters(input), {}, {0.5, 0.2}, out, message);
  check(refused && message.find("sample time 2") != std::string::npos,
        "decreasing sample times are refused: " + message);
  refused = !creep_with_sensitivities(read_parameters(input), {own_constant(2)}, {0.5}, out,
                                      message);
  check(refused && message.find("own constant 2") != std::string::npos,
        "a constant the law does not have is refused: " + message);
  input.overrides.push_back({"Time/Rest time before voltage (s)", "5"});
  refused = !creep_with_sensitivities(read_parameters(input), {}, {0.5}, out, message);
  check(refused && message.find("relaxed") != std::string::npos,
        "a rest time is refused: " + message);
  return cdea_test::failures() == 0 ? 0 : 1;
}
