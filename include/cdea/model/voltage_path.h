#pragma once
// Piecewise-linear voltage path over the rings of a partitioned electrode.
//
// The path starts with every ring at 0 V and visits the user's waypoints in
// order. The path parameter t runs from 0 to n_segments(): on [k, k+1] the
// voltages move linearly from waypoint k to waypoint k+1, waypoint 0 being the
// all-zero state. "5, 5; 5, 6.5" thus means: both rings to 5 kV, then the outer
// one to 6.5 kV.

#include <vector>

namespace cdea
{
  class VoltagePath
  {
  public:
    VoltagePath() = default;

    /// @p waypoints: one vector of ring voltages (V) per waypoint, all of the
    /// same length (the number of rings).
    explicit VoltagePath(std::vector<std::vector<double>> waypoints);

    unsigned int n_rings() const;
    unsigned int n_segments() const { return points.size() - 1; }

    /// Ring voltages (V) at path parameter t in [0, n_segments()].
    std::vector<double> voltages(double t) const;

    /// Largest |dV/dt| over all rings on the segment that contains t (V per
    /// unit of t); converts a tolerance in volts into one in t.
    double max_rate(double t) const;

    /// The waypoints as given (without the leading all-zero state).
    std::vector<std::vector<double>> waypoints() const;

  private:
    std::vector<std::vector<double>> points; ///< zero state, then waypoints
    unsigned int segment(double t) const;
  };
} // namespace cdea
