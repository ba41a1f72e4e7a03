// The plugins' subsections: Material/Model with the registered laws'
// constants (position 140, after Output, where Material/Model always stood),
// and the registered load terms' entries, those of subsection Reservoir with
// the Reservoir's own (105) and the others after subsection Time (160).

#include <cdea/fe/load_term.h>
#include <cdea/input/parameters.h>

namespace cdea
{
  namespace parameters
  {
    namespace
    {
      /// The registered laws' names as deal.II's selection: "elastic|viscoelastic".
      std::string law_selection()
      {
        std::string names;
        for (const std::string &name : MembraneLaws::names())
          names += (names.empty() ? "" : "|") + name;
        return names;
      }
    } // namespace

    void MaterialLaw::declare(ParameterDeclarations &prm)
    {
      prm.enter_subsection("Material");
      prm.add_choice("Model", LawSettings().model, law_selection(), MembraneLaws::documentation(),
                     [this](const EntryValue &v) { model = std::get<std::string>(v); });
      prm.leave_subsection();
      // Every law's entries, by name: numbers into constants, texts into texts.
      const ParameterDeclarations laws = MembraneLaws::parameters();
      for (EntryDeclaration e : laws.entries())
        {
          if (e.kind == EntryKind::text)
            e.assign = [&text = texts[e.name]](const EntryValue &v) {
              text = std::get<std::string>(v);
            };
          else
            e.assign = [&constant = constants[e.name]](const EntryValue &v) {
              constant = std::get<double>(v);
            };
          prm.append(std::move(e));
        }
    }

    LawSettings MaterialLaw::settings(const MaterialConstants &network_a) const
    {
      LawSettings s;
      s.model     = model;
      s.material  = network_a;
      s.constants = constants;
      s.texts     = texts;
      return s;
    }

    void LoadTermValues::declare(ParameterDeclarations &prm, const bool reservoir)
    {
      const ParameterDeclarations terms = LoadTerms::parameters();
      ParameterDeclarations       which;
      for (const EntryDeclaration &e : terms.entries())
        if ((e.subsection == "Reservoir") == reservoir)
          which.append(e);
      prm.append(which, values);
    }
  } // namespace parameters

  CDEA_REGISTER_PARAMETER_SUBSECTION(
    material_law, 140, [](ParameterDeclarations &prm, Parameters &p) { p.material_law.declare(prm); },
    nullptr)
  CDEA_REGISTER_PARAMETER_SUBSECTION(
    reservoir_load_terms, 105,
    [](ParameterDeclarations &prm, Parameters &p) { p.load_terms.declare(prm, true); }, nullptr)
  CDEA_REGISTER_PARAMETER_SUBSECTION(
    other_load_terms, 160,
    [](ParameterDeclarations &prm, Parameters &p) { p.load_terms.declare(prm, false); }, nullptr)
} // namespace cdea
