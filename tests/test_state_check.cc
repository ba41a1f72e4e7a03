// nonphysical_flags(): meridians built by hand. A cone from the disk edge to
// the frame is possible; one that reaches past the frame or the axis, that
// folds back through itself or through the disk is not; the two samples of a
// ring edge (one point written twice) and a meridian that only touches
// itself at a shared sample are not crossings.

#include <cdea/solver/state_check.h>

#include "check.h"

#include <cmath>

using namespace cdea;
using namespace cdea_test;

namespace
{
  const double a = 14e-3, b = 42e-3;

  /// Fields with the given (r, z) samples (mm); other fields are not looked at.
  StepFields meridian(const std::vector<std::pair<double, double>> &points)
  {
    StepFields f;
    for (const auto &[r, z] : points)
      {
        f.r.push_back(r * 1e-3);
        f.z.push_back(z * 1e-3);
      }
    return f;
  }
} // namespace

CDEA_TEST_MAIN()
{
  // A straight cone, sampled with a ring edge written twice at r = 23.8 mm.
  StepFields cone;
  for (int i = 0; i <= 20; ++i)
    {
      const double r = a + (b - a) * i / 20.;
      cone.r.push_back(r);
      cone.z.push_back(0.02 * (b - r) / (b - a));
      if (i == 7)
        {
          cone.r.push_back(r);
          cone.z.push_back(cone.z.back());
        }
    }
  check(nonphysical_flags(cone, b) == physical, "a cone with a doubled ring-edge sample: possible");

  // The end sample on the frame up to round-off is inside.
  StepFields rounded = cone;
  rounded.r.back() = b * (1. + 1e-13);
  check(nonphysical_flags(rounded, b) == physical, "r(B) = b up to 1e-13: inside the frame");

  // Bulging out beyond the frame radius and back (the far branch of the
  // full electrode reaches r = 100 mm).
  const StepFields bulge = meridian({{14, 20}, {40, 15}, {60, 8}, {50, 3}, {42, 0}});
  check(nonphysical_flags(bulge, b) == outside_frame, "r = 60 mm > b: outside the frame");

  // Through the axis.
  const StepFields axis = meridian({{14, 20}, {-2, 15}, {20, 10}, {42, 0}});
  check(nonphysical_flags(axis, b) == outside_frame, "r < 0: outside the frame");

  // An S that folds back across its own earlier part.
  const StepFields loop = meridian({{14, 20}, {30, 20}, {30, 10}, {20, 10}, {25, 25}, {42, 0}});
  check(nonphysical_flags(loop, b) == self_intersection, "meridian crossing itself");

  // Back through the disk (the disk spans r = 0 .. 14 mm at z(A) = 20 mm).
  const StepFields disk = meridian({{14, 20}, {20, 30}, {8, 25}, {6, 15}, {42, 0}});
  check(nonphysical_flags(disk, b) == self_intersection, "meridian through the disk");

  // Both at once.
  const StepFields both = meridian({{14, 20}, {30, 20}, {30, 10}, {20, 10}, {25, 25}, {50, 5},
                                    {42, 0}});
  check(nonphysical_flags(both, b) == (outside_frame | self_intersection),
        "crossing itself and beyond the frame: both bits");

  // A meridian that comes back to one of its samples without crossing.
  const StepFields touch = meridian({{14, 20}, {30, 20}, {30, 10}, {14, 20}, {42, 0}});
  check(nonphysical_flags(touch, b) == physical, "touching at a shared sample is no crossing");

  return failures() ? 1 : 0;
}
