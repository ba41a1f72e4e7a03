// Benchmark: the cost of each stage against the number of elements. The
// default case (prm/default.prm, or the file given, its degree and grading
// kept) with 8, 16, ..., MAX elements per ring; for each mesh:
//
//   build       constructing the model (mesh, dof numbering, shape tables)
//   Newton      a solve of the voltage stage over its Newton iterations
//               (assembly of residual and tangent, banded LU, line search)
//   stability   the stability check of a converged state, as `cdea run`
//               does it after every step (inertia and smallest eigenvalue)
//   fields      the fields along the meridian, the hoop stresses and the
//               non-physical check of a converged state
//   output      appending the step (summary row and fields) to a results
//               file (journal on disk, the file in memory)
//   step        a whole converged step of the voltage stage: all of the above
//   memory      the peak resident memory the run adds (MiB), and the
//               bytes of the banded tangent (LU storage, 3 kd + 1 rows)
//
// every stage timed at each step of the voltage stage (0.25 kV steps, the
// states the load stepper reached), medians printed; then the ratio of
// each stage's time at the largest mesh to the smallest, against the ratio
// of their element counts (linear cost: equal). Writes the table to CSV if
// asked.
//
//   build/benchmarks/bench_scaling [MAX_ELEMENTS | --quick] [FILE.prm] [CSV]
//
// Checks (exit code 1 otherwise): every mesh reaches the end of the path
// with every state stable; the final displacement converges with the mesh
// (the two finest meshes agree within 1e-6, and the finest with the file's
// own mesh); the smallest eigenvalue of the stiffness matrix halves with the
// element length (within 1e-2); and, up to 1024 elements, the check's
// decision (stable) and eigenvalue agree with LAPACK's dsbevx on the final
// tangent (numerics/eigenvalue_reference, within 1e-8). --quick: up to 64
// elements, as ctest runs it (label bench-smoke).

#include <cdea/analysis/run_setup.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/input/solver_settings.h>
#include <cdea/model/output_fields.h>
#include <cdea/numerics/eigenvalue_reference.h>
#include <cdea/output/results_file.h>
#include <cdea/solver/state_check.h>

#include "bench_common.h"

#include <fstream>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

using namespace cdea;
using namespace cdea_bench;

namespace
{
  /// Resets VmHWM to the current resident size (Linux: clear_refs 5).
  void reset_peak_memory()
  {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
  }

  struct Row
  {
    unsigned int elements = 0, dofs = 0, bandwidth = 0, steps = 0, iterations = 0;
    double build = 0., newton = 0., stability = 0., fields = 0., output = 0., step = 0.;
    double memory = 0., band = 0., displacement = 0., eigenvalue = 0.;
    double reference  = std::numeric_limits<double>::quiet_NaN(); ///< dsbevx, final state
    bool   all_stable = true, stable = true;
  };

  /// The states of the voltage stage of a run without the stability check.
  std::vector<ModelState> voltage_states(MembraneModel &model, const Scene &scene,
                                         const SteppingSettings &settings, RunResult &result)
  {
    std::vector<ModelState> states;
    LoadStepper             stepper(scene, model, settings);
    stepper.on_step = [&](const StepSummary &s) {
      if (s.stage == Stage::voltage || (s.stage == Stage::dead_load && s.load_factor == 1.))
        states.push_back(model.state());
    };
    result = stepper.run();
    return states;
  }

  /// Each stage timed at each step of the voltage stage: from the state
  /// before it, solve to the next, check its stability, evaluate its
  /// fields and append it to a results file.
  void time_stages(MembraneModel &model, const std::vector<ModelState> &states,
                   const Parameters &p, const Scene &scene, Row &row)
  {
    const OutputFolder  out("", true);
    ResultsFile         file((out / "scaling.h5").string(), "", scene.n_rings());
    std::vector<double> newton, stability, fields, output, step;
    const double        frame = scene.outer_reference_radius() * scene.prestretch;
    // CPU time: what the code costs, hardly touched by other jobs on a
    // shared machine (the output's waits for the disk are not in it).
    const auto clock = cpu_seconds;
    for (std::size_t k = 1; k < states.size(); ++k)
      {
        model.set_state(states[k - 1]);
        const double      t0     = clock();
        const SolveReport report = model.solve(states[k].load);
        const double      t1     = clock();
        require(report.converged, "a step of the voltage stage did not converge again: " +
                                    report.message);
        const StateStability s  = model.stability(StabilityEigenvalue::every_step);
        const double         t2 = clock();
        StepSummary          summary = model.summary();
        const StepFields     f       = model.fields();
        summary.columns.set(summary_column::nonphysical, double(nonphysical_flags(f, frame)));
        const double t3 = clock();
        summary.columns.set(summary_column::min_eigenvalue, s.min_eigenvalue);
        summary.columns.set(summary_column::stable, s.stable);
        file.append(summary, f);
        const double t4 = clock();
        newton.push_back((t1 - t0) / std::max(1u, report.iterations));
        stability.push_back(t2 - t1);
        fields.push_back(t3 - t2);
        output.push_back(t4 - t3);
        step.push_back(t4 - t0);
        row.iterations += report.iterations;
        row.all_stable = row.all_stable && s.stable == 1.;
        row.stable     = s.stable == 1.;
        row.eigenvalue = s.min_eigenvalue;
      }
    file.finish("benchmark");
    (void)p;
    row.newton    = median(newton);
    row.stability = median(stability);
    row.fields    = median(fields);
    row.output    = median(output);
    row.step      = median(step);
    row.steps     = states.size() - 1;
  }

