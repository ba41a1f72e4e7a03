// The input of `cdea sweep`: the value lists and the subsection Sweep, turned
// into SweepSettings; the rows of each MPI rank.

#include <cdea/base/units.h>
#include <cdea/base/mpi_session.h>
#include <cdea/design/sweep.h>
#include <cdea/fe/load_term.h>
#include <cdea/input/parameters.h>
#include <cdea/input/solver_settings.h>
#include <cdea/input/validation.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cdea
{
  namespace
  {

    std::string format(const double x)
    {
      std::ostringstream o;
      o << x;
      return o.str();
    }



    constexpr std::size_t max_values = 100000;
    /// Map points beyond which a sweep needs Sweep/Confirm long sweep: with
    /// the default discretization 1e6 points take minutes and 0.1 GB, a finer
    /// one takes hours.
    constexpr double long_map_points = 1e6;
    /// Map points (edge values x outer voltages): five doubles each in the rows
    /// (SweepRow) and again in the file's datasets, so 1e7 take about 1 GB.
    constexpr double max_map_points = 1e7;
  } // namespace


  SweepSettings sweep_settings(const Parameters &p, const Scene &scene)
  {
    // The lines are defined by the sign of the plain law's hoop stress, and
    // the map is of the actuator under its dead load alone.
    if (p.wrinkling.model != WrinklingModel::check)
      throw InputError("Wrinkling/Model = " + to_string(p.wrinkling.model) +
                       " is not supported by cdea sweep: the red and blue lines are defined "
                       "by the hoop stress of the plain membrane law (use check)");
    require_load_term_support(p, supports_design_map, "sweep",
                              "the maps are of the actuator under its dead load alone");
    if (p.time.enabled)
      throw InputError("Time/Enabled = true is not supported by cdea sweep: the maps are "
                       "quasi-static (use false)");
    require_film_law(p, "sweep", "the maps are of the film's Gent law");
    SweepSettings s;
    const double  b_over_a = scene.frame_radius / scene.disk_radius;

    const std::string edges_name = "Sweep/Ring edge values (r/a)";
    s.ring_edge_values           = expand_value_list(p.sweep.ring_edge_values_text, edges_name);
    for (const double v : s.ring_edge_values)
      if (!(v > 1. && v < b_over_a))
        throw InputError(edges_name + ": " + format(v) + " is not inside (1, " +
                         format(b_over_a) + "): r_v/a must lie strictly between the disk edge "
                         "and the frame (b/a)");
    for (std::size_t i = 1; i < s.ring_edge_values.size(); ++i)
      if (!(s.ring_edge_values[i] > s.ring_edge_values[i - 1]))
        throw InputError(edges_name + ": values must increase strictly, but " +
                         format(s.ring_edge_values[i]) + " follows " +
                         format(s.ring_edge_values[i - 1]));

    const std::string inner_name = "Sweep/Inner voltage (kV)";
    if (!(p.sweep.inner_voltage_kV > 0.) || !std::isfinite(p.sweep.inner_voltage_kV))
      throw InputError(inner_name + " must be positive (the stroke increase is relative to "
                       "the stroke with both rings at it), got " +
                       format(p.sweep.inner_voltage_kV));
    s.inner_voltage = units::kV_in_V_on_grid(p.sweep.inner_voltage_kV);

    const std::string range_name = "Sweep/Outer voltage range (kV)";
    const auto        range = parse_number_list(p.sweep.outer_voltage_range_text, range_name);
    if (range.size() != 3)
      throw InputError(range_name + ": expected three numbers 'from, to, step', got '" +
                       p.sweep.outer_voltage_range_text + "'");
    const double from = range[0], to = range[1], step = range[2];
    if (from < 0.)
      throw InputError(range_name + ": voltages must not be negative, got from = " +
                       format(from));
    if (!(step > 0.))
      throw InputError(range_name + ": the step must be positive, got " + format(step));
    if (to < from)
      throw InputError(range_name + ": the range is empty: 'to' (" + format(to) +
                       ") is below 'from' (" + format(from) + ")");
    const double count = std::floor((to - from) / step + 1e-9) + 1.;
    if (count > double(max_values))
      throw InputError(range_name + ": " + format(count) + " voltages are too many (at most " +
                       std::to_string(max_values) + ")");
    s.outer_from = units::kV_in_V_on_grid(from);
    s.outer_to   = units::kV_in_V_on_grid(to);
    s.outer_step = units::kV_in_V_on_grid(step);
    for (long k = 0; k < long(count); ++k)
      s.outer_voltages.push_back(units::kV_in_V_on_grid(from + k * step));
    // Land exactly on 'to' when it is on the grid.
    if (std::abs(from + (count - 1.) * step - to) <= 1e-9 * step)
      s.outer_voltages.back() = s.outer_to;
    const double points = double(s.ring_edge_values.size()) * double(s.outer_voltages.size());
    if (points > max_map_points)
      throw InputError("Sweep/Ring edge values (r/a) x Sweep/Outer voltage range (kV): the map "
                       "would have " + format(points) + " points (" +
                       std::to_string(s.ring_edge_values.size()) + " x " +
                       std::to_string(s.outer_voltages.size()) + "), more than the " +
                       format(max_map_points) + " it may hold in memory");
    if (points > long_map_points && !p.sweep.confirm_long)
      throw InputError("Sweep/Ring edge values (r/a) x Sweep/Outer voltage range (kV): the map "
                       "would have " + format(points) + " points, more than " +
                       format(long_map_points) + " (minutes to hours of work): set Sweep/Confirm "
                       "long sweep = true to compute it");
    return s;
  }

  SteppingSettings sweep_stepping_settings(const Parameters &p)
  {
    return study_stepping_settings(p);
  }

  std::vector<std::size_t> rows_of_rank(const std::size_t n_rows, const unsigned int rank,
                                        const unsigned int size)
  {
    return mpi::items_of_rank(n_rows, rank, size);
  }
} // namespace cdea
