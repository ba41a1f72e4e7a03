// Load terms as plugins (fe/load_term.h, input/parameters_plugins.cc):
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
//    analysis/, design/ or commands/;
//  - the water term gives the liquid column whose inertia the time runs and
//    the small-signal dynamics take (LoadTerm::liquid_column()), a term
//    without one none, and liquid_column() of the parameters takes it with
//    Time/Inertia and Time/Water inertia on.

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
#include <cdea/input/solver_settings.h>

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
      prm.enter_subsection("Loading");
      prm.add_number("Test force (N)", "0", "A force on the disk (0: off).");
      prm.leave_subsection();
    }
    explicit TestForceTerm(const ParameterValues &values) { parse_parameters(values); }

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

  CDEA_REGISTER_PLUGIN(LoadTerms, TestForceTerm, "test force", 0, "a force on the disk")
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
    for (const LoadTerms::Plugin &plugin : LoadTerms::plugins())
      names.push_back(plugin.name);
    const auto has = [&](const std::string &name) {
      return std::find(names.begin(), names.end(), name) != names.end();
    };
    check(has("test force") && has("water") && std::is_sorted(names.begin(), names.end()),
          "the test program's term is registered beside the library's, in name order");
    const std::string file     = default_parameter_file();
    const Parameters  defaults = read("");
    for (const LoadTerms::Plugin &plugin : LoadTerms::plugins())
      {
        ParameterDeclarations declared;
        plugin.declare_parameters(declared);
        bool in_file = true;
        for (const EntryDeclaration &e : declared.entries())
          if (e.declared_here)
            in_file = in_file && file.find("set " + e.name) != std::string::npos;
        check(in_file, plugin.name + ": its entries are in the parameter file");
        check(!plugin.create(defaults.load_terms.values)->active(),
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
    check(held.size() == 2 && !held[0]->liquid_column().present(),
          "a term without a liquid column gives none");
    model->set_load_terms(p.load_terms.values);
    check(model->load_terms().size() == 1 && dynamic_cast<const WaterTerm *>(model->load_terms()[0]),
          "set_load_terms() replaces them");
  }

  /// The water's column: 120 ml, a 10 x 20 mm tube (S = 2e-4 m^2); at
  /// V = 100 ml the free surface stands h = 20 ml / S = 0.1 m above the frame
  /// plane and the column's mass on V is rho h / S = 5e5 kg/m^4.
  void check_liquid_column()
  {
    const std::string water = "subsection Reservoir\n  set Water load = true\n"
                              "  set Water volume (ml) = 120\n  set Width (mm) = 10\nend\n";
    const std::string time  = "subsection Time\n  set Enabled = true\n  set Water inertia = true\n"
                              "end\n";
    const LiquidColumn column = liquid_column(read(water + time));
    check(column.present() && column.density == 1000. &&
            std::abs(column.volume - 120e-6) < 1e-18 && std::abs(column.area - 2e-4) < 1e-18,
          "the water term's column: density, volume and tube");
    check(std::abs(column.mass(100e-6) - 5e5) < 1e-9 * 5e5 &&
            std::abs(column.mass_by_slope(100e-6) - 5e5) < 1e-9 * 5e5,
          "its mass rho h / S in both forms: " + format_number(column.mass(100e-6)) + ", " +
            format_number(column.mass_by_slope(100e-6)) + " kg/m^4");
    check(std::abs(column.mass_per_volume() - 1000. / 4e-8) < 1e-9 * 2.5e10,
          "its slope rho / S^2");
    check(column.mass(130e-6) == 0. && column.mass_by_slope(130e-6) == 0.,
          "an empty tube: no mass");
    check(!liquid_column(read(water + "subsection Time\n  set Enabled = true\nend\n")).present(),
          "without Time/Water inertia: none");
    check(!liquid_column(read(time)).present(), "without the water load: none");
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
  check_liquid_column();
  check_refusals();
  return finish();
}
