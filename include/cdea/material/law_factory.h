#pragma once
// The material laws by the names Material/Model gives them ("elastic",
// "viscoelastic"), in the manner of ASPECT's material models: each law
// registers itself in its own source file with one line,
//
//   CDEA_REGISTER_MEMBRANE_LAW(TwoNetworkGentLaw, "viscoelastic", create_function)
//
// and make_membrane_law() builds the one the settings name. The settings are
// plain data (no deal.II): input/ fills them from the parameter file. The law
// files are linked whole into every program (an object library in
// CMakeLists.txt), so that no registration is dropped by the linker.

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
    std::string       model = "elastic"; ///< Material/Model: the name a law is registered under
    MaterialConstants material{};        ///< the film's Gent law and dielectric (SI): network A
    /// Further entries of subsection Material by their names in the
    /// parameter file, in its units (e.g. "Relaxation time (s)").
    std::map<std::string, double> constants;

    /// The entry @p name of constants; throws std::invalid_argument naming
    /// it and the model if it is not there.
    double constant(const std::string &name) const;
  };

  /// Builds a law from its settings.
  using LawCreator = std::shared_ptr<const MembraneLaw> (*)(const LawSettings &);

  /// Registers @p create under @p name (what CDEA_REGISTER_MEMBRANE_LAW
  /// does); true. Throws std::logic_error if the name is taken.
  bool register_membrane_law(const std::string &name, LawCreator create);

  /// The registered names, sorted.
  std::vector<std::string> membrane_law_names();

  /// The law settings.model names, built from @p settings. Throws
  /// std::invalid_argument if no law is registered under that name.
  std::shared_ptr<const MembraneLaw> make_membrane_law(const LawSettings &settings);
} // namespace cdea

/// Registers @p create (a LawCreator) as the law @p name of Material/Model;
/// one line in the law's source file, outside any namespace.
#define CDEA_REGISTER_MEMBRANE_LAW(classname, name, create)                            \
  namespace                                                                             \
  {                                                                                     \
    [[maybe_unused]] const bool classname##_registered =                                \
      ::cdea::register_membrane_law(name, create);                                      \
  }
