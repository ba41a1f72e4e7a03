// A synthetic material test made by the program's own material point
// (material/material_point.h) of the film of a parameter file: the film
// pulled from stretch 1 to PEAK at RATE (1/s), held HOLD seconds, and
// returned to stretch 1 at RATE, sampled every STEP seconds, with Gaussian
// noise of NOISE kPa (seed SEED) on the nominal stress. Prints the CSV
// that `cdea fit` reads (design/material_test_data.h), with a comment
// saying how it was made; the tests and prm/fit-material.prm's data come
// from it:
//
//   material_history FILE.prm KIND PEAK RATE HOLD STEP NOISE SEED [Subsection/Entry=value ...]
//
// The entries after SEED set the film's constants over the file's (the true
// constants of a synthetic test, the file holding a fit's start).
// KIND: uniaxial, equibiaxial or pure_shear. Exit 1 with a message on bad
// arguments or a history the law cannot follow.

#include <cdea/base/format.h>
#include <cdea/base/units.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/material/material_point.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>

using namespace cdea;

namespace
{
  /// The ramp-hold-return history: the stretch at time t.
  double stretch_at(const double t, const double peak, const double rate, const double hold)
  {
    const double ramp = (peak - 1.) / rate;
    if (t <= ramp)
      return 1. + rate * t;
    if (t <= ramp + hold)
      return peak;
    return std::max(1., peak - rate * (t - ramp - hold));
  }

  int make(int argc, char **argv)
  {
    const std::string kind_text = argv[2];
    const double      peak = std::stod(argv[3]), rate = std::stod(argv[4]);
    const double      hold = std::stod(argv[5]), step = std::stod(argv[6]);
    const double      noise = std::stod(argv[7]);
    const unsigned    seed  = unsigned(std::stoul(argv[8]));
    StretchHistory    h;
    if (kind_text == "equibiaxial")
      h.kind = TestKind::equibiaxial;
    else if (kind_text == "pure_shear")
      h.kind = TestKind::pure_shear;
    else if (kind_text != "uniaxial")
      throw std::invalid_argument("KIND must be uniaxial, equibiaxial or pure_shear");
    if (!(peak > 1. && rate > 0. && hold >= 0. && step > 0.))
      throw std::invalid_argument("PEAK > 1, RATE > 0, HOLD >= 0 and STEP > 0 are needed");
    const double       end = 2. * (peak - 1.) / rate + hold;
    const unsigned int n   = unsigned(std::ceil(end / step - 1e-9));
    for (unsigned int i = 0; i <= n; ++i)
      {
        h.time.push_back(std::min(end, i * step));
        h.stretch.push_back(stretch_at(h.time.back(), peak, rate, hold));
      }
    ParameterInput input = ParameterInput::file(argv[1]);
    for (int i = 9; i < argc; ++i)
      {
        const std::string setting = argv[i];
        const std::size_t equal   = setting.find('=');
        if (equal == std::string::npos)
          throw std::invalid_argument("'" + setting + "': expected Subsection/Entry=value");
        input.overrides.emplace_back(setting.substr(0, equal), setting.substr(equal + 1));
      }
    const Parameters    p   = read_parameters(input);
    const auto          law = p.scene().law();
    MaterialPoint       point(*law);
    MaterialPointResult r;
    std::string         why;
    if (!point.run(h, {}, r, why))
      throw std::runtime_error("the law cannot follow the history: " + why);
    std::mt19937                     random(seed);
    std::normal_distribution<double> gaussian(0., noise);
    std::cout << "# Made by material_history (tests/material_history.cc):";
    for (int i = 1; i < argc; ++i) // quoted where the shell needs it
      std::cout << ' ' << (std::string(argv[i]).find(' ') != std::string::npos ?
                             "'" + std::string(argv[i]) + "'" :
                             std::string(argv[i]));
    std::cout << "\n# the material point of the file's film, noise " << format_number(noise)
              << " kPa (seed " << seed << ")\ntime_s, " << kind_text << "_stretch, "
              << "nominal_stress_kPa\n";
    for (std::size_t i = 0; i < h.time.size(); ++i)
      {
        const double stress = units::kPa.from_si(r.stress[i]) + (noise > 0. ? gaussian(random) : 0.);
        std::cout << format_number(h.time[i], 10) << ", " << format_number(h.stretch[i], 10)
                  << ", " << format_number(stress, 10) << '\n';
      }
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  if (argc < 9)
    {
      std::cerr << "usage: material_history FILE.prm KIND PEAK RATE HOLD STEP NOISE SEED "
                   "[Subsection/Entry=value ...]\n";
      return 1;
    }
  try
    {
      return make(argc, argv);
    }
  catch (const std::exception &e)
    {
      std::cerr << "material_history: " << e.what() << '\n';
      return 1;
    }
}