  /// The smallest eigenvalue of the model's tangent without its constrained
  /// dofs by LAPACK's dsbevx (O(n^2 kd)), the stability check's reference.
  double reference_eigenvalue(const MembraneModel &model)
  {
    AssembledSystem system;
    model.assemble(assemble_residual | assemble_tangent, system);
    const std::vector<unsigned int> &constrained = model.discretization().constrained;
    if (system.rank_one_coupling == 0.)
      return reference::smallest_symmetric_eigenvalue(system.tangent, constrained);
    Eigen::VectorXd g = system.volume_gradient;
    for (const unsigned int i : constrained)
      g[i] = 0.;
    return reference::smallest_symmetric_eigenvalue(system.tangent, system.rank_one_coupling, g,
                                                    constrained);
  }

  /// Newton as the file sets it, and a state at the residual's round-off
  /// level counted as converged (NewtonSettings::converge_at_round_off):
  /// that level, eps |K| |x|, grows as the elements shrink and passes the
  /// file's residual tolerance on the finest meshes (from 8192 elements the
  /// pre-stretch stage stalls there otherwise); below it nothing changes.
  NewtonSettings scaling_newton_settings(const Parameters &p)
  {
    NewtonSettings n        = newton_settings(p);
    n.converge_at_round_off = true;
    return n;
  }

  /// The final displacement of the voltage stage on the file's own mesh.
  double default_mesh_displacement(const Parameters &p, const Scene &scene)
  {
    MembraneModel    model(scene, fe_discretization(p), scaling_newton_settings(p));
    SteppingSettings settings = stepping_settings(p);
    settings.stability_check  = false;
    RunResult result;
    voltage_states(model, scene, settings, result);
    require(result.completed, "the file's own mesh: the run did not complete: " + result.message);
    return model.displacement();
  }

  Row measure(const Parameters &p, const Scene &scene, const unsigned int elements)
  {
    Row row;
    row.elements = elements;
    reset_peak_memory();
    const double     before = status_mib("VmRSS");
    FeDiscretization disc   = fe_discretization(p);
    disc.elements_per_ring  = elements;
    disc.refinements        = 0;
    const double t0         = wall_seconds();
    const auto   model      = std::make_unique<MembraneModel>(scene, disc, scaling_newton_settings(p));
    row.build               = wall_seconds() - t0;
    row.dofs                = model->n_dofs();
    row.bandwidth           = model->discretization().bandwidth();
    SteppingSettings settings = stepping_settings(p);
    settings.stability_check  = false;
    RunResult                     result;
    const std::vector<ModelState> states = voltage_states(*model, scene, settings, result);
    require(result.completed, std::to_string(elements) + " elements: the run did not complete: " +
                                result.message);
    require(states.size() > 2, "too few steps in the voltage stage");
    row.displacement = model->displacement();
    time_stages(*model, states, p, scene, row);
    row.memory = status_mib("VmHWM") - before;
    row.band   = double(3 * row.bandwidth + 1) * row.dofs * sizeof(double) / (1024. * 1024.);
    if (elements <= 1024)
      row.reference = reference_eigenvalue(*model);
    return row;
  }

  void print(const std::vector<Row> &rows, std::ostream &o, const bool csv)
  {
    const char *sep = csv ? "," : " ";
    const int   w   = csv ? 0 : 11;
    o << std::setw(w) << "elements" << sep << std::setw(w) << "unknowns" << sep << std::setw(w)
      << "bandwidth" << sep << std::setw(w) << "build_ms" << sep << std::setw(w) << "newton_ms"
      << sep << std::setw(w) << "stability_ms" << sep << std::setw(w) << "fields_ms" << sep
      << std::setw(w) << "output_ms" << sep << std::setw(w) << "step_ms" << sep << std::setw(w)
      << "memory_MiB" << sep << std::setw(w) << "band_MiB" << '\n';
    for (const Row &r : rows)
      o << std::setw(w) << r.elements << sep << std::setw(w) << r.dofs << sep << std::setw(w)
        << r.bandwidth << sep << std::setw(w) << r.build * 1e3 << sep << std::setw(w)
        << r.newton * 1e3 << sep << std::setw(w) << r.stability * 1e3 << sep << std::setw(w)
        << r.fields * 1e3 << sep << std::setw(w) << r.output * 1e3 << sep << std::setw(w)
        << r.step * 1e3 << sep << std::setw(w) << r.memory << sep << std::setw(w) << r.band
        << '\n';
  }

