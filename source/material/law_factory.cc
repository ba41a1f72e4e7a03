#include <cdea/material/law_factory.h>

#include <stdexcept>

namespace cdea
{
  namespace
  {
    /// The registry, made on first use (registrations run during static
    /// initialisation, in an order the language leaves open).
    std::map<std::string, LawCreator> &registry()
    {
      static std::map<std::string, LawCreator> laws;
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

  bool register_membrane_law(const std::string &name, const LawCreator create)
  {
    if (!registry().emplace(name, create).second)
      throw std::logic_error("two material laws are registered as '" + name + "'");
    return true;
  }

  std::vector<std::string> membrane_law_names()
  {
    std::vector<std::string> names;
    for (const auto &entry : registry())
      names.push_back(entry.first);
    return names;
  }

  std::shared_ptr<const MembraneLaw> make_membrane_law(const LawSettings &settings)
  {
    const auto it = registry().find(settings.model);
    if (it == registry().end())
      throw std::invalid_argument("no material law is registered as '" + settings.model + "'");
    return it->second(settings);
  }
} // namespace cdea
