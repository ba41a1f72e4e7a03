#pragma once
// The twelve validation scenes of the FE/shooting agreement (doc/validation.md,
// "Agreement"), shared by tests/test_validation_agreement.cc (the Gent law)
// and tests/test_law_agreement.cc (the other laws of the library).

#include <cdea/model/scene.h>

#include "scenes.h"

#include <string>
#include <vector>

namespace cdea_test
{
  using cdea::Scene;

  struct Case
  {
    std::string name;
    Scene       scene;
    bool        onset_expected = false;
    /// model-notes.md values (empty if none): displacement (mm), s2/mu per ring.
    double              public_displacement_mm = 0.;
    std::vector<double> public_s2_over_mu;
  };

  inline Case make_case(const std::string &name, const Scene &scene, const bool onset = false,
                        const double displacement_mm = 0., const std::vector<double> &s2 = {})
  {
    return Case{name, scene, onset, displacement_mm, s2};
  }

  /// The twelve scenes.
  inline std::vector<Case> cases()
  {
    std::vector<Case> c;
    // Public cases (model-notes.md).
    c.push_back(make_case("public: full electrode, 0 V", paper_scene({1., 3.}, {{0.}}), false,
                          18.24876, {2.67049}));
    c.push_back(make_case("public: full electrode, 5 kV", paper_scene({1., 3.}, {{5.}}), false,
                          23.79359, {0.56700}));
    c.push_back(make_case("public: r_v/a = 1.7, 5/5 then 5/6 kV",
                          paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 6.}}), false, 25.65070,
                          {0.62767, 0.65406}));
    // Own scenes.
    {
      Scene s        = paper_scene({1., 4.}, {{4.5}});
      s.disk_radius  = 10e-3;
      s.frame_radius = 40e-3;
      s.prestretch   = 3.;
      c.push_back(make_case("geometry: a = 10 mm, b/a = 4, lam_pre = 3, to 4.5 kV", s, true));
    }
    {
      Scene s    = paper_scene({1., 3.}, {{2.8}});
      s.material = {50e3, 60., 4.5e-11, 0.5e-3};
      c.push_back(
        make_case("material: mu = 50 kPa, Jlim = 60, eps = 4.5e-11, H = 0.5 mm, to 2.8 kV", s));
    }
    {
      Scene s = paper_scene({1., 1.5, 3.}, {{4., 4.}, {4., 5.5}});
      s.mass  = 0.1;
      c.push_back(make_case("mass 100 g: r_v/a = 1.5, 4/4 then 4/5.5 kV", s));
    }
    {
      Scene s = paper_scene({1., 3.}, {{6.}});
      s.mass  = 0.5;
      c.push_back(make_case("mass 500 g: full electrode to 6 kV", s, true));
    }
    c.push_back(make_case("three rings 1-1.5-2.2-3: 4/4/4 then 4/5/6 kV",
                          paper_scene({1., 1.5, 2.2, 3.}, {{4., 4., 4.}, {4., 5., 6.}})));
    c.push_back(make_case("three rings 1-1.4-2-3: 4.5/4.5/4.5 then 4.5/5.5/7 kV",
                          paper_scene({1., 1.4, 2., 3.}, {{4.5, 4.5, 4.5}, {4.5, 5.5, 7.}}),
                          true));
    {
      Scene s      = paper_scene({1., 1.3, 1.8, 2.4, 3.}, {{3., 3., 3., 3.}, {3., 3.5, 4., 4.5}});
      s.prestretch = 2.;
      c.push_back(make_case("four rings, lam_pre = 2: 3/3/3/3 then 3/3.5/4/4.5 kV", s));
    }
    c.push_back(make_case("paper: full electrode to 5.5 kV (onset)",
                          paper_scene({1., 3.}, {{5.5}}), true));
    c.push_back(make_case("paper: r_v/a = 1.7, 5/5 then 5/7 kV (onset)",
                          paper_scene({1., 1.7, 3.}, {{5., 5.}, {5., 7.}}), true));
    return c;
  }

  struct Run
  {
    cdea::RunResult   result;
    cdea::StepSummary last;
    cdea::StepFields  fields;
  };

  /// All load stages of @p scene with @p model, the onset located to 1e-4 V.
  inline Run run(cdea::EquilibriumModel &model, const cdea::Scene &scene)
  {
    cdea::SteppingSettings settings;
    settings.onset_tolerance = 1e-4; // V
    cdea::LoadStepper      stepper(scene, model, settings);
    Run                    out;
    stepper.on_step = [&](const cdea::StepSummary &s) { out.last = s; };
    out.result      = stepper.run();
    out.fields      = model.fields();
    return out;
  }
} // namespace cdea_test
