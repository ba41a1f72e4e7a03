// The paper's operating lines against this model (doc/validation.md,
// "Comparison with the paper"): two-ring layouts r_v/a = 1.3 .. 2.4 (step
// 0.05) with the inner ring held at 5 kV or 5.5 kV. Each layout is one row of
// a design map (compute_sweep_row, as `cdea sweep` computes it): both rings
// to the inner voltage, then the outer voltage continued in 50 V steps up to
// 9 kV (or a fold), with the lines located to 1e-6 V:
//   blue line: s2 at the two rings' inner edges equal;
//   red line:  s2 = 0 at the inner edge of the outer ring (loss of tension).
// The stroke (displacement minus its value at 0 V under the weight) there is
// compared with the stroke with both rings at the inner voltage. FE (p = 4,
// 16 graded elements per ring) and shooting (tolerance 1e-12) each do this;
// their difference is printed. Then the paper's claims side by side, and the
// outer voltage at which the model's stroke increase equals the paper's
// value (bracketed root of complete runs on the outer voltage).
//
// Writes DIR/paper_lines.csv (default DIR: results/validation). With --smoke
// (ctest, label bench-smoke): r_v/a = 1.7 at 5 kV only, CSV into a temporary
// folder; it fails unless both lines are found, FE and shooting agree on
// them within 1e-3 V, and the red line is at 6485.3 V within 0.1 V.
//
//   build/benchmarks/bench_paper_lines [DIR] [--smoke]

#include <cdea/design/sweep.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/numerics/bracketed_root.h>
#include <cdea/shooting/shooting_model.h>

#include "bench_common.h"

#include <iomanip>
#include <memory>
#include <tuple>

using namespace cdea;
using namespace cdea_bench;

namespace
{
  /// FE mesh of the comparison: p = 4, 16 graded elements per ring.
  FeDiscretization fine_mesh()
  {
    FeDiscretization d;
    d.elements_per_ring = 16;
    return d;
  }

  SweepSettings row_settings(const double r_v, const double Vi)
  {
    SweepSettings s;
    s.ring_edge_values = {r_v};
    s.inner_voltage    = Vi;
    s.outer_from       = Vi;
    s.outer_to         = 9000.;
    s.outer_step       = 50.;
    for (double V = s.outer_from; V <= s.outer_to + 1e-9; V += s.outer_step)
      s.outer_voltages.push_back(V);
    s.line_tolerance = 1e-6;
    return s;
  }

  /// A row of both methods.
  struct Layout
  {
    double   Vi, r_v;
    SweepRow fe, sh;
    double   zero_fe, zero_sh; ///< displacement at 0 V under the weight (m)
  };

  Layout compute_layout(const double Vi, const double r_v)
  {
    const Scene            base  = paper_scene({1., 3.}, {{Vi * 1e-3}});
    const Scene            scene = sweep_scene(base, r_v, Vi);
    const SweepSettings    s     = row_settings(r_v, Vi);
    const SteppingSettings stepping;
    Layout                 l{Vi, r_v, {}, {}, 0., 0.};
    l.zero_fe = zero_voltage_displacement(base, fine_mesh(), NewtonSettings(), stepping);
    {
      shooting::ShootingOptions o;
      o.tolerance = 1e-12;
      const Scene             zero = paper_scene({1., 3.}, {{0.}});
      shooting::ShootingModel sm(zero, o), row_model(scene, o);
      l.zero_sh = run_stages(sm, zero).last.displacement;
      l.sh      = compute_sweep_row(row_model, scene, s, stepping, l.zero_sh);
    }
    MembraneModel fe(scene, fine_mesh(), NewtonSettings());
    l.fe = compute_sweep_row(fe, scene, s, stepping, l.zero_fe);
    for (const SweepRow *row : {&l.fe, &l.sh})
      require(row->base_reached, "r_v/a = " + std::to_string(r_v) +
                                   ": both rings did not reach the inner voltage");
    return l;
  }

  double pct(const double stroke, const double stroke_base)
  {
    return 100. * (stroke / stroke_base - 1.);
  }

