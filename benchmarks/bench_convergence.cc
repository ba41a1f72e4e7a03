// Convergence study of the FE model against the shooting solver
// (doc/validation.md, "Convergence").
//
// Two scenes: the full electrode at 5 kV, and r_v/a = 1.7 with both rings to
// 5 kV and then the outer ring to 6 kV (the public cases of model-notes.md).
// The reference is the shooting model at tolerance 1e-12; its own uncertainty
// is estimated against tolerance 1e-13 and printed.
//
//   h-refinement: p = 1..3 from 8 elements per ring (grading 4), p = 4 from
//                 2, bisected 0, 1, 2, ... times (8, 16, 32, ... elements
//                 per ring); p = 3 also on uniform meshes (grading 1);
//   p-refinement: p = 1..8 on 8 graded elements per ring, and on 2.
//
// Errors, all relative to the reference:
//   displacement |z(A) - z(B)|;
//   s2 at the inner edge of each ring (largest over the rings), as the FE
//   model reports it (from the element's derivatives at the edge);
//   s2 at the disk edge recovered from the reaction of the r(A) constraint
//   (see recovered_disk_edge_s2 below), to show what a flux recovery gains;
//   L2 norm of (r, z) - (r, z)_ref over [A, B], over the L2 norm of (r, z)_ref.
//
// Prints the tables with observed orders and writes DIR/convergence.csv
// (default DIR: results/validation). With --smoke (ctest, label bench-smoke):
// the r_v/a = 1.7 scene, p = 1 and 4 on three meshes each, CSV into a
// temporary folder; it fails unless the observed orders of p = 1 are those of
// the theory (displacement and L2 2, s2 1, each within 0.1).
//
//   build/benchmarks/bench_convergence [DIR] [--smoke]

#include <cdea/fe/membrane_model.h>
#include <cdea/shooting/meridian.h>
#include <cdea/shooting/shooting_model.h>

#include <deal.II/base/quadrature_lib.h>

#include "bench_common.h"

#include <iomanip>
#include <limits>
#include <sstream>
#include <tuple>

using namespace cdea;
using namespace cdea_bench;

namespace
{
  /// Run all stages; the last converged step (fails unless the run completes).
  StepSummary run_to_end(EquilibriumModel &model, const Scene &scene)
  {
    const Run run = run_stages(model, scene);
    require(run.result.completed, "run did not complete: " + run.result.message);
    return run.last;
  }

  /// The reference solution: summary and densely sampled profile.
  struct Reference
  {
    StepSummary summary;
    StepFields  fields;
  };

  Reference shooting_reference(const Scene &scene, const double tolerance)
  {
    shooting::ShootingOptions o;
    o.tolerance        = tolerance;
    o.samples_per_ring = 4001;
    shooting::ShootingModel model(scene, o);
    Reference               ref;
    ref.summary = run_to_end(model, scene);
    ref.fields  = model.fields();
    return ref;
  }

  /// (r, z) of the reference at reference radius R: cubic Hermite
  /// interpolation between the uniform samples of the ring that holds R, with
  /// the slopes r' = l1 cos(theta), z' = -l1 sin(theta) of the samples.
  void reference_profile(const StepFields &f, const unsigned int ring, const double R,
                         double &r, double &z)
  {
    std::size_t first = 0;
    while (first < f.R.size() && f.ring[first] != int(ring))
      ++first;
    std::size_t last = first;
    while (last + 1 < f.R.size() && f.ring[last + 1] == int(ring))
      ++last;
    const std::size_t m  = last - first + 1;
    const double      x0 = f.R[first], h = (f.R[last] - x0) / (m - 1);
    const std::size_t j  = std::min<std::size_t>(m - 2, std::size_t(std::max(0., (R - x0) / h)));
    const std::size_t i0 = first + j, i1 = i0 + 1;
    const double      hh = f.R[i1] - f.R[i0];
    const double      s  = (R - f.R[i0]) / hh;
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    const auto   dr = [&](std::size_t i) { return f.lambda1[i] * std::cos(f.theta[i]); };
    const auto   dz = [&](std::size_t i) { return -f.lambda1[i] * std::sin(f.theta[i]); };
    r = h00 * f.r[i0] + h10 * hh * dr(i0) + h01 * f.r[i1] + h11 * hh * dr(i1);
    z = h00 * f.z[i0] + h10 * hh * dz(i0) + h01 * f.z[i1] + h11 * hh * dz(i1);
  }

