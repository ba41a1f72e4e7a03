#include <cdea/model/load_state.h>

#include <utility>

namespace cdea
{
  LoadState full_load(const Scene &scene, std::vector<double> voltages, const double load_factor,
                      const Stage stage)
  {
    LoadState l;
    l.stage       = stage;
    l.load_factor = load_factor;
    l.stretch     = scene.prestretch;
    l.mass        = scene.mass;
    l.force       = scene.dead_load();
    l.voltages    = std::move(voltages);
    return l;
  }
} // namespace cdea
