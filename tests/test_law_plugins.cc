// Material laws as plugins (material/law_factory.h, input/parameters_plugins.cc):
//  - every registered law is built from its defaults (parameter text that
//    only names it in Material/Model) and from a parameter file that sets its
//    entries;
//  - a law registered here, in the test program, with a constant of its own
//    becomes a value of Material/Model with its entry and documentation in the
//    parameter file, its constant is read from the file, its range check
//    names the entry, the FE model of a run takes it, and the shooting model
//    and the design studies refuse it by name: a new law touches no file of
//    input/, analysis/, design/ or commands/.

#include <cdea/analysis/run_input.h>
#include <cdea/analysis/run_setup.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/design/sweep.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/input/validation.h>
#include <cdea/material/gent_law.h>
#include <cdea/material/law_factory.h>
#include <cdea/material/two_network_gent.h>

#include "check.h"

#include <algorithm>
#include <memory>
#include <string>

namespace cdea
{
  /// The Gent law with its shear modulus times "Test stiffening factor".
  class StiffenedGentLaw final : public MembraneLaw
  {
  public:
    StiffenedGentLaw(MaterialConstants film, const double factor)
      : gent([&] {
        film.shear_modulus *= factor;
        return film;
      }())
      , factor(factor)
    {}

    static void declare_parameters(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Material");
      prm.add_number("Test stiffening factor", "2",
                     "Shear modulus of the test law over Shear modulus.");
      prm.leave_subsection();
    }

    static std::shared_ptr<const MembraneLaw> create(const LawSettings &settings)
    {
      const double f = settings.constant("Test stiffening factor");
      if (!(f > 0. && f <= 10.))
        throw InputError("Material/Test stiffening factor must be above 0 and at most 10, got " +
                         format_number(f));
      return std::make_shared<StiffenedGentLaw>(settings.material, f);
    }

    bool evaluate(const LawInput &input, const InternalStep &step, const unsigned int request,
                  LawResponse &response) const override
    {
      return gent.evaluate(input, step, request, response);
    }
    double max_hoop_stretch(const double l1) const override { return gent.max_hoop_stretch(l1); }

    const GentDielectricLaw gent;
    const double            factor;
  };

  CDEA_REGISTER_PLUGIN(MembraneLaws, StiffenedGentLaw, "stiffened test", 0,
                       "the test program's Gent law, stiffer by Test stiffening factor.")
} // namespace cdea

using namespace cdea;
using namespace cdea_test;

namespace
{
  /// Parameter text naming @p model, with a time run (which every law allows).
  std::string law_text(const std::string &model, const std::string &more = "")
  {
    return "subsection Material\n  set Model = " + model + "\n" + more +
           "end\nsubsection Time\n  set Enabled = true\nend\n";
  }

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
} // namespace

CDEA_TEST_MAIN()
{
  const std::vector<std::string> names = MembraneLaws::names();
  const auto has = [&](const std::string &name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  check(has("elastic") && has("stiffened test") && has("viscoelastic"),
        "the test program's law is registered beside the library's");

  std::cout << "Every law from its defaults\n";
  for (const std::string &name : MembraneLaws::names())
    {
      const Parameters p   = read_parameters(ParameterInput::text(law_text(name)));
      const auto       law = make_membrane_law(p.material_law.settings(p.scene().material));
      check(law != nullptr && p.material_law.model == name, name + " built from its defaults");
    }

  std::cout << "Laws from a parameter file that sets their entries\n";
  {
    const Parameters p = read_parameters(ParameterInput::text(
      law_text("viscoelastic", "  set Relaxation time (s) = 0.5\n  set Network B Jlim = 60\n")));
    const auto  law = make_membrane_law(p.material_law.settings(p.scene().material));
    const auto *two = dynamic_cast<const TwoNetworkGentLaw *>(law.get());
    check(two && two->network_b().relaxation_time == 0.5 && two->network_b().jlim == 60. &&
            two->network_b().shear_modulus == 45e3,
          "viscoelastic: network B from the file (and the default shear modulus)");
  }
  {
    const Parameters p = read_parameters(
      ParameterInput::text(law_text("stiffened test", "  set Test stiffening factor = 3\n")));
    const auto  law = make_membrane_law(p.material_law.settings(p.scene().material));
    const auto *own = dynamic_cast<const StiffenedGentLaw *>(law.get());
    check(own && own->factor == 3. && own->gent.constants().shear_modulus == 3. * 25.1e3,
          "the test law's constant from the file");
  }

  std::cout << "The test law in the parameter file\n";
  const std::string file = default_parameter_file();
  check(file.find("set Test stiffening factor") != std::string::npos,
        "its entry is declared in subsection Material");
  const std::string json = default_parameter_file(ParameterFormat::json);
  check(json.find("'stiffened test': the test program's Gent law") != std::string::npos,
        "Material/Model's documentation describes it");
  std::string selection;
  for (const std::string &name : names)
    selection += (selection.empty() ? "" : "|") + name;
  check(json.find("[Selection " + selection + " ]") != std::string::npos &&
          selection.find("stiffened test") != std::string::npos,
        "Material/Model's selection lists it: " + selection);

  std::cout << "Its range check, the FE model and the refusals\n";
  const std::string range = input_error([] {
    read_parameters(
      ParameterInput::text(law_text("stiffened test", "  set Test stiffening factor = 20\n")));
  });
  check(range == "Material/Test stiffening factor must be above 0 and at most 10, got 20",
        "out of range: " + range);
  const std::string quasi_static = "subsection Material\n  set Model = stiffened test\nend\n";
  const Parameters  p            = read_parameters(ParameterInput::text(quasi_static));
  const auto        model        = make_fe_model(p, p.scene());
  check(dynamic_cast<const StiffenedGentLaw *>(&model->material_law()) != nullptr,
        "a quasi-static run's FE model has the law of Material/Model");
  const std::string shoot =
    input_error([&] { run_input(p, quasi_static, RunMethod::shooting, "shoot"); });
  check(shoot == "Material/Model = stiffened test is implemented in the FE model only: use "
                 "'cdea run', or set it to elastic for 'cdea shoot'",
        "shoot refuses it: " + shoot);
  const std::string fit = input_error([&] { require_quasi_static_elastic(p, "fit"); });
  check(fit == "Material/Model = stiffened test is not supported by cdea fit: its "
               "sensitivities are those of the elastic law (use elastic)",
        "fit refuses it: " + fit);
  const std::string sweep = input_error([&] { sweep_settings(p, p.scene()); });
  check(sweep == "Material/Model = stiffened test is not supported by cdea sweep: the maps are "
                 "of the film's Gent law (use elastic)",
        "sweep refuses it: " + sweep);
  return finish();
}
