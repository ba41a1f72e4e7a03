// Load terms as plugins (fe/load_term.h, input/parameters_plugins.h):
//  - every registered term declares its entries in the parameter file, is
//    built from its defaults (off: a file without its entries runs as before)
//    and from a parameter file that switches it on;
//  - the FE model of a run holds the terms the file switches on, in the
//    registry's order (by name), and set_load_terms() replaces them;
//  - a term registered here, in the test program, that supports nothing
//    beyond the quasi-static FE run is refused generically, naming its entry
//    and how to switch it off: with a time run, arc length or the stability
//    check, by the shooting model (shoot, compare) and by the design studies
//    (sweep, optimize, fit). A new term touches no file of input/,
//    analysis/, design/ or commands/.

#include <cdea/analysis/run_input.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/design/fit.h>
#include <cdea/design/optimize.h>
#include <cdea/design/sweep.h>
#include <cdea/fe/load_term.h>
#include <cdea/fe/water_term.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>

#include "check.h"

#include <algorithm>
#include <memory>
#include <string>

namespace cdea
{
  /// A force on the disk, -F z(A), beside the dead load: on when
  /// Loading/Test force (N) is not 0; supports nothing beyond the
  /// quasi-static FE run.
  class TestForceTerm final : public LoadTerm
  {
  public:
    static void declare_parameters(ParameterDeclarations &prm)
    {
      prm.declare_number("Loading", "Test force (N)", "0", "A force on the disk (0: off).");
    }
    void parse_parameters(const ParameterValues &values) override
    {
      force = values.number("Loading/Test force (N)");
      if (!(std::abs(force) <= 1e3))
        throw InputError("Loading/Test force (N) must be between -1000 and 1000, got " +
                         format_number(force));
    }
    bool        active() const override { return force != 0.; }
    std::string switched_on() const override
    {
      return "Loading/Test force (N) = " + format_number(force);
    }
    std::string off_value() const override { return "0"; }

    bool add_cell(const CellInput &in, unsigned int, CellScratch &, CellContribution &out) override
    {
      if (in.index != 0)
        return true;
      for (unsigned int i = 0; i < in.mesh->dofs_per_cell(); ++i)
        if (in.mesh->component[i] == 1)
          {
            out.energy -= force * in.mesh->left_end.value[i] * in.x[i];
            out.residual[i] -= force * in.mesh->left_end.value[i];
          }
      return true;
    }

    double force = 0.;
  };

