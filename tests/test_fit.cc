// The calibration in-process (design/fit.h):
//  A. the data file and subsection Calibration: messages name the file, line,
//     column or parameter;
//  B. the Jacobian of the data points against central differences of ramps
//     (every fit parameter; the pre-stretch moves the mesh);
//  C. synthetic data from known parameters recovered: exact data to 1e-7,
//     noisy data (seeded) within three reported standard errors, with a
//     residual rms near the noise;
//  D. mu and Jlim fitted to points generated at the paper's values return
//     25.1 kPa and 270;
//  E. shear modulus, permittivity and mass together: the energy depends on
//     eps/mu and F/mu only, and the fit says that they are not identifiable.

#include <cdea/design/fit.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameters.h>

#include "check.h"
#include "scenes.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <random>

using namespace cdea;
using namespace cdea_test;

namespace
{
  std::string temporary(const std::string &name, const std::string &content)
  {
    const auto path = std::filesystem::temp_directory_path() /
                      ("cdea_test_fit_" + std::to_string(getpid()) + "_" + name);
    std::ofstream(path) << content;
    return path.string();
  }

  std::string data_error(const std::string &csv, const unsigned int rings)
  {
    const std::string file = temporary("data.csv", csv);
    std::string       message;
    try
      {
        read_calibration_data(file, rings);
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    std::filesystem::remove(file);
    return message;
  }

  std::string settings_error(const std::string &entries)
  {
    const std::string file = temporary("fit.prm", "subsection Calibration\n" + entries + "end\n");
    std::string       message;
    try
      {
        fit_settings(read_parameters(file));
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    std::filesystem::remove(file);
    return message;
  }

  void expect(const std::string &message, const std::string &expected)
  {
    check(message.find(expected) != std::string::npos,
          "'" + expected + "' in: " + (message.empty() ? "(no error)" : message));
  }

  /// Points of the paper's actuator: two rings (r_v/a = 1.7), both rings up
  /// to 5 kV, then the outer ring up to 6.5 kV.
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

  /// The model's displacements at @p values as data.
  CalibrationData synthetic(const Scene &scene, CalibrationData d,
                            const std::vector<SceneParameter> &free,
                            const std::vector<double>         &values)
  {
    DisplacementModel model(scene, d, free, FeDiscretization(), NewtonSettings(),
                            SteppingSettings());
    Eigen::VectorXd   x;
    model.evaluate(values, x, nullptr);
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
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  const Scene      paper = paper_scene({1., 1.7, 3.}, {{5., 5.}});
  const SceneParameter mu{ParameterKind::shear_modulus, 0}, jlim{ParameterKind::jlim, 0},
    eps{ParameterKind::permittivity, 0}, mass{ParameterKind::mass, 0},
    prestretch{ParameterKind::prestretch, 0};

  std::cout << "A. Input checks\n";
  expect(data_error("V1_kV, displacement_mm\n1, 20\n", 2), "no column V2_kV (there are 2 rings)");
  expect(data_error("V1_kV, V2_kV, disp\n", 2), "unknown column 'disp'");
  expect(data_error("V1_kV, V2_kV, displacement_mm\n1, 1, x\n", 2),
         "line 2, column displacement_mm: 'x' is not a number");
  expect(data_error("V1_kV, V2_kV, displacement_mm\n1, 1\n", 2),
         "line 2: 2 fields, but the header has 3");
  expect(data_error("V1_kV, V2_kV, displacement_mm, weight\n# comment\n1, 1, 20, 0\n", 2),
         "line 3, column weight: weights must be positive");
  expect(data_error("V1_kV, V2_kV, displacement_mm\n-1, 1, 20\n", 2),
         "column V1_kV: a voltage must not be negative");
  expect(data_error("# only a comment\n", 1), "no header line");
  expect(data_error("V1_kV, V2_kV, displacement_mm\n1, 1, -20\n", 2),
         "line 2, column displacement_mm: a displacement is the distance");
  check(data_error("\xEF\xBB\xBFV1_kV, displacement_mm\n1, 20\n", 1) == "",
        "a UTF-8 byte order mark before the header is skipped");
  expect(data_error("V1_kV, displacement_mm\xC2\xA0\n", 1),
         "unknown column 'displacement_mm\\xC2\\xA0'");
  {
    std::istringstream in("V1_kV, displacement_mm\n1601, 20\n");
    std::string        message;
    try
      {
        read_calibration_data(in, "data", 1, 1.6e6);
      }
    catch (const InputError &e)
      {
        message = e.what();
      }
    expect(message, "data, line 2, column V1_kV: 1601 kV is above the ceiling of 1600 kV");
  }
  check(data_error("V2_kV,displacement_mm, V1_kV\n1,20,2 # comment\n\n", 2) == "",
        "columns in any order, comments and blank lines accepted");
  expect(settings_error("  set Free parameters = shear modulus, thickness\n"),
         "Calibration/Free parameters: 'thickness' is not a parameter that can be fitted");
  expect(settings_error("  set Free parameters = Jlim, jlim\n"),
         "Calibration/Free parameters: 'jlim' is given twice");

  std::cout << "B. The Jacobian against central differences of ramps\n";
  {
    const std::vector<SceneParameter> free{mu, jlim, eps, mass, prestretch};
    const CalibrationData             points = two_ring_points();
    DisplacementModel model(paper, points, free, FeDiscretization(), NewtonSettings(),
                            SteppingSettings());
    std::vector<double> values;
    for (const auto &p : free)
      values.push_back(parameter_value(paper, p));
    Eigen::VectorXd d;
    Eigen::MatrixXd J;
    check(model.evaluate(values, d, &J), "all points reached");
    for (std::size_t j = 0; j < free.size(); ++j)
      {
        const double    h = 1e-5 * values[j];
        auto            plus = values, minus = values;
        Eigen::VectorXd dp, dm;
        plus[j] += h;
        minus[j] -= h;
        DisplacementModel fresh(paper, points, free, FeDiscretization(), NewtonSettings(),
                                SteppingSettings());
        fresh.evaluate(plus, dp, nullptr);
        DisplacementModel fresh2(paper, points, free, FeDiscretization(), NewtonSettings(),
                                 SteppingSettings());
        fresh2.evaluate(minus, dm, nullptr);
        const Eigen::VectorXd fd = (dp - dm) / (2. * h);
        check_close((fd - J.col(j)).lpNorm<Eigen::Infinity>() / J.col(j).lpNorm<Eigen::Infinity>(),
                    0., 1e-6, "d displacement / d " + free[j].name() + ", 20 points");
      }
  }

  std::cout << "C. Synthetic data recovered\n";
  {
    const std::vector<SceneParameter> free{mu, jlim};
    const std::vector<double>         truth{30e3, 200.};
    const CalibrationData exact = synthetic(paper, two_ring_points(), free, truth);
    Scene start = with_parameter(with_parameter(paper, mu, 24e3), jlim, 320.);
    const FitResult a = fit_from(start, exact, free);
    check(a.converged, "exact data: converged (" + a.status + ")");
    check_close(a.values[0] / truth[0] - 1., 0., 1e-7, "exact data: shear modulus");
    check_close(a.values[1] / truth[1] - 1., 0., 1e-7, "exact data: Jlim");
    check_close(a.rms, 0., 1e-12, "exact data: rms residual (m)");
    // Exact data leave only rounding in the residuals (rms about 1e-15 m),
    // so the reported standard errors must be tiny. The recovery error is
    // then set by where Levenberg-Marquardt stops (Tolerance 1e-10 on the
    // relative step), not by the data: it must lie within 2 standard errors
    // plus that stopping tolerance (measured: 5 standard errors, 1e-12 and
    // 1.5e-11 relative).
    for (std::size_t j = 0; j < 2; ++j)
      {
        std::cout << "  " << free[j].name() << ": error " << a.values[j] - truth[j]
                  << ", standard error " << a.standard_errors[j] << "\n";
        check(a.standard_errors[j] > 0. && a.standard_errors[j] < 1e-10 * truth[j],
              "exact data: " + free[j].name() + " standard error below 1e-10 relative");
        check(std::abs(a.values[j] - truth[j]) <= 2. * a.standard_errors[j] + 1e-10 * truth[j],
              "exact data: " + free[j].name() +
                " within 2 standard errors plus the stopping tolerance");
      }

    CalibrationData  noisy = exact;
    std::mt19937     generator(20250829);
    std::normal_distribution<double> noise(0., 0.02e-3); // 0.02 mm
    for (double &x : noisy.displacement)
      x += noise(generator);
    const FitResult b = fit_from(start, noisy, free);
    check(b.converged, "noisy data: converged (" + b.status + ")");
    for (std::size_t j = 0; j < 2; ++j)
      {
        std::cout << "  " << free[j].name() << ": " << b.values[j] << " +- "
                  << b.standard_errors[j] << " (truth " << truth[j] << ")\n";
        // 2 standard errors, as tests/fit_run.sh uses (about 95 %).
        check(std::abs(b.values[j] - truth[j]) < 2. * b.standard_errors[j],
              "noisy data: " + free[j].name() + " within 2 standard errors of the truth");
      }
    check(b.rms > 0.5 * 0.02e-3 && b.rms < 1.5 * 0.02e-3, "noisy data: rms residual near the noise");
    check(std::abs(b.correlation(0, 1)) <= 1. && b.correlation(0, 0) == 1.,
          "a correlation matrix");
  }

  std::cout << "D. mu and Jlim at the paper's values\n";
  {
    const std::vector<SceneParameter> free{mu, jlim};
    const CalibrationData data = synthetic(paper, two_ring_points(), free, {25.1e3, 270.});
    const Scene     start = with_parameter(with_parameter(paper, mu, 20e3), jlim, 150.);
    const FitResult r     = fit_from(start, data, free);
    check(r.converged, "converged (" + r.status + ")");
    check_close(r.values[0] * 1e-3, 25.1, 1e-6, "shear modulus (kPa)");
    check_close(r.values[1], 270., 1e-5, "Jlim");
  }

  std::cout << "E. Parameters the data cannot separate\n";
  {
    const std::vector<SceneParameter> free{mu, eps, mass};
    const CalibrationData data = synthetic(paper, two_ring_points(), free, {25.1e3, 3.98e-11, 0.28});
    const Scene     start = with_parameter(paper, mu, 22e3);
    const FitResult r     = fit_from(start, data, free);
    check(!r.warnings.empty() &&
            r.warnings[0].find("do not determine shear modulus, permittivity, mass separately") !=
              std::string::npos,
          "warning: " + (r.warnings.empty() ? std::string("(none)") : r.warnings[0]));
    check(std::isnan(r.standard_errors[0]), "no standard errors");
    check_close(r.rms, 0., 1e-9, "the data are still matched (rms, m)");
  }
  return finish();
}
