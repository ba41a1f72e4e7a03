// The products of the studies against the table of quantities
// (doc/architecture.md, "One table of quantities, one product per study"):
// every product of every command that writes a file (chart, sweep, optimize,
// fit of each kind of data, response, frequency sweep), built from small
// inputs (the material charts computed, the other studies' results made up,
// NaN and empty values included, so that the test takes no solves), written
// by the one writer and read back (tests/product_file_check.h): every group,
// attribute and dataset of the file is a value of its product with a row of
// the table (name, unit, description), values the row's conversion of the
// SI values bit for bit, nothing else in the file. And the table printer
// prints the file's numbers. The run's file and its journal:
// tests/test_run_products.cc.

#include <cdea/analysis/frequency_response.h>
#include <cdea/analysis/frequency_sweep.h>
#include <cdea/base/format.h>
#include <cdea/design/fit.h>
#include <cdea/design/optimize.h>
#include <cdea/design/sweep.h>
#include <cdea/design/viscous_fit.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/material/material_chart.h>
#include <cdea/model/chart_product.h>
#include <cdea/model/quantities_chart.h>
#include <cdea/model/quantities_sweep.h>
#include <cdea/output/product_file.h>
#include <cdea/output/product_table.h>

#include "check.h"
#include "product_file_check.h"

#include <iomanip>
#include <limits>
#include <sstream>

using namespace cdea;
using namespace cdea_test;

namespace
{
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  /// Writes @p product and checks the file against it.
  void check_written(const Product &product, const std::string &name)
  {
    const std::string path = "test_products_" + name + ".h5";
    write_product_file(product, path);
    check_product_file(product, path, name);
  }

  Parameters parameters(const std::string &text)
  {
    return read_parameters(ParameterInput::text(text));
  }

  void check_charts()
  {
    ChartSettings settings;
    settings.stretch_points   = 11;
    settings.frequency_points = 7;
    const Parameters elastic  = parameters("");
    check_written(chart_product(*elastic.scene().law(), settings, "text", "elastic"),
                  "chart_elastic");
    const Parameters viscous = parameters(
      "subsection Material\n  set Model = viscoelastic\n  set Network B shear modulus (kPa) = "
      "45\n  set Relaxation time (s) = 2\nend\nsubsection Time\n  set Enabled = true\nend\n");
    const Product chart = chart_product(*viscous.scene().law(), settings, "text", "viscoelastic");
    check_written(chart, "chart_viscoelastic");
    check(chart.find("/dma") != nullptr, "chart: a law with internal variables has /dma");
  }

  SweepMap made_up_map()
  {
    SweepMap map;
    map.settings.ring_edge_values = {1.5, 2.};
    map.settings.outer_voltages   = {5e3, 5.5e3, 6e3};
    map.zero_voltage_displacement = 0.0182;
    for (std::size_t i = 0; i < 2; ++i)
      {
        SweepRow r;
        r.rv_over_a         = map.settings.ring_edge_values[i];
        r.base_reached      = true;
        r.base_displacement = 0.0237 + 1e-4 * i;
        r.base_s2_inner[0]  = 14e3;
        r.base_s2_inner[1]  = 1.3e3 * i;
        r.lowest_voltage    = 5e3;
        r.highest_voltage   = i ? 5.5e3 : 6e3;
        r.message           = i ? "a fold of the voltage path at 5.73 kV" : "";
        r.displacement      = {0.0237, 0.0251, i ? nan : 0.0266};
        r.stroke            = {0.0055, 0.0069, i ? nan : 0.0084};
        r.stroke_increase   = {0., 25.4, i ? nan : 52.7};
        r.s2_inner_ring1    = {14e3, 15e3, i ? nan : 16e3};
        r.s2_inner_ring2    = {1e3, 0.2e3, i ? nan : -0.7e3};
        r.red.outer_voltage = i ? nan : 5.63e3;
        r.red.displacement  = i ? nan : 0.0255;
        r.blue.outer_voltage = 5.21e3;
        r.solves            = 40 + unsigned(i);
        r.newton_iterations = 120;
        map.rows.push_back(r);
      }
    return map;
  }

