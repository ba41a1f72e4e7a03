#pragma once
// `cdea sweep FILE.prm`: design maps over two-ring layouts (see doc/design-maps.md).
//
// For every inner-ring edge r_v/a of the subsection Sweep the actuator with the
// rings [1, r_v/a] and [r_v/a, b/a] is loaded as in a normal run (pre-stretch,
// dead load, both rings together to the inner voltage). From that state the
// outer ring's voltage is continued along the map's grid with the inner one
// held; the continuation stops where the solver cannot go on (a fold of the
// voltage-displacement curve, typically): the grid points beyond are NaN. On
// the way two lines of the paper's figure 8 are located by root finding:
//   red:  s2 = 0 at the outer ring's inner edge (loss of tension there);
//   blue: s2 equal at the inner edges of both rings.
// The rows (one per r_v) are independent, so `mpirun -np N cdea sweep` deals
// them round-robin to the ranks and rank 0 gathers one file; every row is
// computed from scratch in the same way, so the file does not depend on N.

#include <cdea/base/text.h>
#include <cdea/input/parameter_input.h>
#include <cdea/fe/membrane_model.h>
#include <cdea/model/scene.h>
#include <cdea/model/equilibrium_model.h>
#include <cdea/model/product.h>
#include <cdea/solver/load_stepper.h>

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace cdea
{
  struct Parameters;

  /// What one map is made of (SI units: volts).
  struct SweepSettings
  {
    std::vector<double> ring_edge_values; ///< r_v/a, strictly increasing, in (1, b/a)
    double              inner_voltage = 5e3; ///< V
    double              outer_from    = 5e3; ///< V
    double              outer_to      = 8e3; ///< V
    double              outer_step    = 50.; ///< V
    std::vector<double> outer_voltages;      ///< V, from + k step, k = 0 .. m-1
    double              line_tolerance = 0.1; ///< V, root finding of the two lines
  };

  /// The sweep's settings from parsed parameters; every check of the
  /// subsection Sweep is made here. Throws InputError naming the parameter.
  SweepSettings sweep_settings(const Parameters &p, const Scene &scene);

  /// The Solver settings of the file for the load stages of a row, by load
  /// stepping and without the stability, breakdown and arc-length options
  /// (the map reports none of them).
  SteppingSettings sweep_stepping_settings(const Parameters &p);

  /// The two-ring scene of one map row: rings [1, rv] and [rv, b/a], the path
  /// raising both to the inner voltage.
  Scene sweep_scene(const Scene &base, double rv_over_a, double inner_voltage);

  /// A point of the red or the blue line of one row (NaN where absent).
  struct SweepLine
  {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    double       outer_voltage   = nan; ///< V
    double       displacement    = nan; ///< m
    double       stroke_increase = nan; ///< percent
    double       s2_inner[2]     = {nan, nan}; ///< Pa, inner edges of rings 1 and 2
    double       bracket_width   = nan; ///< V, of the root bracket at the end
    unsigned int evaluations     = 0;   ///< equilibrium solves of the root search
  };

  /// One row of the map: one r_v/a over all outer voltages.
  struct SweepRow
  {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    double rv_over_a = nan;
    /// Both rings reached the inner voltage (else the whole row is NaN).
    bool   base_reached = false;
    /// Not computed: the sweep was asked to stop (SIGINT, SIGTERM) before
    /// this row began; message says by what.
    bool   skipped = false;
    double base_displacement = nan; ///< m, both rings at the inner voltage
    double base_s2_inner[2]  = {nan, nan}; ///< Pa
    /// Lowest and highest outer voltage reached by the continuation (V).
    double lowest_voltage = nan, highest_voltage = nan;
    /// Why the continuation stopped before the end of the grid (empty if not).
    std::string message;
    /// One entry per outer voltage of the grid, NaN where not reached.
    std::vector<double> displacement;    ///< m
    std::vector<double> stroke;          ///< m
    std::vector<double> stroke_increase; ///< percent
    std::vector<double> s2_inner_ring1;  ///< Pa, at the disk edge
    std::vector<double> s2_inner_ring2;  ///< Pa, at r_v
    SweepLine red, blue;
    unsigned int solves            = 0; ///< equilibrium solves attempted (all stages)
    unsigned int newton_iterations = 0; ///< of all those solves
    /// Where the solves went: the load stages up to the base state, the root
    /// searches of the two lines, and the solves that failed (cut-backs).
    unsigned int base_solves = 0, base_iterations = 0;
    unsigned int line_solves = 0, line_iterations = 0;
    unsigned int failed_solves = 0, failed_iterations = 0;
    double       seconds = 0.; ///< wall time of the row (not written to the file)
    double       base_seconds = 0., line_seconds = 0.; ///< of it: base state, root searches
  };

  /// Continuation of one row with @p model, a model of @p scene (from
  /// sweep_scene()) in any state. @p zero_voltage_displacement (m) is the
  /// displacement with all voltages zero under the dead load, the zero of the
  /// stroke. @p on_points is told how many grid points were finished (the
  /// points beyond a stop count as finished).
  SweepRow compute_sweep_row(EquilibriumModel &model, const Scene &scene,
                             const SweepSettings &settings, const SteppingSettings &stepping,
                             double zero_voltage_displacement,
                             const std::function<void(std::size_t)> &on_points = {});

  /// The displacement with all voltages zero under the dead load (m): the
  /// full-electrode scene of @p base loaded as in a normal run. It does not
  /// depend on the electrode layout, so a map computes it once.
  double zero_voltage_displacement(const Scene &base, const FeDiscretization &disc,
                                   const NewtonSettings &newton,
                                   const SteppingSettings &stepping);

  struct SweepMap
  {
    SweepSettings         settings;
    double                zero_voltage_displacement = 0.; ///< m
    std::vector<SweepRow> rows; ///< one per ring edge value, in its order
  };

  /// Which rows rank @p rank of @p size computes: round-robin by index.
  std::vector<std::size_t> rows_of_rank(std::size_t n_rows, unsigned int rank,
                                        unsigned int size);

  /// The whole map with the FE model. Collective over MPI_COMM_WORLD: every
  /// rank computes its rows (rows_of_rank) and rank 0 gets all of them (the
  /// other ranks return their own rows only). @p on_points (rank 0 only) is
  /// told about finished grid points of every rank as they come in. Once a
  /// stop is requested (StopOnSignals) a rank computes no further row: the
  /// rows it has not begun are skipped (NaN, SweepRow::skipped).
  SweepMap compute_sweep_map(const Parameters &p, const Scene &base,
                             const SweepSettings &settings,
                             const std::function<void(std::size_t)> &on_points = {});

  /// The map as a product (model/quantities_sweep.h): the root attributes
  /// (with run_status, sweep_run_status()) and the datasets of
  /// doc/design-maps.md, in SI; written to <Base name>_map.h5 by rank 0 and
  /// returned by the Python module.
  Product sweep_product(const SweepMap &map, const std::string &parameter_text);

  /// Whether some layout of the map reached the inner voltage (else the map
  /// is empty).
  bool some_row_reached(const SweepMap &map);

  /// The rows skipped after a stop request (0 for a whole map).
  std::size_t skipped_rows(const SweepMap &map);

  /// The map's run_status: "complete", or why not: "stopped: interrupted by
  /// SIGINT after 3 of 29 layouts", or "stopped: no layout reached the inner
  /// voltage".
  std::string sweep_run_status(const SweepMap &map);

  /// A design map kept in memory.
  struct SweepRecord
  {
    SweepMap    map;
    std::string parameters;   ///< every parameter (root attribute)
    std::string results_path; ///< where `cdea sweep` would write the map
    double      seconds = 0.; ///< wall time of the map
  };

  /// The map of `cdea sweep` for @p input, on this process alone (MPI is not
  /// used); InputError with the command's message on bad input.
  SweepRecord sweep_in_memory(const ParameterInput &input);
} // namespace cdea
