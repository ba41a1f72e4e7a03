#include <cdea/input/parameters.h>
#include <cdea/input/pump.h>

#include <cmath>
#include <sstream>
#include <string>

namespace cdea
{
  void validate_reservoir(const Parameters &p)
  {
    const auto &r = p.reservoir;
    require_positive(r.width_mm, "Reservoir/Width (mm)");
    require_positive(r.depth_mm, "Reservoir/Depth (mm)");
    require_positive(r.water_volume_ml, "Reservoir/Water volume (ml)");
    require_positive(r.water_density, "Reservoir/Water density (kg/m^3)");
  }

  double tube_area(const Parameters &p)
  {
    return p.reservoir.width_mm * 1e-3 * p.reservoir.depth_mm * 1e-3;
  }

  WaterLoad water_load(const Parameters &p)
  {
    WaterLoad w;
    w.enabled      = p.reservoir.water_load;
    w.density      = p.reservoir.water_density;
    w.gravity      = p.loading.gravity;
    w.water_volume = p.reservoir.water_volume_ml * 1e-6;
    w.tube_area    = tube_area(p);
    return w;
  }
} // namespace cdea