  /// Relative L2 error of (r, z) over [A, B]: Gauss rule with p + 4 points on
  /// every cell of the FE mesh (the FE error is smooth inside cells).
  double l2_error(const Scene &scene, const MembraneModel &model, const Reference &ref)
  {
    const Discretization     &mesh = model.discretization();
    const dealii::QGauss<1>   gauss(mesh.degree() + 4);
    std::vector<double>       R, weight;
    for (const MeshCell &cell : mesh.cells)
      for (unsigned int i = 0; i < gauss.size(); ++i)
        {
          R.push_back(cell.x0 + cell.h * gauss.point(i)[0]);
          weight.push_back(cell.h * gauss.weight(i));
        }
    std::vector<double> r, z;
    model.profile_at(R, r, z);
    double err = 0., norm = 0.;
    for (std::size_t i = 0; i < R.size(); ++i)
      {
        double rr, zz;
        reference_profile(ref.fields, scene.ring_of(R[i]), R[i], rr, zz);
        err += weight[i] * ((r[i] - rr) * (r[i] - rr) + (z[i] - zz) * (z[i] - zz));
        norm += weight[i] * (rr * rr + zz * zz);
      }
    return std::sqrt(err / norm);
  }

  /// Hoop stress at the disk edge from the reaction of the r(A) constraint:
  /// at equilibrium the residual entry of r(A) is -2 pi H A s1 cos(theta),
  /// and the disk's axial balance gives 2 pi H A s1 sin(theta) = F, so s1(A)
  /// follows without differentiating the FE solution; l1 then solves
  /// s1(l1, lam_pre) = s1(A) under the inner ring's law and s2 = s2(l1, lam_pre).
  /// In 1D Galerkin FE such reactions converge like the energy, O(h^2p).
  double recovered_disk_edge_s2(const Scene &scene, const MembraneModel &model)
  {
    const double A   = scene.inner_reference_radius();
    const auto   res = model.residual_vector();
    const double c   = 2. * M_PI * scene.material.thickness * A;
    const double s1  = std::hypot(-res[model.discretization().r_inner] / c, scene.dead_load() / c);
    const GentDielectric law(scene.material, model.summary().voltages.front());
    const auto l1 = shooting::solve_lambda1(law, scene.prestretch, s1, scene.prestretch);
    require(l1.has_value(), "no meridian stretch gives the recovered s1 at the disk edge");
    return law.stress(*l1, scene.prestretch).s2;
  }

  struct Row
  {
    std::string scene, study;
    unsigned    degree = 0, elements_per_ring = 0, refinements = 0;
    double      grading = 0.;
    unsigned    dofs    = 0;
    double      disp = 0., s2_max = 0., s2_recovered = 0., l2 = 0.;
    std::vector<double> s2; ///< per ring
  };

  Row measure(const std::string &name, const std::string &study, const Scene &scene,
              const FeDiscretization &d, const Reference &ref)
  {
    MembraneModel     model(scene, d, NewtonSettings());
    const StepSummary s = run_to_end(model, scene);
    Row               row;
    row.scene             = name;
    row.study             = study;
    row.degree            = d.degree;
    row.elements_per_ring = d.elements_per_ring << d.refinements;
    row.refinements       = d.refinements;
    row.grading           = d.grading;
    row.dofs              = model.n_dofs();
    row.disp              = rel(s.displacement, ref.summary.displacement);
    for (unsigned int k = 0; k < scene.n_rings(); ++k)
      {
        row.s2.push_back(rel(s.s2_ring_inner[k], ref.summary.s2_ring_inner[k]));
        row.s2_max = std::max(row.s2_max, row.s2.back());
      }
    row.s2_recovered = rel(recovered_disk_edge_s2(scene, model), ref.summary.s2_ring_inner[0]);
    row.l2           = l2_error(scene, model, ref);
    for (const double e : {row.disp, row.s2_max, row.s2_recovered, row.l2})
      require_finite(e, "an error of p = " + std::to_string(d.degree) + ", " +
                          std::to_string(row.elements_per_ring) + "/ring");
    return row;
  }

  /// Observed order between two rows of an h-study (element size halves);
  /// NaN unless both errors lie above @p floor.
  double order(const double e_coarse, const double e_fine, const double floor)
  {
    if (!(e_coarse > floor) || !(e_fine > floor))
      return std::numeric_limits<double>::quiet_NaN();
    return std::log2(e_coarse / e_fine);
  }

