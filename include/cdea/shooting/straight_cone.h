#pragma once
// The straight cone: the continuous limit of partitioning (doc/optimization.md),
// where every point of the film carries just the voltage that makes its hoop
// stress vanish (s2 = 0 everywhere, the field limit off).
//
// With s2 = 0 the paper's eqs. (4) and (5) make R s1 sin(theta) and
// R s1 cos(theta) constant, so theta is constant and the meridian is a straight
// line. With e = eps Phi^2 / H^2 chosen pointwise so that
// s2 = s2_el - e l1^2 l2 = 0, the meridian stress is
// s1 = s1_el - s2_el l2 / l1 =: sigma(l1, l2). For a tension C = R sigma cos(theta)
// (tan(theta) = F / (2 pi H C)) the meridian follows r' = l1 cos(theta) with
// sigma(l1, r/R) = C / (R cos(theta)); C is shot so that r(B) = b, and the
// displacement of the disk is tan(theta) (b - a).

#include <cdea/model/scene.h>

#include <vector>

namespace cdea::shooting
{
  struct StraightCone
  {
    bool   ok           = false; ///< the tension C was found
    double displacement = 0.;    ///< z(A) = tan(theta) (b - a) (m)
    double theta        = 0.;    ///< the cone angle (rad)
    double tension      = 0.;    ///< C = R sigma cos(theta) (N/m^2 times m: Pa m)
    double max_voltage  = 0.;    ///< the largest voltage the profile needs (V)
    std::vector<double> sample_R;       ///< reference radii asked for (m)
    std::vector<double> sample_voltage; ///< the voltage that makes s2 = 0 there (V)
  };

  /// The straight cone of @p scene's film (its Gent constants, pre-stretch,
  /// radii and dead load; the scene's rings and voltages play no part), with
  /// the voltage it needs at each reference radius of @p sample_R (in [A, B]).
  StraightCone straight_cone(const Scene &scene, const std::vector<double> &sample_R = {});
} // namespace cdea::shooting
