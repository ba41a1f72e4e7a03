// Periodic steady states (analysis/periodic_steady_state.h, doc/dynamics.md
// "Periodic steady states and the frequency sweep") on a coarse mesh:
//  (a) at a small drive (a 5 V swing on 5 kV) the steady state's first
//      harmonic of z(A) equals `cdea response`'s transfer function within
//      1e-3 in amplitude and phase, elastic (no damping, off resonance) and
//      viscoelastic (around resonance);
//  (b) energy balance over a steady period of a large drive (0 to 5 kV):
//      electrical work = dissipation + stored change within 1e-6 relative;
//  (c) periodicity: one more period integrated with error control from the
//      found state moves it by less than the tolerance;
//  the frequency sweep's usable band and the bad inputs of its settings.
#include <cdea/analysis/frequency_response.h>
#include <cdea/analysis/frequency_sweep.h>
#include <cdea/analysis/periodic_steady_state.h>
#include <cdea/base/text.h>
#include <cdea/input/parameter_input.h>

#include "check.h"

#include <cmath>
#include <complex>
#include <string>

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// prm/response.prm's actuator on a coarse mesh, ESDIRK4 at tight tolerances.
  std::string base_text(const bool viscous, const std::string &voltage)
  {
    std::string text = "subsection Discretization\n  set Polynomial degree = 2\n"
                       "  set Elements per ring = 2\nend\n"
                       "subsection Electrodes\n  set Ring edges (r/a) = 1, 3\n"
                       "  set Voltage path (kV) = " + voltage + "\nend\n"
                       "subsection Time\n  set Enabled = true\n  set Waveform = sine\n"
                       "  set Scheme = ESDIRK4\n  set Relative tolerance = 1e-10\n"
                       "  set Absolute tolerance (mm) = 1e-9\n  set Inertia = true\nend\n";
    if (viscous)
      text += "subsection Material\n  set Model = viscoelastic\n"
              "  set Network B shear modulus (kPa) = 45\n  set Relaxation time (s) = 2\nend\n";
    return text;
  }

  RunInput input_of(const std::string &text)
  {
    return read_run_input(ParameterInput::text(text), RunMethod::finite_elements);
  }

  /// (a): the steady state's first harmonic against the response, for a
  /// swing of @p swing volts about 5 kV.
  void small_drive(const bool viscous, const std::vector<double> &frequencies,
                   const double swing = 5.)
  {
    const std::string name = viscous ? "viscoelastic" : "elastic";
    const RunInput    bias = input_of(base_text(viscous, "5"));
    const RunInput drive = input_of(base_text(viscous, std::to_string(5. + 1e-3 * swing)));
    SteadyStateSettings s;
    s.tolerance    = 1e-8;
    s.low_fraction = (5000. - swing) / (5000. + swing);
    PeriodicSteadyState steady(drive.parameters, drive.scene, s);
    for (const double f : frequencies)
      {
        RunInput in                                 = bias;
        in.parameters.response.lowest_frequency_Hz  = f;
        in.parameters.response.highest_frequency_Hz = 2. * f;
        const FrequencyResponse one                 = frequency_response(in);
        // The drive's complex amplitude on the largest ring: -5 V (a -cos).
        const std::complex<double> expected = one.disk_drive[0] * -swing;
        const SteadyPeriod         p        = steady.solve(f);
        const std::string at = name + " at " + std::to_string(f) + " Hz, swing " +
                               std::to_string(swing) + " V";
        if (!p.converged)
          out() << p.message << "\n";
        check(p.converged, at + ": converged (" + std::to_string(p.newton_iterations) +
                             " Newton iterations, " + std::to_string(p.period_maps) +
                             " periods, " + std::to_string(p.seconds) + " s)");
        check_rel(std::abs(p.first_harmonic), std::abs(expected), 1e-3, at + ": amplitude (m)");
        check_close(std::arg(p.first_harmonic / expected), 0., 1e-3, at + ": phase (rad)");
        check(p.check_move <= s.tolerance, at + ": the check period moves it by " +
                                             std::to_string(p.check_move));
      }
  }

  /// (b) and (c) at a large drive, and the sweep's band.
  void large_drive()
  {
    const RunInput      in = input_of(base_text(true, "5"));
    SteadyStateSettings s;
    s.tolerance = 1e-8;
    PeriodicSteadyState steady(in.parameters, in.scene, s);
    const SteadyPeriod  p = steady.solve(2.5);
    check(p.converged, "0 to 5 kV at 2.5 Hz: converged");
    out() << "  stroke " << p.stroke_amplitude * 1e3 << " mm, work " << p.electrical_work
          << " J, dissipated " << p.dissipated << " J, stored change " << p.stored_change
          << " J, weight's work " << p.weight_work << " J\n";
    check_close(p.energy_defect(), 0., 1e-6, "energy balance over the steady period (relative)");
    check_close((p.electrical_work + p.weight_work - p.dissipated) / p.dissipated, 0., 1e-6,
                "work of the source and the weight = dissipation (relative)");
    check(p.check_move <= s.tolerance, "periodicity: the check period moves it by " +
                                         std::to_string(p.check_move));
  }

  std::string settings_error(const std::string &text)
  {
    try
      {
        frequency_sweep_settings(input_of(base_text(true, "5") + text).parameters);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  void bad_settings()
  {
    const std::string empty =
      settings_error("subsection Frequency sweep\n  set Frequencies = 0\nend\n");
    check(empty.find("Frequency sweep/Frequencies") != std::string::npos, "empty list: " + empty);
    const std::string negative =
      settings_error("subsection Frequency sweep\n  set Frequencies (Hz) = 1, -2\nend\n");
    check(negative.find("Frequency sweep/Frequencies (Hz)") != std::string::npos,
          "negative frequency: " + negative);
    const std::string ramp = settings_error("subsection Time\n  set Waveform = ramp-hold\nend\n");
    check(ramp.find("Time/Waveform") != std::string::npos, "ramp-hold: " + ramp);
  }
} // namespace

// With --doc: the five frequencies of doc/dynamics.md for each film.
CDEA_TEST_MAIN(int argc, char **argv)
{
  const bool doc = argc > 1 && std::string(argv[1]) == "--doc";
  small_drive(false, doc ? std::vector<double>{2., 3., 3.5, 4., 5.} : std::vector<double>{2., 5.});
  small_drive(true, doc ? std::vector<double>{3., 3.5, 3.8, 4.2, 5.} : std::vector<double>{3.5, 4.2});
  // At the resonance the difference is the nonlinearity: it falls as the
  // square of the swing.
  if (doc)
    for (const double swing : {0.5, 0.05})
      small_drive(true, {3.8}, swing);
  large_drive();
  bad_settings();
  return finish();
}
