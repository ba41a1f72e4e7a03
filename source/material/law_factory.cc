#include <cdea/material/law_factory.h>

#include <stdexcept>

namespace cdea
{
  namespace
  {
    /// The registry by name, made on first use (registrations run during
    /// static initialisation, in an order the language leaves open; the map
    /// orders them by name).
    std::map<std::string, LawPlugin> &registry()
    {
      static std::map<std::string, LawPlugin> laws;
      return laws;
    }
  } // namespace

  double LawSettings::constant(const std::string &name) const
  {
    const auto it = constants.find(name);
    if (it == constants.end())
      throw std::invalid_argument("the material law '" + model + "' needs Material/" + name);
    return it->second;
  }

  std::string LawSettings::text(const std::string &name, const std::string &fallback) const
  {
    const auto it = texts.find(name);
    return it == texts.end() ? fallback : it->second;
  }

  bool register_membrane_law(const LawPlugin &plugin)
  {
    if (!registry().emplace(plugin.name, plugin).second)
      throw std::logic_error("two material laws are registered as '" + plugin.name + "'");
    return true;
  }

  std::vector<std::string> membrane_law_names()
  {
    std::vector<std::string> names;
    for (const auto &entry : registry())
      names.push_back(entry.first);
    return names;
  }

  std::string membrane_law_documentation()
  {
    std::string text;
    for (const auto &entry : registry())
      text += (text.empty() ? "'" : " '") + entry.first + "': " + entry.second.description;
    return text;
  }

  ParameterDeclarations membrane_law_parameters()
  {
    ParameterDeclarations all;
    for (const auto &entry : registry())
      {
        ParameterDeclarations own;
        entry.second.declare_parameters(own);
        all.append(own);
      }
    return all;
  }

  std::shared_ptr<const MembraneLaw> make_membrane_law(const LawSettings &settings)
  {
    const auto it = registry().find(settings.model);
    if (it == registry().end())
      throw std::invalid_argument("no material law is registered as '" + settings.model + "'");
    return it->second.parse_parameters(settings);
  }
} // namespace cdea