  int benchmark(const unsigned int max_elements, const std::string &file, const std::string &csv)
  {
    const Parameters p     = read_parameters(file);
    const Scene      scene = p.scene();
    std::vector<Row> rows;
    for (unsigned int n = 8; n <= max_elements; n *= 2)
      {
        rows.push_back(measure(p, scene, n));
        const Row &r = rows.back();
        std::cout << "  " << r.elements << " elements: " << r.steps << " steps, " << r.iterations
                  << " Newton iterations, displacement " << std::setprecision(10)
                  << r.displacement * 1e3 << " mm, eigenvalue " << r.eigenvalue << " N/m"
                  << std::setprecision(6) << std::endl;
      }
    require(rows.size() >= 2, "MAX_ELEMENTS must be at least 16");
    std::cout << std::setprecision(4) << "\nmedian per step of the voltage stage (ms; memory: peak "
              << "added by the run, MiB)\n";
    print(rows, std::cout, false);
    const Row &small = rows.front(), &large = rows.back();
    std::cout << "\nratio " << large.elements << " / " << small.elements
              << " elements: " << double(large.elements) / small.elements
              << " (linear); Newton iteration " << large.newton / small.newton
              << ", stability check " << large.stability / small.stability << ", fields "
              << large.fields / small.fields << ", output " << large.output / small.output
              << ", step " << large.step / small.step << '\n';
    if (!csv.empty())
      {
        std::ofstream o(csv);
        print(rows, o, true);
        std::cout << "table written to " << csv << '\n';
      }

    // The answers: every state stable, the displacement and the eigenvalue
    // converge with the mesh (h^2p: the two finest agree closely).
    for (const Row &r : rows)
      require(r.all_stable, std::to_string(r.elements) + " elements: a state is not stable");
    const Row &finer = rows[rows.size() - 2];
    require(rel(finer.displacement, large.displacement) < 1e-6,
            "the displacement of the two finest meshes differs by " +
              std::to_string(rel(finer.displacement, large.displacement)));
    // The smallest eigenvalue of the stiffness matrix scales with the
    // element length (no mass matrix): halved with every refinement.
    require(rel(finer.eigenvalue, 2. * large.eigenvalue) < 1e-2,
            "the smallest eigenvalue does not halve with the element length: " +
              std::to_string(finer.eigenvalue) + " and " + std::to_string(large.eigenvalue));
    const double own = default_mesh_displacement(p, scene);
    require(rel(large.displacement, own) < 1e-6,
            "the displacement of the finest mesh differs from the file's own mesh by " +
              std::to_string(rel(large.displacement, own)));
    double worst_reference = 0.;
    for (const Row &r : rows)
      if (!std::isnan(r.reference))
        {
          require(r.stable == (r.reference > 0.),
                  std::to_string(r.elements) + " elements: the stability decision disagrees "
                                               "with the sign of dsbevx's eigenvalue");
          worst_reference = std::max(worst_reference, rel(r.eigenvalue, r.reference));
          require(rel(r.eigenvalue, r.reference) < 1e-8,
                  std::to_string(r.elements) + " elements: the smallest eigenvalue " +
                    std::to_string(r.eigenvalue) + " differs from dsbevx's " +
                    std::to_string(r.reference));
        }
    std::cout << "checks: every state stable; displacement of the two finest meshes within "
              << rel(finer.displacement, large.displacement) << ", of the finest and the file's "
              << "own mesh within " << rel(large.displacement, own)
              << "; eigenvalue halved with the element length within "
              << rel(finer.eigenvalue, 2. * large.eigenvalue)
              << "; decision and eigenvalue against dsbevx (up to 1024 elements) within "
              << worst_reference << '\n';
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  const MpiSession mpi(argc, argv);
  return guarded("bench_scaling", [&] {
    const bool         quick        = argc > 1 && std::string(argv[1]) == "--quick";
    const unsigned int max_elements = quick ? 64 : argc > 1 ? std::atoi(argv[1]) : 16384;
    const std::string  file =
      argc > 2 && *argv[2] ? argv[2] : std::string(CDEA_SOURCE_DIR) + "/prm/default.prm";
    const std::string csv = argc > 3 ? argv[3] : "";
    return benchmark(max_elements, file, csv);
  });
}
