#include <cdea/solver/state_check.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cdea
{
  namespace
  {
    struct Point2
    {
      double r, z;
    };

    bool operator==(const Point2 &a, const Point2 &b)
    {
      return a.r == b.r && a.z == b.z;
    }

    /// Sign of the turn a -> b -> c (cross product of b - a and c - a).
    int orientation(const Point2 &a, const Point2 &b, const Point2 &c)
    {
      const double x = (b.r - a.r) * (c.z - a.z) - (b.z - a.z) * (c.r - a.r);
      return (x > 0.) - (x < 0.);
    }

    /// Segments pq and uv cross at a point inside both (a touch at an end
    /// point or a collinear overlap does not count: neighbouring segments
    /// share end points).
    bool cross(const Point2 &p, const Point2 &q, const Point2 &u, const Point2 &v)
    {
      const int o1 = orientation(p, q, u), o2 = orientation(p, q, v);
      const int o3 = orientation(u, v, p), o4 = orientation(u, v, q);
      return o1 * o2 < 0 && o3 * o4 < 0;
    }
    /// Whether two segments of the polyline that are not neighbours cross:
    /// only segments whose r-ranges overlap can, so a sweep over the segments
    /// by their smallest r compares each with those still open at that r
    /// (linear for a meridian that turns back in r only locally, where every
    /// pair would be quadratic in the samples).
    bool crosses_itself(const std::vector<Point2> &line)
    {
      const std::size_t        segments = line.size() < 2 ? 0 : line.size() - 1;
      std::vector<std::size_t> order(segments), open;
      const auto               r_min = [&](const std::size_t i) {
        return std::min(line[i].r, line[i + 1].r);
      };
      const auto r_max = [&](const std::size_t i) { return std::max(line[i].r, line[i + 1].r); };
      for (std::size_t i = 0; i < segments; ++i)
        order[i] = i;
      std::sort(order.begin(), order.end(),
                [&](const std::size_t a, const std::size_t b) { return r_min(a) < r_min(b); });
      for (const std::size_t i : order)
        {
          open.erase(std::remove_if(open.begin(), open.end(),
                                    [&](const std::size_t j) { return r_max(j) < r_min(i); }),
                     open.end());
          for (const std::size_t j : open)
            if ((i > j ? i - j : j - i) >= 2 &&
                cross(line[std::min(i, j)], line[std::min(i, j) + 1], line[std::max(i, j)],
                      line[std::max(i, j) + 1]))
              return true;
          open.push_back(i);
        }
      return false;
    }
  } // namespace

  int nonphysical_flags(const StepFields &f, const double frame_radius)
  {
    int flags = physical;
    // 1e-9 b: the end sample sits on the frame up to round-off.
    const double tolerance = 1e-9 * frame_radius;
    for (const double r : f.r)
      if (r < -tolerance || r > frame_radius + tolerance)
        flags |= outside_frame;

    // The polyline: the disk from the axis to r(A), then the meridian, with
    // repeated points (the two samples of a ring edge) dropped.
    std::vector<Point2> line;
    if (!f.r.empty())
      line.push_back({0., f.z.front()});
    for (std::size_t i = 0; i < f.r.size(); ++i)
      {
        const Point2 p{f.r[i], f.z[i]};
        if (line.empty() || !(p == line.back()))
          line.push_back(p);
      }
    // A line whose r never decreases cannot cross itself (two segments that
    // are not neighbours share an r only at end points or on a common
    // vertical): O(n), the answer for every usual state.
    bool r_monotone = true;
    for (std::size_t i = 0; i + 1 < line.size() && r_monotone; ++i)
      r_monotone = line[i + 1].r >= line[i].r;
    if (r_monotone)
      return flags;
    if (crosses_itself(line))
      flags |= self_intersection;
    return flags;
  }
} // namespace cdea