  CDEA_REGISTER_LOAD_TERM(TestForceTerm, "test force", 0)
} // namespace cdea

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// The InputError of @p f ("" if none).
  template <typename F>
  std::string input_error(F &&f)
  {
    try
      {
        f();
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  Parameters read(const std::string &text)
  {
    return read_parameters(ParameterInput::text(text));
  }

  /// The test force switched on, with the stability check off.
  const std::string test_force = "subsection Loading\n  set Test force (N) = 0.5\nend\n"
                                 "subsection Solver\n  set Stability check = false\nend\n";

  /// Every registered term: declared, off by default, on from a file.
  void check_registered_terms()
  {
    std::vector<std::string> names;
    for (const LoadTermPlugin &plugin : load_term_plugins())
      names.push_back(plugin.name);
    const auto has = [&](const std::string &name) {
      return std::find(names.begin(), names.end(), name) != names.end();
    };
    check(has("test force") && has("water") && std::is_sorted(names.begin(), names.end()),
          "the test program's term is registered beside the library's, in name order");
    const std::string file     = default_parameter_file();
    const Parameters  defaults = read("");
    for (const LoadTermPlugin &plugin : load_term_plugins())
      {
        ParameterDeclarations declared;
        plugin.declare_parameters(declared);
        bool in_file = true;
        for (const EntryDeclaration &e : declared.entries())
          if (e.declared_here)
            in_file = in_file && file.find("set " + e.name) != std::string::npos;
        check(in_file, plugin.name + ": its entries are in the parameter file");
        check(!parse_load_term(plugin, defaults.load_terms.values)->active(),
              plugin.name + ": built from its defaults, and off");
      }
    check(make_fe_model(defaults, defaults.scene())->load_terms().empty(),
          "a file without the terms' entries: no load term in the model");
  }

  /// The water term from a parameter file; the model's terms in order.
  void check_water_from_file()
  {
    const Parameters p = read("subsection Reservoir\n  set Water load = true\n"
                              "  set Water volume (ml) = 120\n  set Width (mm) = 10\nend\n");
    const auto       terms = make_load_terms(p.load_terms.values);
    const auto      *water = terms.size() == 1 ? dynamic_cast<const WaterTerm *>(terms[0].get()) :
                                                 nullptr;
    check(water && water->water().water_volume == 120. * 1e-6 &&
            water->water().tube_area == 10. * 1e-3 * 20. * 1e-3 && water->water().gravity == 9.81,
          "water: its entries, the tube and gravity read from the file");
    check(water && water->describe() == "Water load: 120 ml of density 1000 kg/m^3 above the "
                                        "membrane, level tube 10 x 20 mm",
          "water: its line for cdea run");

    const Parameters both = read(test_force + "subsection Reservoir\n  set Water load = true\nend\n");
    auto             model = make_fe_model(both, both.scene());
    const auto       held  = model->load_terms();
    check(held.size() == 2 && dynamic_cast<const TestForceTerm *>(held[0]) &&
            dynamic_cast<const WaterTerm *>(held[1]),
          "the model holds both terms switched on, in the registry's order");
    model->set_load_terms(p.load_terms.values);
    check(model->load_terms().size() == 1 && dynamic_cast<const WaterTerm *>(model->load_terms()[0]),
          "set_load_terms() replaces them");
  }

  /// The test force, which supports nothing, refused generically.
  void check_refusals()
  {
    check(input_error([] { read(test_force); }).empty(), "the test force runs quasi-statically");
    const std::string with_stability =
      input_error([] { read("subsection Loading\n  set Test force (N) = 0.5\nend\n"); });
    check(with_stability == "Loading/Test force (N) = 0.5 is not supported with Solver/Stability "
                            "check = true (use 0)",
          "stability check: " + with_stability);
    const std::string with_time =
      input_error([] { read(test_force + "subsection Time\n  set Enabled = true\nend\n"); });
    check(with_time == "Loading/Test force (N) = 0.5 is not supported with Time/Enabled = true "
                       "(use 0)",
          "time run: " + with_time);
    const std::string with_arc_length = input_error(
      [] { read(test_force + "subsection Solver\n  set Continuation = arc length\nend\n"); });
    check(with_arc_length == "Loading/Test force (N) = 0.5 is not supported with "
                             "Solver/Continuation = arc length (use 0)",
          "arc length: " + with_arc_length);
    const std::string range =
      input_error([] { read("subsection Loading\n  set Test force (N) = 2000\nend\n"); });
    check(range == "Loading/Test force (N) must be between -1000 and 1000, got 2000",
          "its range check: " + range);

    const Parameters  p     = read(test_force);
    const std::string shoot = input_error([&] { run_input(p, "", RunMethod::shooting, "compare"); });
    check(shoot == "Loading/Test force (N) = 0.5 is implemented in the FE model only: use 'cdea "
                   "run', or set it to 0 for 'cdea compare'",
          "compare: " + shoot);
    const std::string sweep = input_error([&] { sweep_settings(p, p.scene()); });
    check(sweep == "Loading/Test force (N) = 0.5 is not supported by cdea sweep: the maps are of "
                   "the actuator under its dead load alone (use 0)",
          "sweep: " + sweep);
    const std::string optimize = input_error([&] { optimization_settings(p, p.scene()); });
    check(optimize == "Loading/Test force (N) = 0.5 is not supported by cdea optimize: the "
                      "layouts are designed for the actuator under its dead load (use 0)",
          "optimize: " + optimize);
    const std::string fit = input_error([&] { fit_settings(p); });
    check(fit == "Loading/Test force (N) = 0.5 is not supported by cdea fit: it fits the "
                 "displacement of the actuator under its dead load (use 0)",
          "fit: " + fit);
  }
} // namespace

CDEA_TEST_MAIN()
{
  check_registered_terms();
  check_water_from_file();
  check_refusals();
  return finish();
}
