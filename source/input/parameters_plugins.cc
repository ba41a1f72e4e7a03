#include <deal.II/base/parameter_handler.h>

#include <cdea/input/parameters_plugins.h>

namespace cdea
{
  using dealii::ParameterHandler;

  void declare_plugin_entries(ParameterHandler &prm, const ParameterDeclarations &declarations,
                              const std::function<bool(const EntryDeclaration &)> &which)
  {
    for (const EntryDeclaration &e : declarations.entries())
      if (e.declared_here && which(e))
        {
          prm.enter_subsection(e.subsection);
          if (e.kind == EntryKind::flag)
            prm.declare_entry(e.name, e.default_value, dealii::Patterns::Bool(), e.documentation);
          else if (e.kind == EntryKind::text)
            prm.declare_entry(e.name, e.default_value, dealii::Patterns::Anything(),
                              e.documentation);
          else
            prm.declare_entry(e.name, e.default_value, dealii::Patterns::Double(),
                              e.documentation);
          prm.leave_subsection();
        }
  }

  ParameterValues read_plugin_entries(ParameterHandler &prm, const ParameterDeclarations &declarations)
  {
    ParameterValues values;
    for (const EntryDeclaration &e : declarations.entries())
      {
        prm.enter_subsection(e.subsection);
        if (e.kind == EntryKind::flag)
          values.set_flag(e.path(), prm.get_bool(e.name));
        else if (e.kind == EntryKind::text)
          values.set_text(e.path(), prm.get(e.name));
        else
          values.set_number(e.path(), prm.get_double(e.name));
        prm.leave_subsection();
      }
    return values;
  }

  namespace parameters
  {
    namespace
    {
      /// The registered laws' names as deal.II's selection: "elastic|viscoelastic".
      std::string law_selection()
      {
        std::string names;
        for (const std::string &name : membrane_law_names())
          names += (names.empty() ? "" : "|") + name;
        return names;
      }
    } // namespace

    void MaterialLaw::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("Model", LawSettings().model, dealii::Patterns::Selection(law_selection()),
                        membrane_law_documentation());
      prm.leave_subsection();
      declare_plugin_entries(prm, membrane_law_parameters(),
                             [](const EntryDeclaration &) { return true; });
    }

    void MaterialLaw::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      model = prm.get("Model");
      prm.leave_subsection();
      constants.clear();
      texts.clear();
      const ParameterDeclarations laws = membrane_law_parameters();
      const ParameterValues       values = read_plugin_entries(prm, laws);
      for (const EntryDeclaration &e : laws.entries())
        if (e.kind == EntryKind::text)
          texts[e.name] = values.text(e.path());
        else
          constants[e.name] = values.number(e.path());
    }

    void LoadTerms::declare(ParameterHandler                                    &prm,
                            const std::function<bool(const EntryDeclaration &)> &which)
    {
      declare_plugin_entries(prm, load_term_parameters(), which);
    }

    void LoadTerms::parse(ParameterHandler &prm)
    {
      values = read_plugin_entries(prm, load_term_parameters());
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
  } // namespace parameters
} // namespace cdea
