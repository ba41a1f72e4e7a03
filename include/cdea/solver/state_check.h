#pragma once
// Is a computed state physically possible for the actuator? The membrane
// equations know nothing of the frame or of the film's other parts, so
// far along a solution curve (past the second fold of the full electrode)
// they have states whose meridian reaches beyond the frame or passes through
// itself or the disk. Such states are flagged, not removed.

#include <cdea/model/records.h>

namespace cdea
{
  /// Bits of nonphysical_flags().
  enum NonPhysical : int
  {
    physical           = 0,
    outside_frame      = 1, ///< some r < 0 or r > b
    self_intersection  = 2  ///< the meridian crosses itself or the disk
  };

  /// The NonPhysical bits of the sampled meridian @p fields (r, z; SI) of a
  /// film held by a frame of inner radius @p frame_radius (m). The check sees
  /// the samples only: a crossing between two samples is judged from the
  /// straight segments joining them.
  int nonphysical_flags(const StepFields &fields, double frame_radius);
} // namespace cdea
