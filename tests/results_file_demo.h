#pragma once
// The demo run shared by the ResultsFile tests: a 2-ring summary, fields and
// extra columns per step, an onset record and the parameters text.

#include <cdea/output/results_file.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "check.h"

namespace results_file_demo
{
  using namespace cdea_test;

  inline const double nan_value = std::numeric_limits<double>::quiet_NaN();

  inline const std::string parameters_text =
    "subsection Material\n  set Shear modulus (kPa) = 25.1\nend\n";

  // ---------------------------------------------------------------- data
  inline cdea::StepSummary demo_summary(const unsigned int i)
  {
    cdea::StepSummary s;
    s.stage             = i == 0 ? cdea::Stage::dead_load : cdea::Stage::voltage;
    s.load_factor       = 0.25 + 0.5 * i;
    s.voltages          = {1000. * i + 100., 2000. * i + 300.};
    s.mass              = 0.28 + 0.01 * i;
    s.displacement      = (18.2 + i) * 1e-3;
    s.stroke            = i == 0 ? nan_value : 0.5e-3 * i;
    s.s2_min            = -1000. + 3000. * i;
    s.s2_ring_inner     = {67000. + 10. * i, 12000. - 20. * i};
    s.wrinkled          = i == 2;
    s.newton_iterations = 3 + i;
    return s;
  }

  inline unsigned int demo_n_samples(const unsigned int i) { return 4 + i; }

  inline cdea::StepFields demo_fields(const unsigned int i)
  {
    cdea::StepFields  f;
    const auto        s = demo_summary(i);
    const unsigned int n = demo_n_samples(i);
    for (unsigned int j = 0; j < n; ++j)
      {
        const int ring = j < n / 2 ? 0 : 1;
        f.R.push_back((5.6 + 0.3 * j + 0.01 * i) * 1e-3);
        f.r.push_back(1.3 * f.R.back() + 1e-6 * i);
        f.z.push_back(-(2. + j + 0.1 * i) * 1e-3);
        f.theta.push_back(0.1 * j + 0.01 * i);
        f.lambda1.push_back(2.5 + 0.01 * j + 0.001 * i);
        f.lambda2.push_back(2.4 - 0.02 * j + 0.002 * i);
        f.s1.push_back(50000. + 100. * j + i);
        f.s2.push_back(20000. - 5000. * j + i);
        f.E.push_back(5e6 * (1. + 0.1 * j) + i);
        f.Phi.push_back(s.voltages[ring]);
        f.ring.push_back(ring);
      }
    return f;
  }

  inline std::vector<std::pair<std::string, double>> demo_extra(const unsigned int i)
  {
    // volume_mm3 appears from the second step on; energy_mJ only in the first.
    if (i == 0)
      return {{"energy_mJ", 7.5}};
    return {{"volume_mm3", 1234.5 + i}};
  }

  inline const std::vector<std::pair<std::string, std::string>> demo_root_attributes = {
    {"solver", "shooting"}, {"prm_file", "prm/test.prm"}};

  inline cdea::OnsetRecord demo_onset()
  {
    cdea::OnsetRecord o;
    o.found    = true;
    o.voltages = {5432.1, 6543.2};
    o.radius   = 19.6e-3;
    return o;
  }

  inline void write_demo(const std::string &path, const unsigned int n_steps, const bool with_onset)
  {
    cdea::ResultsFile file(path, parameters_text, 2, demo_root_attributes);
    file.describe_column("volume_mm3", "mm3", "enclosed volume");
    for (unsigned int i = 0; i < n_steps; ++i)
      file.append(demo_summary(i), demo_fields(i), demo_extra(i));
    file.set_summary_attribute("limit_point_kV", {1., 2., 3.});
    file.set_summary_attribute("limit_point_kV", {6.5, 7.25}); // overwrite, new length
    if (with_onset)
      file.write_onset(demo_onset());
    const auto done = file.finish("complete");
    check(done.written && done.file == path && done.steps_written == n_steps,
          "finish() writes every step to the path");
  }
} // namespace results_file_demo