  /// The sweep's product, and its table as `cdea sweep` prints it: the
  /// printed cells are the file's numbers.
  void check_sweep()
  {
    const Product map = sweep_product(made_up_map(), "text");
    check_written(map, "sweep");
    std::ostringstream table;
    using namespace sweep_quantity;
    print_table(table, map.root(),
                {{&base_displacement, "base (mm)", 11, CellStyle::fixed_or_dash, 4},
                 {&red_outer, "red kV", 10, CellStyle::fixed_or_dash, 4},
                 {&stop_message, "stop", 0, CellStyle::text, 60, "  "}},
                {0, 1});
    const hid_t file = H5Fopen("test_products_sweep.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
    const Read  base = read_dataset(file, "/base_displacement_mm");
    const Read  red  = read_dataset(file, "/red_line_outer_kV");
    const Read  stop = read_dataset(file, "/stop_message");
    H5Fclose(file);
    std::ostringstream expected;
    expected << std::setw(11) << "base (mm)" << std::setw(10) << "red kV" << "  stop\n";
    for (std::size_t i = 0; i < 2; ++i)
      expected << std::setw(11) << format_fixed_or_dash(base.values[i], 4) << std::setw(10)
               << format_fixed_or_dash(red.values[i], 4) << "  "
               << (stop.texts[i].empty() ? "-" : stop.texts[i]) << '\n';
    check(table.str() == expected.str(), "sweep: the table printer prints the file's numbers");
  }

  StartResult made_up_start(const unsigned int k)
  {
    StartResult r;
    r.start       = k;
    r.initial     = {{1., 1.6, 3.}, {4e3, 4e3}};
    r.best        = {{1., 1.7 + 0.01 * k, 3.}, {5e3, 6.5e3}};
    r.converged   = k == 0;
    r.status      = k ? "stopped: maximum evaluations" : "converged";
    r.objective   = 8.77 - k;
    r.worst_constraint = -1e-3;
    r.optimality       = 1e-7;
    r.active           = {"s2 >= 0 kPa at the inner edge of ring 2"};
    r.evaluations      = 3;
    r.solves           = 9;
    LayoutEvaluation &e = r.at_best;
    e.ok                = true;
    e.displacement      = 0.0265;
    e.stroke            = 0.00877;
    e.volume_change     = 3.1e-5;
    e.min_eigenvalue    = 0.42;
    e.points.R                   = {0.0056, 0.0068, 0.0095};
    e.points.ring                = {0, 1, 1};
    e.points.n_quadrature_points = 2;
    e.points.s2                  = Eigen::Vector3d(12e3, 0.5e3, 0.);
    e.points.field               = Eigen::Vector3d(40e6, 55e6, 56e6);
    for (unsigned int j = 1; j <= 3; ++j)
      r.history.push_back({k, j, j == 2 ? nan : 8.7 + 0.01 * j, -1e-3, {5., 6.5, 1.7}, ""});
    return r;
  }

  void check_optimum()
  {
    OptimizationSettings settings;
    settings.voltages = {OptimizationSettings::free, OptimizationSettings::free};
    settings.edges    = {1., OptimizationSettings::free, 3.};
    OptimizationRun run;
    run.starts = {made_up_start(0), made_up_start(1)};
    const Scene base = parameters("").scene();
    check_written(optimum_product(run, settings, base, "text"), "optimum");
    settings.objective = DesignObjective::volume_change;
    run.starts[0].at_best.ok = false; // no points: no /optimum
    check_written(optimum_product(run, settings, base, "text"), "optimum_volume");
  }

  FitResult made_up_fit(const std::size_t observations)
  {
    FitResult r;
    r.initial         = {25e3, 270.};
    r.values          = {25.13e3, 273.7};
    r.standard_errors = {40., nan};
    r.correlation     = Eigen::Matrix2d{{1., -0.3}, {-0.3, 1.}};
    r.fitted          = Eigen::VectorXd::LinSpaced(Eigen::Index(observations), 0.02, 0.03);
    r.residuals       = Eigen::VectorXd::Constant(Eigen::Index(observations), 1e-6);
    r.rms             = 1.2e-6;
    r.condition       = 35.;
    r.converged       = true;
    r.status          = "converged";
    r.warnings        = {"Jlim: the data do not determine it"};
    r.iterations      = 7;
    r.evaluations     = 9;
    return r;
  }

  void check_fits()
  {
    FitSettings settings;
    settings.free = {SceneParameter(ParameterKind::shear_modulus),
                     SceneParameter(ParameterKind::jlim)};
    const CalibrationData points{{{4e3}, {5e3}, {6e3}}, {0.021, 0.0237, 0.0276}, {1., 1., 2.}};
    Calibrated c;
    c.result             = made_up_fit(3);
    c.curve_voltages     = {{0.}, {2.5e3}, {5e3}};
    c.curve_displacement = {0.0182, 0.0195, 0.0237};
    c.solves             = 31;
    check_written(fit_product("text", points, settings, c), "fit_points");
    c.result.fitted.resize(0); // a fit that could not start: no model values
    c.curve_voltages.clear();
    c.curve_displacement.clear();
    check_written(fit_product("text", points, settings, c), "fit_not_started");
    const DmaData dma{{0.1, 1.}, {80e3, 120e3}, {10e3, 30e3}, {1., 1.}};
    check_written(dma_fit_product("text", dma, settings, made_up_fit(4)), "fit_dma");
    const CreepData creep{{0., 1., 2.}, {{5e3}, {5e3}, {5e3}}, {0.02, 0.021, 0.0215}, {1., 1., 1.}};
    check_written(creep_fit_product("text", creep, settings, made_up_fit(3)), "fit_creep");
  }

  FrequencyResponse made_up_response(const Eigen::Index rings)
  {
    FrequencyResponse r;
    r.frequency       = {0.1, 1., 10.};
    r.bias            = std::vector<double>(std::size_t(rings), 5e3);
    r.displacement    = 0.0237;
    r.volume          = 1.4e-5;
    r.drive_scale     = 5e3;
    r.disk            = Eigen::MatrixXcd::Constant(3, rings, {1e-6, -2e-7});
    r.volume_per_volt = Eigen::MatrixXcd::Constant(3, rings, {3e-9, -1e-10});
    r.disk_drive      = Eigen::VectorXcd::Constant(3, {2e-6, -4e-7});
    r.volume_drive    = Eigen::VectorXcd::Constant(3, {6e-9, 2e-10});
    r.mode_frequency  = {12.3};
    r.mode_damping    = {0.02};
    r.sample_R        = {0.0056, 0.01, 0.0168};
    r.mode_r          = Eigen::MatrixXd::Constant(1, 3, 0.1);
    r.mode_z          = Eigen::MatrixXd::Constant(1, 3, 0.9);
    r.disk_mass       = 0.28;
    r.density         = 1000.;
    return r;
  }

  void check_dynamics()
  {
    check_written(response_product("text", made_up_response(2)), "response");
    check_written(response_product("text", made_up_response(1)), "response_one_ring");
    FrequencySweepResult r;
    for (const double f : {0.5, 2.})
      {
        SteadyPeriod s;
        s.frequency        = f;
        s.converged        = f < 1.;
        s.stroke_amplitude = 1e-3 / f;
        s.first_harmonic   = {1e-3, -2e-4};
        s.volume_swing     = 2e-6;
        s.dissipated       = 1e-4;
        s.electrical_work  = 1.1e-4;
        s.s2_min           = f < 1. ? 2e3 : -1e2;
        s.loss_of_tension  = f > 1.;
        s.newton_iterations = 4;
        s.period_maps       = 9;
        r.periods.push_back(s);
      }
    r.usable                 = {1, 0};
    r.quasi_static_amplitude = 2e-3;
    r.band_low = r.band_high = 0.5;
    r.usable_factor          = 1.5;
    check_written(frequency_sweep_product("text", r), "frequency_sweep");
  }
} // namespace

CDEA_TEST_MAIN()
{
  check_charts();
  check_sweep();
  check_optimum();
  check_fits();
  check_dynamics();
  return failures() ? 1 : 0;
}
