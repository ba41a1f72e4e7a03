#include <cdea/model/scene.h>

namespace cdea
{
  std::vector<double> Scene::reference_ring_edges() const
  {
    std::vector<double> edges;
    for (const double e : ring_edges_over_a)
      edges.push_back(e * disk_radius / prestretch);
    // The end points are exact, not the product of rounded ratios.
    edges.front() = inner_reference_radius();
    edges.back()  = outer_reference_radius();
    return edges;
  }

  LawSettings Scene::law_settings() const
  {
    LawSettings s;
    s.model     = material_model;
    s.material  = material;
    s.constants = law_constants;
    s.texts     = law_texts;
    return s;
  }

  std::shared_ptr<const MembraneLaw> Scene::law() const
  {
    return make_membrane_law(law_settings());
  }

  unsigned int Scene::ring_of(const double R) const
  {
    const auto   edges = reference_ring_edges();
    unsigned int ring  = 0;
    while (ring + 1 < n_rings() && R >= edges[ring + 1])
      ++ring;
    return ring;
  }

  Scene paper_scene(const std::vector<double>              &ring_edges_over_a,
                    const std::vector<std::vector<double>> &waypoints_kV)
  {
    Scene scene;
    scene.ring_edges_over_a = ring_edges_over_a;
    auto volts              = waypoints_kV;
    for (auto &waypoint : volts)
      for (double &v : waypoint)
        v *= 1e3;
    scene.path = VoltagePath(volts);
    return scene;
  }
} // namespace cdea
