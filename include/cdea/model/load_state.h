#pragma once
// The one builder of the load of a scene at its full dead load: the film
// pre-stretched, the whole weight hung and given ring voltages. The voltage
// stage of the load stepper, the time stepper, the rows of a design map, the
// layouts of the optimizer and the data points of a fit all solve at it.

#include <cdea/model/equilibrium_model.h>
#include <cdea/model/scene.h>

#include <vector>

namespace cdea
{
  /// The load of @p scene pre-stretched, under its whole dead load and the
  /// ring voltages @p voltages (V), as stage @p stage (the voltage stage, or
  /// the end of the dead-load stage) at stage parameter @p load_factor.
  LoadState full_load(const Scene &scene, std::vector<double> voltages,
                      double load_factor = 1., Stage stage = Stage::voltage);
} // namespace cdea