  /// Largest stroke increase along a line over r_v: parabola through the
  /// best layout and its neighbours.
  std::pair<double, double> best_on_line(const std::vector<Layout> &all, const double Vi,
                                         const bool red, const bool fe)
  {
    std::vector<std::pair<double, double>> v;
    for (const Layout &l : all)
      if (l.Vi == Vi)
        {
          const SweepLine &line = red ? (fe ? l.fe : l.sh).red : (fe ? l.fe : l.sh).blue;
          if (std::isfinite(line.stroke_increase))
            v.push_back({l.r_v, line.stroke_increase});
        }
    require(!v.empty(), "no layout has the line");
    std::size_t k = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (v[i].second > v[k].second)
        k = i;
    if (k == 0 || k + 1 == v.size())
      return v[k];
    const double h = v[k + 1].first - v[k].first;
    const double a = v[k - 1].second, b = v[k].second, c = v[k + 1].second;
    const double d = 0.5 * (a - c) / (a - 2 * b + c);
    return {v[k].first + d * h, b - 0.25 * (a - c) * d};
  }

  /// The outer voltage at which the FE stroke increase of layout @p l equals
  /// @p target percent: a bracketed root on the outer voltage between two
  /// grid points of the row, every evaluation a complete run (both rings to
  /// Vi, then the outer one to Vo). Prints it with s2/mu at both edges there.
  void where_increase(const Layout &l, const double target)
  {
    const SweepRow &row = l.fe;
    const Scene     base = paper_scene({1., 3.}, {{l.Vi * 1e-3}});
    const double    mu   = base.material.shear_modulus;
    const auto      s    = row_settings(l.r_v, l.Vi);
    std::size_t     k    = 0;
    while (k + 1 < s.outer_voltages.size() &&
           !(row.stroke_increase[k] <= target && row.stroke_increase[k + 1] > target))
      ++k;
    require(k + 1 < s.outer_voltages.size(), "the row never reaches the paper's increase");
    StepSummary at;
    const auto  increase = [&](const double Vo) {
      Scene scene = sweep_scene(base, l.r_v, l.Vi);
      scene.path  = VoltagePath({{l.Vi, l.Vi}, {l.Vi, Vo}});
      MembraneModel fe(scene, fine_mesh(), NewtonSettings());
      const Run     run = run_stages(fe, scene);
      if (!run.result.completed)
        return std::nan("");
      at = run.last;
      return pct(at.displacement - l.zero_fe, row.base_displacement - l.zero_fe) - target;
    };
    BracketedRootSettings settings;
    settings.x_tolerance = 1e-6;
    const BracketedRoot root =
      find_bracketed_root(increase, s.outer_voltages[k], row.stroke_increase[k] - target,
                          s.outer_voltages[k + 1], row.stroke_increase[k + 1] - target, settings);
    increase(root.x);
    std::cout << std::setprecision(2) << "  inner " << l.Vi * 1e-3 << " kV, r_v/a = " << l.r_v
              << ": +" << target << " % at outer " << std::setprecision(4) << root.x * 1e-3
              << " kV, s2/mu there " << at.s2_ring_inner[0] / mu << " (disk edge), "
              << at.s2_ring_inner[1] / mu << " (outer ring's inner edge); red line at "
              << row.red.outer_voltage * 1e-3 << " kV\n";
  }

  const Layout &find(const std::vector<Layout> &all, const double Vi, const double r_v)
  {
    for (const Layout &l : all)
      if (l.Vi == Vi && std::abs(l.r_v - r_v) < 1e-9)
        return l;
    throw std::runtime_error("no layout r_v/a = " + std::to_string(r_v));
  }

