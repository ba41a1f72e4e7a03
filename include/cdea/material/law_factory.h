#pragma once
// The material laws as plugins of Material/Model, in the manner of ASPECT's
// material models: each law is a plugin of MembraneLaws (base/plugin_list.h)
// and registers itself at the end of its own source file, inside namespace
// cdea, with one line,
//
//   CDEA_REGISTER_PLUGIN(MembraneLaws, TwoNetworkGentLaw, "viscoelastic", 0, "description")
//
// and the core lists no law by hand. The class gives two static functions:
//
//   static void declare_parameters(ParameterDeclarations &prm);
//     its entries of subsection Material (MembraneLaw's default: none);
//   static std::shared_ptr<const MembraneLaw> create(const LawSettings &);
//     its constants taken from the settings and checked (InputError naming
//     the entry and what is allowed), the law built.
//
// Material/Model's selection is the registered names, its documentation the
// laws' descriptions ("'NAME': description", in name order); input/ declares
// and reads the entries (input/parameters_plugins.cc), so a law with
// constants of its own touches no file outside its own. The settings are
// plain data (no deal.II). The law files are linked whole into every program
// (an object library in CMakeLists.txt), so that no registration is dropped
// by the linker.

#include <cdea/base/plugin_list.h>
#include <cdea/material/gent_dielectric.h>
#include <cdea/material/membrane_law.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  /// What a law is built from.
  struct LawSettings
  {
    /// Material/Model: the name a law is registered under; the default is the
    /// law of the FE model, the shooting model and the design studies.
    std::string       model = "elastic";
    MaterialConstants material{}; ///< the film's Gent law and dielectric (SI): network A
    /// The entries the laws declare in subsection Material, by name, in the
    /// parameter file's units (e.g. "Relaxation time (s)").
    std::map<std::string, double> constants;
    /// The text entries they declare (ParameterDeclarations::add_text:
    /// lists, names), by name, as the file writes them.
    std::map<std::string, std::string> texts;

    /// The entry @p name of constants; throws std::invalid_argument naming
    /// it and the model if it is not there.
    double constant(const std::string &name) const;
    /// The text entry @p name of texts, or @p fallback if it is not there
    /// (settings built by hand, without the parameter file).
    std::string text(const std::string &name, const std::string &fallback) const;
  };

  /// The registered laws: made from their LawSettings.
  using MembraneLaws = PluginList<MembraneLaw, LawSettings, std::shared_ptr<const MembraneLaw>>;

  /// The law settings.model names, built from @p settings. Throws
  /// std::invalid_argument if no law is registered under that name or a
  /// constant is missing, InputError if a constant is outside its range.
  std::shared_ptr<const MembraneLaw> make_membrane_law(const LawSettings &settings);
} // namespace cdea
