#pragma once
// The entries that plugins declare (base/parameter_declarations.h), made
// entries of deal.II's ParameterHandler: Material/Model with the registered
// material laws (material/law_factory.h) and their constants, and the entries
// of the registered load terms (fe/load_term.h). The core lists no plugin:
// the selection of Material/Model, its documentation and the entries come
// from the registries.

#include <cdea/base/parameter_declarations.h>
#include <cdea/fe/load_term.h>
#include <cdea/material/law_factory.h>

#include <functional>
#include <map>
#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{
  /// Declares the entries of @p declarations that are declared here
  /// (EntryDeclaration::declared_here) and that @p which accepts, in their
  /// order: numbers as Patterns::Double(), flags as Patterns::Bool().
  void declare_plugin_entries(dealii::ParameterHandler &prm,
                              const ParameterDeclarations &declarations,
                              const std::function<bool(const EntryDeclaration &)> &which);

  /// The values of every entry of @p declarations (also those read only).
  ParameterValues read_plugin_entries(dealii::ParameterHandler   &prm,
                                      const ParameterDeclarations &declarations);

  namespace parameters
  {
    /// Material/Model and the entries the registered laws declare in
    /// subsection Material.
    struct MaterialLaw
    {
      std::string                   model;     ///< a registered law's name
      std::map<std::string, double> constants; ///< every law's number entries, by name
      std::map<std::string, std::string> texts; ///< every law's text entries, by name
      static void                   declare(dealii::ParameterHandler &prm);
      void                          parse(dealii::ParameterHandler &prm);

      /// The settings of the law, with @p network_a (the film's constants, SI).
      LawSettings settings(const MaterialConstants &network_a) const;
    };

    /// The entries the registered load terms declare, and those of the core
    /// they read, by path: what MembraneModel::set_load_terms() and the
    /// checks of validation.h build the terms from.
    struct LoadTerms
    {
      ParameterValues values;
      /// Declares the terms' entries that @p which accepts (Parameters::declare()
      /// places those of subsection Reservoir with the Reservoir's own).
      static void declare(dealii::ParameterHandler                            &prm,
                          const std::function<bool(const EntryDeclaration &)> &which);
      void        parse(dealii::ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace cdea
