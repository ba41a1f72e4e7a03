#include <cdea/base/format.h>
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

  Scene spectrum_scene(Scene base, const std::vector<double> &moduli_kPa,
                       const std::vector<double> &times_s, const double branch_jlim)
  {
    const auto list = [](const std::vector<double> &values) {
      std::string text;
      for (const double v : values)
        text += (text.empty() ? "" : ", ") + format_number(v, 17);
      return text;
    };
    base.material_model = "viscoelastic";
    // The one-branch entries are read (Network B Jlim: every branch's).
    base.law_constants["Network B shear modulus (kPa)"] = moduli_kPa.empty() ? 1. : moduli_kPa[0];
    base.law_constants["Network B Jlim"]                = branch_jlim;
    base.law_constants["Relaxation time (s)"]           = times_s.empty() ? 1. : times_s[0];
    base.law_texts["Branch shear moduli (kPa)"]         = list(moduli_kPa);
    base.law_texts["Branch relaxation times (s)"]       = list(times_s);
    return base;
  }
} // namespace cdea