  /// The order, or in brackets where an error is at the reference's level
  /// (not to be trusted), or "-" where an error did not decrease.
  std::string order_text(const double a, const double b, const double floor)
  {
    std::ostringstream s;
    const double       v = order(a, b, floor);
    s << std::fixed << std::setprecision(2);
    if (!std::isnan(v))
      s << v;
    else if (a > 0. && b > 0. && b < a)
      s << '(' << std::log2(a / b) << ')';
    else
      s << '-';
    return s.str();
  }

  void print_header(const std::string &what)
  {
    std::cout << what << "\n"
              << std::setw(3) << "p" << std::setw(6) << "n/ring" << std::setw(6) << "grad"
              << std::setw(7) << "dofs" << std::setw(11) << "disp err" << std::setw(7)
              << "order" << std::setw(11) << "s2 err" << std::setw(7) << "order"
              << std::setw(11) << "s2 recov." << std::setw(7) << "order" << std::setw(11)
              << "L2 err" << std::setw(7) << "order" << "\n";
  }

  /// Thresholds below which errors are not resolved by the reference.
  struct Floors
  {
    double disp, s2, l2;
  };

  void print_row(const Row &r, const Row *prev, const Floors &floor)
  {
    const auto o = [&](const double Row::*e, const double fl) {
      return prev ? order_text(prev->*e, r.*e, fl) : std::string();
    };
    std::cout << std::setw(3) << r.degree << std::setw(6) << r.elements_per_ring << std::setw(6)
              << std::defaultfloat << r.grading << std::scientific << std::setw(7) << r.dofs
              << std::setw(11) << r.disp << std::setw(7) << o(&Row::disp, floor.disp)
              << std::setw(11) << r.s2_max << std::setw(7) << o(&Row::s2_max, floor.s2)
              << std::setw(11) << r.s2_recovered << std::setw(7)
              << o(&Row::s2_recovered, floor.s2) << std::setw(11) << r.l2 << std::setw(7)
              << o(&Row::l2, floor.l2) << "\n";
  }

  /// In the smoke run: the orders of the last two rows of an h-study of
  /// p = 1 must be the theory's (2, 1, 2) within 0.1.
  void check_p1_orders(const Row &coarse, const Row &fine, const Floors &floor)
  {
    for (const auto &[a, b, fl, theory, what] :
         {std::make_tuple(coarse.disp, fine.disp, floor.disp, 2., "displacement"),
          std::make_tuple(coarse.s2_max, fine.s2_max, floor.s2, 1., "s2 at the ring edges"),
          std::make_tuple(coarse.l2, fine.l2, floor.l2, 2., "L2 of (r, z)")})
      {
        const double o = order(a, b, fl);
        require(std::abs(o - theory) < 0.1, std::string("observed order of the ") + what +
                                              " for p = 1 is " + std::to_string(o) +
                                              ", theory " + std::to_string(theory));
      }
  }

