#include <cdea/model/voltage_path.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cdea
{
  VoltagePath::VoltagePath(std::vector<std::vector<double>> waypoints)
  {
    if (waypoints.empty())
      throw std::invalid_argument("a voltage path needs at least one waypoint");
    const std::size_t n = waypoints.front().size();
    for (const auto &w : waypoints)
      if (w.size() != n || n == 0)
        throw std::invalid_argument(
          "every waypoint of a voltage path needs one voltage per ring");
    points.emplace_back(n, 0.);
    points.insert(points.end(), waypoints.begin(), waypoints.end());
  }

  unsigned int VoltagePath::n_rings() const
  {
    return points.empty() ? 0 : points.front().size();
  }

  unsigned int VoltagePath::segment(const double t) const
  {
    const double clamped = std::clamp(t, 0., double(n_segments()));
    return std::min<unsigned int>(static_cast<unsigned int>(std::floor(clamped)),
                                  n_segments() - 1);
  }

  std::vector<double> VoltagePath::voltages(const double t) const
  {
    const unsigned int k = segment(t);
    const double       s = std::clamp(t - k, 0., 1.);
    std::vector<double> v(n_rings());
    for (unsigned int i = 0; i < v.size(); ++i)
      v[i] = (1. - s) * points[k][i] + s * points[k + 1][i];
    return v;
  }

  double VoltagePath::max_rate(const double t) const
  {
    const unsigned int k    = segment(t);
    double             rate = 0.;
    for (unsigned int i = 0; i < n_rings(); ++i)
      rate = std::max(rate, std::abs(points[k + 1][i] - points[k][i]));
    return rate;
  }

  std::vector<std::vector<double>> VoltagePath::waypoints() const
  {
    return {points.begin() + 1, points.end()};
  }
} // namespace cdea