  /// The paper's claims, side by side (FE values; shooting in brackets).
  void compare_with_paper(const std::vector<Layout> &all)
  {
    const double mu = Scene().material.shear_modulus;
    std::cout << "\n=============== comparison with the paper (FE p=4, 16/ring; shooting in "
                 "brackets) ===============\n"
              << std::fixed;
    const Layout &b50 = find(all, 5000., 1.7), &b55 = find(all, 5500., 1.7);
    const double  stroke50 = b50.fe.base_displacement - b50.zero_fe;
    const double  stroke55 = b55.fe.base_displacement - b55.zero_fe;
    std::cout << std::setprecision(5) << "displacement at 0 V under the weight "
              << b50.zero_fe * 1e3 << " mm; stroke with both rings at 5 kV " << stroke50 * 1e3
              << " mm, at 5.5 kV " << stroke55 * 1e3 << " mm\n";
    const Layout &l18 = find(all, 5000., 1.8);
    std::cout << std::setprecision(2)
              << "red line, inner 5 kV, r_v/a = 1.8, other baselines: displacement +"
              << pct(l18.fe.red.displacement, l18.fe.base_displacement)
              << " % over both at 5 kV; stroke +"
              << pct(l18.fe.red.displacement - l18.zero_fe, stroke55)
              << " % over both at 5.5 kV\n";
    // The full electrode's onset (shooting, located to 1e-4 V on the path to 5.5 kV).
    SteppingSettings fine;
    fine.onset_tolerance = 1e-4;
    const Scene               full = paper_scene({1., 3.}, {{5.5}});
    shooting::ShootingOptions o;
    o.tolerance = 1e-12;
    shooting::ShootingModel sm(full, o);
    const Run               onset = run_stages(sm, full, fine);
    require(onset.result.onset.found, "the full electrode has no onset below 5.5 kV");
    std::cout << "full electrode: s2/mu at the disk edge " << std::setprecision(4)
              << b50.fe.base_s2_inner[0] / mu << " at 5.0 kV, " << b55.fe.base_s2_inner[0] / mu
              << " at 5.5 kV; onset (s2 = 0) at " << std::setprecision(2)
              << onset.result.onset.voltages[0] << " V (paper: wrinkles at 5.5 kV, not at "
              << "5.0 kV)\n";
    for (const auto &[Vi, red, r_v, paper] :
         std::vector<std::tuple<double, bool, double, double>>{
           {5000., false, 1.7, 32.9}, {5000., true, 1.8, 40.5}, {5500., true, 2.0, 20.3}})
      {
        const Layout    &l  = find(all, Vi, r_v);
        const SweepLine &fe = red ? l.fe.red : l.fe.blue, &sh = red ? l.sh.red : l.sh.blue;
        const auto bf = best_on_line(all, Vi, red, true), bs = best_on_line(all, Vi, red, false);
        std::cout << (red ? "red" : "blue") << " line, inner " << Vi * 1e-3
                  << " kV, r_v/a = " << r_v << ": outer " << std::setprecision(4)
                  << fe.outer_voltage * 1e-3 << " kV, stroke +" << std::setprecision(2)
                  << fe.stroke_increase << " % [" << sh.stroke_increase << " %], displacement +"
                  << pct(fe.displacement, l.fe.base_displacement) << " %; largest on the line: +"
                  << bf.second << " % [" << bs.second << " %] at r_v/a = " << bf.first << " ["
                  << bs.first << "]; paper +" << paper << " % at r_v/a = " << r_v << "\n";
      }
    const Layout &l14 = find(all, 5000., 1.4);
    std::cout << "experiment, r_v/a = 1.4, inner 5 kV, outer raised to wrinkling: model red "
                 "line outer "
              << std::setprecision(4) << l14.fe.red.outer_voltage * 1e-3 << " kV, stroke +"
              << std::setprecision(2) << l14.fe.red.stroke_increase << " %, displacement +"
              << pct(l14.fe.red.displacement, l14.fe.base_displacement)
              << " % (paper, measured: +58.2 %)\n";
    const double stroke_red17 = b50.fe.red.displacement - b50.zero_fe;
    std::cout << "experiment, r_v/a = 1.7, inner 5 kV at wrinkling vs both rings at 5.5 kV: "
                 "model stroke "
              << std::setprecision(4) << stroke_red17 * 1e3 << " mm vs " << stroke55 * 1e3
              << " mm: +" << std::setprecision(2) << pct(stroke_red17, stroke55)
              << " %, displacement +" << pct(b50.fe.red.displacement, b55.fe.base_displacement)
              << " % (paper, measured: +19.4 %)\n"
              << "experiment, r_v/a = 1.7, inner 5 kV: wrinkles seen at outer 6.3 kV (paper "
                 "figure 5); model red line at outer "
              << std::setprecision(4) << b50.fe.red.outer_voltage * 1e-3 << " kV\n";
    std::cout << "outer voltage at which the model's stroke increase equals the paper's value "
                 "(FE):\n";
    for (const auto &[Vi, r_v, paper] : std::vector<std::tuple<double, double, double>>{
           {5000., 1.7, 32.9}, {5000., 1.8, 40.5}, {5500., 2.0, 20.3}, {5000., 1.4, 58.2}})
      where_increase(find(all, Vi, r_v), paper);
    std::cout << std::defaultfloat;
  }

