// The calibration of a law's own constants (design/fit.h, issue 20, item 4):
//  A. Calibration/Free parameters names a law's constants by their entries
//     of subsection Material (with or without the unit); a name the law does
//     not have is refused naming the entry and this law's names; a free Jlim
//     under a law without the Gent limit is refused;
//  B. Mooney-Rivlin mu and C2 from synthetic data of the program (the
//     two-ring points of test_fit) plus seeded noise of 0.02 mm: recovered
//     within 2 standard errors for each seed, rms near the noise; exact
//     data recovered to 1e-6;
//  C. Ogden mu_1 and alpha_1 from exact data; Gent-Gent C2 fitted to data
//     of the Gent law (C2 = 0) ends on its bound, not below;
//  D. a parameter the displacements do not depend on (Jlim under neo-Hooke,
//     given to fit() directly) is named in the warning.

#include <cdea/design/fit.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameters.h>

#include "check.h"
#include "scenes.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

using namespace cdea;
using namespace cdea_test;

namespace
{
  std::string settings_error(const std::string &material, const std::string &free)
  {
    const auto path = std::filesystem::temp_directory_path() /
                      ("cdea_test_law_fit_" + std::to_string(getpid()) + ".prm");
    std::ofstream(path) << "subsection Material\n" << material
                        << "end\nsubsection Calibration\n  set Free parameters = " << free
                        << "\nend\n";
    std::string message;
    try
      {
        const FitSettings s = fit_settings(read_parameters(path.string()));
        for (const auto &p : s.free)
          message += "[" + label(p) + "]";
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    std::filesystem::remove(path);
    return message;
  }

  void expect(const std::string &message, const std::string &expected)
  {
    check(message.find(expected) != std::string::npos,
          "'" + expected + "' in: " + (message.empty() ? "(no error)" : message));
  }

  /// Both rings up to 5 kV, then the outer ring up to 6.5 kV (r_v/a = 1.7).
  CalibrationData two_ring_points()
  {
    CalibrationData d;
    for (int k = 1; k <= 10; ++k)
      d.voltages.push_back({500. * k, 500. * k});
    for (int k = 1; k <= 10; ++k)
      d.voltages.push_back({5e3, 5e3 + 150. * k});
    d.displacement.assign(d.voltages.size(), 0.);
    d.weight.assign(d.voltages.size(), 1.);
    return d;
  }

  CalibrationData synthetic(const Scene &scene, CalibrationData d,
                            const std::vector<SceneParameter> &free,
                            const std::vector<double>         &values)
  {
    DisplacementModel model(scene, d, free, FeDiscretization(), NewtonSettings(),
                            SteppingSettings());
    Eigen::VectorXd   x;
    check(model.evaluate(values, x, nullptr), "synthetic data: every point reached");
    d.displacement.assign(x.data(), x.data() + x.size());
    return d;
  }

  FitResult fit_from(const Scene &start, const CalibrationData &data,
                     const std::vector<SceneParameter> &free)
  {
    FitSettings settings;
    settings.free = free;
    DisplacementModel model(start, data, free, FeDiscretization(), NewtonSettings(),
                            SteppingSettings());
    return fit(start, data, settings, model);
  }

  Scene law_scene(const std::string &model, const std::map<std::string, double> &constants)
  {
    Scene s          = paper_scene({1., 1.7, 3.}, {{5., 5.}});
    s.material_model = model;
    s.law_constants  = constants;
    return s;
  }

  void input_checks()
  {
    std::cout << "A. Free parameters of a law\n";
    const std::string mooney = "  set Model = mooney-rivlin\n";
    expect(settings_error(mooney, "shear modulus, Mooney-Rivlin C2 (kPa)"),
           "[shear modulus][Mooney-Rivlin C2 (kPa)]");
    expect(settings_error(mooney, "mooney-rivlin c2"), "[Mooney-Rivlin C2 (kPa)]");
    expect(settings_error(mooney, "shear modulus, Ogden alpha 1"),
           "Calibration/Free parameters: 'ogden alpha 1' is not a parameter that can be fitted "
           "with Material/Model = mooney-rivlin (any of shear modulus, permittivity, mass, "
           "pre-stretch, Mooney-Rivlin C2 (kPa))");
    expect(settings_error(mooney, "Mooney-Rivlin C2, mooney-rivlin c2 (kPa)"),
           "'mooney-rivlin c2 (kpa)' is given twice");
    expect(settings_error("  set Model = neo-hooke\n", "shear modulus, Jlim"),
           "Calibration/Free parameters: 'jlim': Material/Model = neo-hooke has no Jlim, the "
           "displacements do not depend on it (any of shear modulus, permittivity, mass, "
           "pre-stretch)");
    expect(settings_error("  set Model = ogden\n", "shear modulus, ogden alpha 1, Ogden mu 2"),
           "[shear modulus][Ogden alpha 1][Ogden mu 2 (kPa)]");
    expect(settings_error("  set Model = ogden\n", "Ogden mu 1"),
           "'ogden mu 1' is not a parameter that can be fitted with Material/Model = ogden (any "
           "of shear modulus, permittivity, mass, pre-stretch, Ogden alpha 1, Ogden mu 2 (kPa), "
           "Ogden alpha 2, Ogden mu 3 (kPa), Ogden alpha 3)");
    expect(settings_error("  set Model = gent-gent\n", "Jlim, Gent-Gent C2"),
           "[Jlim][Gent-Gent C2 (kPa)]");
    expect(settings_error("", "Gent-Gent C2"),
           "'gent-gent c2' is not a parameter that can be fitted (any of shear modulus, Jlim, "
           "permittivity, mass, pre-stretch)");
  }

  void mooney_rivlin_recovered()
  {
    std::cout << "B. Mooney-Rivlin mu and C2 recovered\n";
    const SceneParameter mu{ParameterKind::shear_modulus, 0},
      c2{ParameterKind::law_constant, 0, "Mooney-Rivlin C2 (kPa)"};
    const std::vector<SceneParameter> free{mu, c2};
    const std::vector<double>         truth{20e3, 3.};
    const Scene scene = law_scene("mooney-rivlin", {{"Mooney-Rivlin C2 (kPa)", 0.}});
    const CalibrationData exact = synthetic(scene, two_ring_points(), free, truth);
    // The start: the neo-Hookean law (C2 = 0, the lower end of its range).
    const Scene     start = with_parameter(scene, mu, 25e3);
    const FitResult a     = fit_from(start, exact, free);
    check(a.converged, "exact data: converged (" + a.status + ")");
    check_close(a.values[0] / truth[0] - 1., 0., 1e-6, "exact data: shear modulus");
    check_close(a.values[1] / truth[1] - 1., 0., 1e-6, "exact data: Mooney-Rivlin C2");

    for (const unsigned int seed : {1u, 2u, 3u, 4u, 5u})
      {
        CalibrationData                  noisy = exact;
        std::mt19937                     generator(seed);
        std::normal_distribution<double> noise(0., 0.02e-3);
        for (double &x : noisy.displacement)
          x += noise(generator);
        const FitResult b = fit_from(start, noisy, free);
        check(b.converged, "seed " + std::to_string(seed) + ": converged (" + b.status + ")");
        for (std::size_t j = 0; j < 2; ++j)
          {
            std::cout << "  seed " << seed << ", " << label(free[j]) << ": " << b.values[j]
                      << " +- " << b.standard_errors[j] << " (truth " << truth[j] << ")\n";
            check(std::abs(b.values[j] - truth[j]) < 2. * b.standard_errors[j],
                  "seed " + std::to_string(seed) + ": " + label(free[j]) +
                    " within 2 standard errors of the truth");
          }
        check(b.rms > 0.5 * 0.02e-3 && b.rms < 1.5 * 0.02e-3,
              "seed " + std::to_string(seed) + ": rms residual near the noise");
      }
  }

  void ogden_and_gent_gent()
  {
    std::cout << "C. Ogden mu_1 and alpha_1; Gent-Gent C2 kept in its range\n";
    const SceneParameter mu{ParameterKind::shear_modulus, 0},
      alpha{ParameterKind::law_constant, 0, "Ogden alpha 1"};
    const Scene ogden = law_scene("ogden", {{"Ogden alpha 1", 2.},
                                            {"Ogden mu 2 (kPa)", 0.},
                                            {"Ogden alpha 2", -2.},
                                            {"Ogden mu 3 (kPa)", 0.},
                                            {"Ogden alpha 3", 5.}});
    const CalibrationData data = synthetic(ogden, two_ring_points(), {mu, alpha}, {22e3, 2.6});
    const FitResult       r    = fit_from(ogden, data, {mu, alpha});
    check(r.converged, "Ogden: converged (" + r.status + ")");
    check_close(r.values[0] / 22e3 - 1., 0., 1e-6, "Ogden: mu_1");
    check_close(r.values[1] / 2.6 - 1., 0., 1e-6, "Ogden: alpha_1");

    // Data of the Gent law (C2 = 0, the lower end of the range) fitted from
    // C2 = 2 kPa: the fit ends on the bound, never below it.
    const SceneParameter c2{ParameterKind::law_constant, 0, "Gent-Gent C2 (kPa)"};
    const Scene gent_gent = law_scene("gent-gent", {{"Gent-Gent C2 (kPa)", 2.}});
    const CalibrationData gent_data =
      synthetic(gent_gent, two_ring_points(), {mu, c2}, {27e3, 0.});
    const FitResult g = fit_from(gent_gent, gent_data, {mu, c2});
    std::cout << "  Gent-Gent: mu " << g.values[0] << ", C2 " << g.values[1] << " kPa\n";
    check(g.values[1] >= 0., "Gent-Gent: C2 stays at least 0");
    check_close(g.values[0] / 27e3 - 1., 0., 1e-5, "Gent-Gent: mu of the Gent data");
  }

  void undetermined_parameter_named()
  {
    std::cout << "D. A parameter the displacements do not depend on is named\n";
    const SceneParameter mu{ParameterKind::shear_modulus, 0}, jlim{ParameterKind::jlim, 0};
    const Scene           scene = law_scene("neo-hooke", {});
    const CalibrationData data  = synthetic(scene, two_ring_points(), {mu}, {24e3});
    const FitResult       r     = fit_from(scene, data, {mu, jlim});
    check(!r.warnings.empty() &&
            r.warnings[0].find("the data do not determine Jlim separately") != std::string::npos,
          "warning: " + (r.warnings.empty() ? std::string("(none)") : r.warnings[0]));
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  input_checks();
  mooney_rivlin_recovered();
  ogden_and_gent_gent();
  undetermined_parameter_named();
  return finish();
}
