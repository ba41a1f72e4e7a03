#pragma once
// The pump module of Guo et al. 2025 (section 4, figures 10-11): the cone
// actuator under a water reservoir whose level is read in a tube of
// rectangular cross-section. The volume enclosed by the cone grows with the
// voltage, water flows into it and the level in the tube drops by
// (volume change) / (tube cross-section). Subsection Reservoir of the
// parameter file; see doc/pump.md.

#include <cdea/fe/membrane_model.h>

namespace cdea
{
  struct Parameters;

  /// Rejects bad Reservoir entries with an InputError that names the
  /// parameter, e.g. "Reservoir/Width (mm) must be positive, got -3".
  void validate_reservoir(const Parameters &p);

  /// Cross-section width x depth of the level tube (m^2).
  double tube_area(const Parameters &p);

  /// The water load of the Reservoir subsection in SI units (gravity from
  /// Loading); enabled if Reservoir/Water load is true.
  WaterLoad water_load(const Parameters &p);
} // namespace cdea
