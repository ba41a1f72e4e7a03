// Material-test data and fits (design/material_test_data.h,
// design/material_fit.h):
//
// 1. The reader: each kind from its header, raw machine columns through the
//    specimen, weights; the refusals with file, line and column; the
//    specimen's entries.
// 2. A linear problem: the Mooney-Rivlin film's nominal stress is linear in
//    (mu, C2) in every test, s = mu g1(L) + C2 g2(L) (uniaxial: g1 = L - L^-2,
//    g2 = 2 (1 - L^-3); equibiaxial: g1 = L - L^-5, g2 = 2 (L^3 - L^-3)). The
//    weighted least squares of noisy data is then exact, p = (A^T W A)^-1
//    A^T W y, with the covariance s^2 (A^T W A)^-1, s^2 = r^T W r / (M - K):
//    the fit's values and covariance against those, and a joint fit of two
//    files against its single-file fits, p = (N1 + N2)^-1 (N1 p1 + N2 p2)
//    with N = A^T W A.
// 3. The model's message for a history beyond the law's range.
// 4. A three-branch Gent film from exact uniaxial histories, fitted from the
//    data-driven starts: the constants recovered; from 20 noisy realisations:
//    the share of constants within 2 standard errors and the mean of
//    z^2 = ((fitted - true) / standard error)^2, which Gaussian errors put at
//    95.4 % and 1.

#include <cdea/base/parameter_declarations.h>
#include <cdea/base/text.h>
#include <cdea/design/material_fit.h>
#include <cdea/material/two_network_gent.h>
#include <cdea/model/scene.h>

#include "check.h"

#include <Eigen/Dense>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <tuple>

using namespace cdea;
using cdea_test::check;
using cdea_test::check_close;