  int benchmark(const OutputFolder &dir, const bool smoke)
  {
    std::cout << "stroke = displacement - displacement at 0 V under the weight; increases are "
                 "relative to both rings at the inner voltage\n";
    std::ofstream csv(dir / "paper_lines.csv");
    csv << "method,Vi_kV,r_v,disp0_mm,disp_base_mm,blue_Vo_kV,blue_disp_mm,red_Vo_kV,"
           "red_disp_mm,last_Vo_kV,stop\n"
        << std::setprecision(10);
    std::vector<Layout> all;
    for (const double Vi : smoke ? std::vector<double>{5000.} : std::vector<double>{5000., 5500.})
      {
        std::cout << "\ninner " << Vi * 1e-3 << " kV\n"
                  << "  r_v/a | blue: Vo (kV)  stroke +%  disp +% | red: Vo (kV)  stroke +%  "
                     "disp +% | FE - shooting: blue Vo, red Vo (V), red stroke (pts)\n";
        for (int i = smoke ? 8 : 0; i <= (smoke ? 8 : 22); ++i)
          {
            const Layout &l = all.emplace_back(compute_layout(Vi, 1.3 + 0.05 * i));
            for (const SweepRow *row : {&l.fe, &l.sh})
              csv << (row == &l.fe ? "fe" : "shooting") << ',' << Vi * 1e-3 << ',' << l.r_v
                  << ',' << (row == &l.fe ? l.zero_fe : l.zero_sh) * 1e3 << ','
                  << row->base_displacement * 1e3 << ',' << row->blue.outer_voltage * 1e-3
                  << ',' << row->blue.displacement * 1e3 << ','
                  << row->red.outer_voltage * 1e-3 << ',' << row->red.displacement * 1e3 << ','
                  << row->highest_voltage * 1e-3 << ",\"" << row->message << "\"\n";
            std::cout << std::fixed << std::setprecision(2) << std::setw(7) << l.r_v << " | "
                      << std::setprecision(4) << std::setw(12) << l.fe.blue.outer_voltage * 1e-3
                      << std::setprecision(2) << std::setw(10) << l.fe.blue.stroke_increase
                      << std::setw(8) << pct(l.fe.blue.displacement, l.fe.base_displacement)
                      << " | " << std::setprecision(4) << std::setw(11)
                      << l.fe.red.outer_voltage * 1e-3 << std::setprecision(2) << std::setw(10)
                      << l.fe.red.stroke_increase << std::setw(8)
                      << pct(l.fe.red.displacement, l.fe.base_displacement) << " | "
                      << std::scientific << std::setprecision(1) << std::setw(8)
                      << l.fe.blue.outer_voltage - l.sh.blue.outer_voltage << std::setw(9)
                      << l.fe.red.outer_voltage - l.sh.red.outer_voltage << std::setw(9)
                      << l.fe.red.stroke_increase - l.sh.red.stroke_increase
                      << std::defaultfloat << std::setprecision(7);
            if (!l.fe.message.empty())
              std::cout << "  fold above " << l.fe.highest_voltage * 1e-3 << " kV";
            std::cout << "\n";
          }
      }
    require(bool(csv), "could not write " + (dir / "paper_lines.csv").string());
    if (smoke)
      {
        const Layout &l = all.front();
        for (const SweepLine *line : {&l.fe.red, &l.fe.blue, &l.sh.red, &l.sh.blue})
          require_finite(line->outer_voltage, "a line voltage of r_v/a = 1.7");
        require(std::abs(l.fe.red.outer_voltage - l.sh.red.outer_voltage) < 1e-3 &&
                  std::abs(l.fe.blue.outer_voltage - l.sh.blue.outer_voltage) < 1e-3,
                "FE and shooting disagree on the lines by more than 1e-3 V");
        require(std::abs(l.fe.red.outer_voltage - 6485.3) < 0.1,
                "the red line of r_v/a = 1.7 is at " + std::to_string(l.fe.red.outer_voltage) +
                  " V, not 6485.3 V");
      }
    else
      compare_with_paper(all);
    std::cout << "\nwrote " << (dir / "paper_lines.csv").string() << "\n";
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  return study_main(argc, argv, "bench_paper_lines", benchmark);
}