  int benchmark(const OutputFolder &dir, const bool smoke)
  {
    struct Case
    {
      std::string name;
      Scene       scene;
    };
    std::vector<Case> cases{
      {"full", paper_scene({1., 3.}, {{5.}})},
      {"partitioned", paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 6.}})}};
    if (smoke)
      cases.erase(cases.begin());
    // (p, elements per ring before bisection, bisections): p = 4 starts from
    // 2 elements per ring, else its errors reach the reference's level after
    // one bisection.
    const std::vector<std::tuple<unsigned, unsigned, unsigned>> h_plan =
      smoke ? std::vector<std::tuple<unsigned, unsigned, unsigned>>{{1, 8, 2}, {4, 2, 2}} :
              std::vector<std::tuple<unsigned, unsigned, unsigned>>{
                {1, 8, 6}, {2, 8, 5}, {3, 8, 4}, {4, 2, 4}};

    std::vector<Row> rows;
    std::cout << std::setprecision(3) << std::scientific;
    for (const Case &c : cases)
      {
        const Reference ref   = shooting_reference(c.scene, 1e-12);
        const Reference tight = shooting_reference(c.scene, 1e-13);
        // Uncertainty of the reference: its change from tolerance 1e-12 to 1e-13.
        double ref_s2 = 0., ref_l2 = 0., norm = 0.;
        for (unsigned int k = 0; k < c.scene.n_rings(); ++k)
          ref_s2 = std::max(ref_s2, rel(ref.summary.s2_ring_inner[k],
                                        tight.summary.s2_ring_inner[k]));
        for (std::size_t i = 0; i < tight.fields.R.size(); ++i)
          {
            double r, z;
            reference_profile(ref.fields, tight.fields.ring[i], tight.fields.R[i], r, z);
            ref_l2 = std::max(ref_l2, std::hypot(r - tight.fields.r[i], z - tight.fields.z[i]));
            norm   = std::max(norm, std::hypot(tight.fields.r[i], tight.fields.z[i]));
          }
        const double ref_disp = rel(ref.summary.displacement, tight.summary.displacement);
        std::cout << "\n=== " << c.name << ": reference = shooting, tolerance 1e-12; change "
                  << "to tolerance 1e-13: displacement " << ref_disp << ", s2 at ring edges "
                  << ref_s2 << ", profile (max, relative) " << ref_l2 / norm << "\n"
                  << std::defaultfloat << std::setprecision(12) << "reference displacement "
                  << ref.summary.displacement * 1e3 << " mm, s2/mu at ring inner edges";
        for (const double s2 : ref.summary.s2_ring_inner)
          std::cout << ' ' << s2 / c.scene.material.shear_modulus;
        std::cout << std::scientific << std::setprecision(3) << "\n";

        // Orders are computed only from errors above 100 times the
        // reference's own change.
        const Floors floor{std::max(1e-13, 100. * ref_disp), std::max(1e-12, 100. * ref_s2),
                           std::max(1e-12, 100. * ref_l2 / norm)};

        for (const auto &[p, base, kmax] : h_plan)
          for (const double grading :
               (p == 3 ? std::vector<double>{4., 1.} : std::vector<double>{4.}))
            {
              print_header("h-refinement, p = " + std::to_string(p) +
                           (grading == 1. ? ", uniform mesh" : ", grading 4"));
              for (unsigned k = 0; k <= kmax; ++k)
                {
                  FeDiscretization d;
                  d.degree            = p;
                  d.elements_per_ring = base;
                  d.grading           = grading;
                  d.refinements       = k;
                  rows.push_back(
                    measure(c.name, grading == 1. ? "h-uniform" : "h", c.scene, d, ref));
                  const Row *prev = k > 0 ? &rows[rows.size() - 2] : nullptr;
                  print_row(rows.back(), prev, floor);
                  if (smoke && p == 1 && k == kmax)
                    check_p1_orders(*prev, rows.back(), floor);
                  // Stop once every error is at the reference's level.
                  if (rows.back().disp < floor.disp && rows.back().l2 < floor.l2 &&
                      rows.back().s2_max < floor.s2)
                    break;
                }
            }
        for (const unsigned n : smoke ? std::vector<unsigned>{} : std::vector<unsigned>{8, 2})
          {
            print_header("p-refinement, " + std::to_string(n) + " elements per ring, grading 4");
            for (unsigned p = 1; p <= 8; ++p)
              {
                FeDiscretization d;
                d.degree            = p;
                d.elements_per_ring = n;
                rows.push_back(measure(c.name, "p" + std::to_string(n), c.scene, d, ref));
                print_row(rows.back(), nullptr, floor);
              }
          }
        std::cout << "(orders: log2 of the error ratio of successive bisections; in brackets "
                     "or '-' where an error is within 100x of the reference's own change; "
                     "thresholds: disp "
                  << floor.disp << ", s2 " << floor.s2 << ", L2 " << floor.l2 << ")\n";
      }

    std::ofstream csv(dir / "convergence.csv");
    csv << "scene,study,degree,elements_per_ring,refinements,grading,dofs,disp_err,s2_err_max,"
           "s2_err_ring1,s2_err_ring2,s2_recovered_err,l2_err\n";
    csv << std::setprecision(6) << std::scientific;
    for (const Row &r : rows)
      csv << r.scene << ',' << r.study << ',' << r.degree << ',' << r.elements_per_ring << ','
          << r.refinements << ',' << r.grading << ',' << r.dofs << ',' << r.disp << ','
          << r.s2_max << ',' << r.s2[0] << ',' << (r.s2.size() > 1 ? r.s2[1] : 0.) << ','
          << r.s2_recovered << ',' << r.l2 << '\n';
    require(bool(csv), "could not write " + (dir / "convergence.csv").string());
    std::cout << "\nwrote " << (dir / "convergence.csv").string() << "\n";
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  return study_main(argc, argv, "bench_convergence", benchmark);
}