namespace
{
  /// InputError's message of reading @p text as a test ("" if none).
  std::string refusal(const std::string &text, const TestSpecimen &specimen = {})
  {
    std::istringstream in(text);
    try
      {
        read_material_test(in, "t.csv", specimen);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  void expect_refusal(const std::string &text, const std::string &message,
                      const TestSpecimen &specimen = {})
  {
    const std::string got = refusal(text, specimen);
    check(got.find(message) != std::string::npos, "refused: '" + got + "' holds '" + message + "'");
  }

  void reader()
  {
    std::istringstream uni("# a uniaxial test\ntime_s, uniaxial_stretch, nominal_stress_kPa, weight\n"
                           "0, 1, 0, 1\n1, 1.5, 20.5, 2\n\n2, 2, 31, 1 # peak\n");
    check(is_material_test(uni), "a uniaxial header is a material test");
    uni.clear();
    uni.seekg(0);
    const MaterialTestData u = read_material_test(uni, "u.csv");
    check(u.history.kind == TestKind::uniaxial && u.size() == 3 && u.stress[1] == 20500. &&
            u.weight[1] == 2. && u.lines[2] == 6 && u.history.stretch[2] == 2.,
          "uniaxial: kind, stresses in Pa, weights, lines");
    std::istringstream equi("pure_shear_stretch,time_s,nominal_stress_kPa\n1,0,0\n1.2,0.5,7\n");
    const MaterialTestData e = read_material_test(equi, "p.csv");
    check(e.history.kind == TestKind::pure_shear && e.history.time[1] == 0.5 && e.weight[0] == 1.,
          "pure shear in any column order, weight 1 without the column");
    TestSpecimen specimen{TestKind::equibiaxial, 20e-3, 10e-3, 1e-3};
    std::istringstream raw("time_s, displacement_mm, force_N\n0, 0, 0\n1, 5, 2.5\n");
    const MaterialTestData r = read_material_test(raw, "r.csv", specimen);
    check(r.raw && r.history.kind == TestKind::equibiaxial &&
            std::abs(r.history.stretch[1] - 1.25) < 1e-15 && std::abs(r.stress[1] - 2.5e5) < 1e-9,
          "raw columns: stretch 1 + 5/20, stress 2.5 N / (10 mm x 1 mm)");
    std::istringstream creep("time_s, V1_kV, displacement_mm\n0, 0, 0\n");
    check(!is_material_test(creep), "a creep curve is not a material test");

    const std::string head = "time_s, uniaxial_stretch, nominal_stress_kPa\n";
    expect_refusal(head + "0, 1, 0\n1, 0.98, 1\n",
                   "t.csv, line 3, column uniaxial_stretch: a tension test's stretch must be at "
                   "least 1 (the unstressed state), got 0.98");
    expect_refusal(head + "0, 1, 0\n1, 1.1, 1\n1, 1.2, 2\n",
                   "t.csv, line 4, column time_s: times must be >= 0 and increase strictly, got 1");
    expect_refusal(head + "0, 1, 0\n1, 1.1, abc\n", "t.csv, line 3, column nominal_stress_kPa: 'abc'");
    expect_refusal(head + "0, 1, 0\n1, nan, 1\n", "t.csv, line 3, column uniaxial_stretch");
    expect_refusal("", "t.csv: no header line");
    expect_refusal(head, "t.csv: no data rows after the header");
    expect_refusal("time_s, uniaxial_stretch, nominal_stress_kPa, force_N\n0, 1, 0, 0\n",
                   "t.csv, line 1, column force_N: a column of time_s, displacement_mm, force_N "
                   "(a machine's raw columns) mixed with the columns of time_s, uniaxial_stretch, "
                   "nominal_stress_kPa (a uniaxial test)");
    expect_refusal("time_s, uniaxial_stretch, equibiaxial_stretch, nominal_stress_kPa\n0,1,1,0\n",
                   "t.csv, line 1, column equibiaxial_stretch: a second test's stretch column");
    expect_refusal("time_s, displacement_mm, force_N, nominal_stress_kPa\n0, 0, 0, 0\n",
                   "t.csv, line 1, column nominal_stress_kPa: a column of the stretch tests");
    expect_refusal("time_s, uniaxial_stretch\n0, 1\n", "t.csv, line 1: no column nominal_stress_kPa");
    expect_refusal("time_s, strain\n0, 1\n", "t.csv, line 1: unknown column 'strain'");
    expect_refusal("time_s, displacement_mm, force_N\n0, 0, 0\n",
                   "t.csv: raw machine columns (time_s, displacement_mm, force_N) need the specimen");
    expect_refusal("time_s, displacement_mm, force_N\n0, -0.1, 0\n",
                   "t.csv, line 2, column displacement_mm: a tension test's displacement must be "
                   "at least 0", specimen);
    expect_refusal(head + "0, 1, 0, 4\n", "t.csv, line 2: 4 fields, but the header has 3");
  }

  /// The specimen's entries, declared and parsed as a plugin's.
  void specimen_entries()
  {
    ParameterDeclarations prm;
    declare_specimen_parameters(prm);
    check(prm.entries().size() == 4 && prm.entries()[1].path() == "Calibration/Specimen gauge length (mm)",
          "four specimen entries of subsection Calibration");
    ParameterValues v;
    v.set_text("Calibration/Specimen test", "pure shear");
    v.set_number("Calibration/Specimen gauge length (mm)", 10.);
    v.set_number("Calibration/Specimen width (mm)", 100.);
    v.set_number("Calibration/Specimen thickness (mm)", 0.5);
    const TestSpecimen s = parse_specimen(v);
    check(s.kind == TestKind::pure_shear && s.gauge_length == 0.01 && s.width == 0.1 &&
            s.thickness == 0.5e-3, "the specimen in SI units");
    for (const auto &[entry, value, message] :
         std::vector<std::tuple<std::string, std::string, std::string>>{
           {"Calibration/Specimen test", "biaxial", "Calibration/Specimen test must be uniaxial, "
                                                    "equibiaxial or pure shear, got 'biaxial'"},
           {"Calibration/Specimen width (mm)", "-1",
            "Calibration/Specimen width (mm) must be from 0 (not given) to 1e4 mm, got -1"}})
      {
        ParameterValues bad = v;
        if (entry == "Calibration/Specimen test")
          bad.set_text(entry, value);
        else
          bad.set_number(entry, std::stod(value));
        std::string got;
        try
          {
            parse_specimen(bad);
          }
        catch (const InputError &e)
          {
            got = e.what();
          }
        check(got.find(message) == 0, "specimen refused: " + got);
      }
  }
} // namespace

namespace
{
  /// Gaussian numbers from a seeded generator (Box-Muller: the same on every
  /// standard library).
  struct Noise
  {
    std::mt19937_64 engine;
    explicit Noise(const unsigned int seed) : engine(seed) {}
    double operator()()
    {
      const double u1 = (double(engine() >> 11) + 0.5) / 9007199254740992.,
                   u2 = double(engine() >> 11) / 9007199254740992.;
      return std::sqrt(-2. * std::log(u1)) * std::cos(2. * M_PI * u2);
    }
  };

  /// @p scene's model along @p history plus noise of @p sigma (Pa), as a test.
  MaterialTestData synthetic(const Scene &scene, const StretchHistory &history, const double sigma,
                             Noise &noise, const std::string &name)
  {
    const auto          law = scene.law();
    MaterialPoint       point(*law);
    MaterialPointResult r;
    std::string         message;
    check(point.run(history, {}, r, message), name + ": the truth runs " + message);
    MaterialTestData d;
    d.name    = name;
    d.history = history;
    for (std::size_t k = 0; k < history.time.size(); ++k)
      {
        d.stress.push_back(r.stress[k] + sigma * noise());
        d.weight.push_back(1.);
        d.lines.push_back(unsigned(k + 2));
      }
    return d;
  }

  StretchHistory sweep(const TestKind kind, const double top, const unsigned int n)
  {
    StretchHistory h;
    h.kind = kind;
    for (unsigned int k = 0; k <= n; ++k)
      {
        h.time.push_back(k);
        h.stretch.push_back(1. + (top - 1.) * k / n);
      }
    return h;
  }

  /// Rows [g1, g2] of the Mooney-Rivlin stress (Pa per Pa of mu, per kPa of C2).
  Eigen::MatrixXd design_rows(const MaterialTestData &t)
  {
    Eigen::MatrixXd A(Eigen::Index(t.size()), 2);
    for (std::size_t k = 0; k < t.size(); ++k)
      {
        const double L = t.history.stretch[k];
        const bool   u = t.history.kind == TestKind::uniaxial;
        A(Eigen::Index(k), 0) = u ? L - 1. / (L * L) : L - std::pow(L, -5);
        A(Eigen::Index(k), 1) = 2e3 * (u ? 1. - std::pow(L, -3) : std::pow(L, 3) - std::pow(L, -3));
      }
    return A;
  }

  struct Linear
  {
    Eigen::Vector2d p;
    Eigen::Matrix2d N, covariance;
  };

  /// The exact weighted least squares of the tests (test weights @p w).
  Linear exact(const std::vector<MaterialTestData> &tests, const std::vector<double> &w)
  {
    Linear          l;
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    l.N.setZero();
    std::size_t M = 0;
    for (std::size_t f = 0; f < tests.size(); ++f)
      {
        const Eigen::MatrixXd A = design_rows(tests[f]);
        for (Eigen::Index k = 0; k < A.rows(); ++k)
          {
            const double weight = w[f] * tests[f].weight[std::size_t(k)];
            l.N += weight * A.row(k).transpose() * A.row(k);
            b += weight * A.row(k).transpose() * tests[f].stress[std::size_t(k)];
          }
        M += tests[f].size();
      }
    l.p = l.N.ldlt().solve(b);
    double rss = 0.;
    for (std::size_t f = 0; f < tests.size(); ++f)
      {
        const Eigen::VectorXd r =
          Eigen::Map<const Eigen::VectorXd>(tests[f].stress.data(), Eigen::Index(tests[f].size())) -
          design_rows(tests[f]) * l.p;
        for (Eigen::Index k = 0; k < r.size(); ++k)
          rss += w[f] * tests[f].weight[std::size_t(k)] * r[k] * r[k];
      }
    l.covariance = rss / double(M - 2) * l.N.inverse();
    return l;
  }

  MaterialFitResult fit(const Scene &base, const std::vector<MaterialTestData> &tests,
                        const std::vector<SceneParameter> &free, const std::vector<double> &w,
                        const unsigned int starts, const double tolerance = 1e-10)
  {
    MaterialFitSettings s;
    s.fit.free         = free;
    s.fit.tolerance    = tolerance;
    s.test_weights     = w;
    s.starts           = starts;
    return fit_material_tests(base, tests, s);
  }

  void linear_problem()
  {
    Scene base          = paper_scene({1., 3.}, {{0.}});
    base.material_model = "mooney-rivlin";
    base.law_constants  = {{"Mooney-Rivlin C2 (kPa)", 3.}};
    base.material.shear_modulus = 20e3;
    Noise noise(7);
    std::vector<MaterialTestData> tests{
      synthetic(base, sweep(TestKind::uniaxial, 3., 30), 300., noise, "uniaxial.csv"),
      synthetic(base, sweep(TestKind::equibiaxial, 2.2, 24), 300., noise, "equibiaxial.csv")};
    for (std::size_t k = 0; k < tests[0].size(); ++k)
      tests[0].weight[k] = 1. + double(k % 3);
    const std::vector<SceneParameter> free{{ParameterKind::shear_modulus},
                                           {ParameterKind::law_constant, 0, "Mooney-Rivlin C2 (kPa)"}};
    const std::vector<double> w{1., 2.5};
    const Linear              truth = exact(tests, w);
    const MaterialFitResult   r     = fit(base, tests, free, w, 1, 1e-14);
    check(r.fit.converged, "linear problem: converged (" + r.fit.status + ")");
    double value = 0., covariance = 0.;
    for (int i = 0; i < 2; ++i)
      {
        value = std::max(value, std::abs(r.fit.values[std::size_t(i)] - truth.p[i]) / std::abs(truth.p[i]));
        for (int j = 0; j < 2; ++j)
          covariance = std::max(covariance, std::abs(r.fit.covariance(i, j) - truth.covariance(i, j)) /
                                              std::sqrt(truth.covariance(i, i) * truth.covariance(j, j)));
      }
    std::cout << "  linear fit: mu = " << r.fit.values[0] << " +- " << r.fit.standard_errors[0]
              << " Pa, C2 = " << r.fit.values[1] << " +- " << r.fit.standard_errors[1] << " kPa\n";
    check_close(value, 0., 1e-9, "linear problem: values against the exact least squares (rel.)");
    check_close(covariance, 0., 1e-7, "linear problem: covariance against s^2 (A^T W A)^-1 "
                                      "(over the standard errors' product)");

    // Joint against the single-file fits.
    Eigen::Vector2d p[2];
    for (int f = 0; f < 2; ++f)
      {
        const MaterialFitResult single = fit(base, {tests[std::size_t(f)]}, free, {1.}, 1, 1e-14);
        p[f] = Eigen::Vector2d(single.fit.values[0], single.fit.values[1]);
      }
    const Eigen::Matrix2d N1 = exact({tests[0]}, {1.}).N, N2 = exact({tests[1]}, {1.}).N;
    const Eigen::Vector2d joint =
      (w[0] * N1 + w[1] * N2).ldlt().solve(w[0] * N1 * p[0] + w[1] * N2 * p[1]);
    check_close(std::max(std::abs(r.fit.values[0] / joint[0] - 1.), std::abs(r.fit.values[1] / joint[1] - 1.)),
                0., 1e-8, "joint fit against its single-file fits (N1 + N2)^-1 (N1 p1 + N2 p2)");

    // The measures per test, by hand.
    double sum = 0., sum_w = 0., largest = 0.;
    for (std::size_t k = 0; k < tests[0].size(); ++k)
      {
        const double res = r.fit.fitted[Eigen::Index(k)] - tests[0].stress[k];
        sum += tests[0].weight[k] * res * res;
        sum_w += tests[0].weight[k];
        largest = std::max(largest, std::abs(tests[0].stress[k]));
      }
    check(r.tests.size() == 2 && std::abs(r.tests[0].rms - std::sqrt(sum / sum_w)) < 1e-9 * r.tests[0].rms &&
            std::abs(r.tests[0].relative - r.tests[0].rms / largest) < 1e-15,
          "rms of the first test: absolute and relative to its largest stress");
  }
} // namespace

namespace
{
  /// The viscoelastic film: network A 25 kPa (Jlim 100) and branches 30,
  /// 15, 8 kPa at 1, 10, 100 s.
  Scene three_branch_film()
  {
    Scene s                  = paper_scene({1., 3.}, {{0.}});
    s.material.shear_modulus = 25e3;
    s.material.jlim          = 100.;
    return spectrum_scene(s, {30., 15., 8.}, {1., 10., 100.}, 100.);
  }

  /// Uniaxial: a ramp at @p rate to @p top held to @p end (or, with @p back,
  /// unloaded at the same rate), sampled every @p dt.
  StretchHistory uniaxial(const double rate, const double top, const double end, const double dt,
                          const bool back)
  {
    StretchHistory h;
    const double   t_top = (top - 1.) / rate;
    for (double t = 0.; t <= end + 1e-9; t += dt)
      {
        h.time.push_back(t);
        h.stretch.push_back(t <= t_top ? 1. + rate * t :
                            back       ? std::max(1., top - rate * (t - t_top)) :
                                         top);
      }
    return h;
  }

  std::vector<MaterialTestData> film_tests(const Scene &truth, const double sigma,
                                           const unsigned int seed)
  {
    Noise noise(seed);
    return {synthetic(truth, uniaxial(0.05, 2.5, 300., 2., false), sigma, noise, "relax.csv"),
            synthetic(truth, uniaxial(0.01, 2.5, 300., 2., true), sigma, noise, "cycle.csv"),
            synthetic(truth, uniaxial(0.25, 2., 60., 0.5, false), sigma, noise, "fast.csv")};
  }

  std::vector<SceneParameter> spectrum_parameters()
  {
    std::vector<SceneParameter> free{{ParameterKind::shear_modulus}};
    for (unsigned int k = 1; k <= 3; ++k)
      free.push_back({ParameterKind::law_constant, 0, branch_constant_entry(k, false)});
    for (unsigned int k = 1; k <= 3; ++k)
      free.push_back({ParameterKind::law_constant, 0, branch_constant_entry(k, true)});
    return free;
  }

  void model_refusal()
  {
    Scene film     = three_branch_film();
    film.material.jlim = 10.;
    MaterialTestData t;
    t.name    = "far.csv";
    t.history = uniaxial(0.1, 4., 40., 1., false);
    t.stress.assign(t.history.time.size(), 0.);
    t.weight.assign(t.history.time.size(), 1.);
    for (std::size_t k = 0; k < t.size(); ++k)
      t.lines.push_back(unsigned(k + 2));
    const MaterialTestModel model(film, {t}, spectrum_parameters());
    Eigen::VectorXd         s;
    std::string             message;
    const bool failed = !model.evaluate({25e3, 30e3, 15e3, 8e3, 1., 10., 100.}, s, nullptr, &message);
    check(failed && message.find("far.csv, line 28: the model cannot follow the test there: sample 27 "
                                 "(t = 26 s, stretch 3.6)") == 0,
          "a stretch beyond the Gent limit: " + message);
  }

  void recovery()
  {
    const Scene                       truth = three_branch_film();
    const std::vector<SceneParameter> free  = spectrum_parameters();
    std::vector<double>               exact_values;
    for (const SceneParameter &p : free)
      exact_values.push_back(parameter_value(truth, p));
    const auto tests = film_tests(truth, 0., 1);
    std::size_t samples = 0;
    for (const auto &t : tests)
      samples += t.size();
    const MaterialFitResult r = fit(truth, tests, free, {}, 3);
    double                  worst = 0.;
    for (std::size_t j = 0; j < free.size(); ++j)
      worst = std::max(worst, std::abs(r.fit.values[j] / exact_values[j] - 1.));
    std::cout << "  exact data (" << samples << " samples): start " << r.best << " of "
              << r.starts.size() << ", " << r.evaluations << " evaluations; starts:";
    for (const auto &s : r.starts)
      std::cout << " [" << s[0] * 1e-3 << " kPa, " << s[1] * 1e-3 << ", " << s[2] * 1e-3 << ", "
                << s[3] * 1e-3 << " kPa; " << s[4] << ", " << s[5] << ", " << s[6] << " s]";
    std::cout << '\n';
    std::cout << "  costs of the starts:";
    for (const double c : r.costs)
      std::cout << ' ' << c;
    std::cout << "\n  fitted:";
    for (const double v : r.fit.values)
      std::cout << ' ' << v;
    std::cout << '\n';
    check(r.fit.converged, "exact data: converged (" + r.fit.status + ")");
    check_close(worst, 0., 1e-6, "exact data: the seven constants recovered (rel.)");
  }

  /// 20 realisations of 0.2 kPa noise on the three histories, each fitted
  /// from its data-driven start: z = (fitted - true) / standard error of
  /// every constant. Gaussian errors put 95.4 % of the z within 2 and give
  /// mean z^2 = 1; both are checked, so that standard errors neither under-
  /// nor overstated pass.
  void noisy_recovery()
  {
    const Scene                       truth = three_branch_film();
    const std::vector<SceneParameter> free  = spectrum_parameters();
    unsigned int inside = 0, all_inside = 0, total = 0, converged = 0;
    double       z2 = 0., worst = 0.;
    for (unsigned int seed = 1; seed <= 20; ++seed)
      {
        const MaterialFitResult r = fit(truth, film_tests(truth, 200., seed), free, {}, 3);
        converged += r.fit.converged;
        bool all = true;
        for (std::size_t j = 0; j < free.size(); ++j)
          {
            const double z = (r.fit.values[j] - parameter_value(truth, free[j])) /
                             r.fit.standard_errors[j];
            inside += std::abs(z) <= 2.;
            all = all && std::abs(z) <= 2.;
            z2 += z * z;
            worst = std::max(worst, std::abs(z));
            ++total;
          }
        all_inside += all;
        if (!all)
          {
            std::cout << "  seed " << seed << ": cost " << r.costs[0] << ", values";
            for (std::size_t j = 0; j < free.size(); ++j)
              std::cout << ' ' << r.fit.values[j] << " +- " << r.fit.standard_errors[j];
            std::cout << '\n';
          }
      }
    std::cout << "  20 noisy realisations: " << all_inside << " with every constant within 2 s.e., "
              << inside << " of " << total << " constants within 2 s.e., mean z^2 " << z2 / total
              << ", largest |z| " << worst << '\n';
    check(converged == 20, "every noisy fit converged");
    check(inside >= 0.9 * total, "at least 90 % of the constants within 2 standard errors");
    check(z2 / total > 0.6 && z2 / total < 1.5, "mean z^2 near 1 (0.6 to 1.5)");
  }
} // namespace

CDEA_TEST_MAIN()
{
  reader();
  specimen_entries();
  linear_problem();
  model_refusal();
  recovery();
  noisy_recovery();
  return cdea_test::finish();
}
