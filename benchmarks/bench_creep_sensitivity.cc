// Benchmark: one Jacobian evaluation of a 3-branch creep fit (doc/materials.md,
// "Sensitivities through time"). The film of prm/default.prm (viscoelastic,
// branches of 25, 15 and 5 kPa at 0.2, 2 and 20 s) under a 5 kV step held
// 20 s (0.05 s ramp), ESDIRK4 with error control (the defaults), sampled
// every second of the hold: creep_with_sensitivities with the 7 parameters
// of the fit (network A's shear modulus, each branch's mu_k and tau_k)
// against the same run without parameters (the same steps), interleaved.
// It prints the median CPU time of each and their ratio, and checks the
// answer: the two runs' displacements agree to 1e-12 (relative), and on a
// short fixed-step version every column agrees with central differences of
// the displacement to 1e-6 of the column's largest entry.
//
//   build/benchmarks/bench_creep_sensitivity [RUNS] [HOLD_S]
//
// Smoke run (ctest): bench_creep_sensitivity 1 2

#include <cdea/analysis/creep_sensitivity.h>
#include <cdea/base/format.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>

#include "bench_common.h"

#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace cdea;

namespace
{
  using Overrides = std::vector<std::pair<std::string, std::string>>;

  const std::vector<double> moduli_kPa = {25., 15., 5.}, times_s = {0.2, 2., 20.};

  /// The film with branch constant @p own (-1: none) moved by @p step (SI).
  Parameters film(const double hold, const bool fixed_steps, const int own, const double step)
  {
    std::vector<double> mu = moduli_kPa, tau = times_s;
    if (own >= 0 && own % 2 == 0)
      mu[own / 2] += step / 1e3;
    else if (own >= 0)
      tau[own / 2] += step;
    std::string mu_list, tau_list;
    for (std::size_t k = 0; k < mu.size(); ++k)
      {
        mu_list += (k ? ", " : "") + format_number(mu[k], 17);
        tau_list += (k ? ", " : "") + format_number(tau[k], 17);
      }
    ParameterInput input = ParameterInput::text("");
    input.overrides      = {{"Material/Model", "viscoelastic"},
                            {"Material/Branch shear moduli (kPa)", mu_list},
                            {"Material/Branch relaxation times (s)", tau_list},
                            {"Time/Enabled", "true"},
                            {"Time/Ramp time (s)", "0.05"},
                            {"Time/Hold time (s)", format_number(hold, 17)}};
    if (fixed_steps)
      input.overrides.insert(input.overrides.end(), {{"Time/Step control", "fixed"},
                                                     {"Time/Time step (s)", "0.05"},
                                                     {"Solver/Residual tolerance", "1e-13"}});
    return read_parameters(input);
  }

  CreepSensitivity creep(const Parameters &p, const std::vector<LawParameter> &list,
                         const std::vector<double> &samples)
  {
    CreepSensitivity out;
    std::string      message;
    if (!creep_with_sensitivities(p, list, samples, out, message))
      throw std::runtime_error(message);
    return out;
  }

  /// The largest error of a column of the fixed-step Jacobian of the branch
  /// constants against central differences (relative step 1e-4), over the
  /// column's largest entry.
  double difference_check(const std::vector<LawParameter> &list)
  {
    const std::vector<double> samples = {0.1, 0.3, 0.5};
    const CreepSensitivity    exact   = creep(film(0.45, true, -1, 0.), list, samples);
    double                    worst   = 0.;
    for (unsigned int k = 0; k < 6; ++k)
      {
        const double value = k % 2 == 0 ? moduli_kPa[k / 2] * 1e3 : times_s[k / 2];
        const double step  = 1e-4 * value;
        const auto   plus  = creep(film(0.45, true, int(k), step), {}, samples);
        const auto   minus = creep(film(0.45, true, int(k), -step), {}, samples);
        double       scale = 0., error = 0.;
        for (std::size_t i = 0; i < samples.size(); ++i)
          {
            const double fd = (plus.displacement[i] - minus.displacement[i]) / (2. * step);
            scale           = std::max(scale, std::abs(fd));
            error           = std::max(error, std::abs(exact.jacobian(i, k + 1) - fd));
          }
        worst = std::max(worst, error / scale);
      }
    return worst;
  }
} // namespace

int main(int argc, char **argv)
{
  const int    runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const double hold = argc > 2 ? std::atof(argv[2]) : 20.;
  std::vector<LawParameter> list = {LawParameter::shear_modulus};
  for (unsigned int k = 0; k < 6; ++k)
    list.push_back(own_constant(k));
  std::vector<double> samples;
  for (double t = 0.05; t <= 0.05 + hold + 1e-9; t += 1.)
    samples.push_back(t);

  const Parameters    p = film(hold, false, -1, 0.);
  std::vector<double> with, without;
  CreepSensitivity    a, b;
  for (int r = 0; r < runs; ++r)
    {
      double t0 = cdea_bench::cpu_seconds();
      a         = creep(p, list, samples);
      with.push_back(cdea_bench::cpu_seconds() - t0);
      t0 = cdea_bench::cpu_seconds();
      b  = creep(p, {}, samples);
      without.push_back(cdea_bench::cpu_seconds() - t0);
    }
  double agree = 0.;
  for (std::size_t i = 0; i < samples.size(); ++i)
    agree = std::max(agree, std::abs(a.displacement[i] - b.displacement[i]) / b.displacement[i]);
  const double fd = difference_check(list);

  const double t_with = cdea_bench::median(with), t_without = cdea_bench::median(without);
  std::cout << std::setprecision(4) << "creep run of 3 branches, " << samples.size()
            << " samples over a " << hold << " s hold, " << runs << " run(s), CPU median:\n"
            << "  with sensitivities (7 parameters): " << t_with << " s\n"
            << "  without:                           " << t_without << " s\n"
            << "  ratio:                             " << t_with / t_without << '\n'
            << "  displacements with and without agree to " << agree << " (relative)\n"
            << "  fixed-step Jacobian against central differences: " << fd << '\n';
  const bool ok = agree <= 1e-12 && fd <= 1e-6 && a.jacobian.allFinite();
  if (!ok)
    std::cout << "FAIL: the answer is wrong\n";
  return ok ? 0 : 1;
}
