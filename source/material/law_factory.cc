#include <cdea/material/law_factory.h>

#include <stdexcept>

namespace cdea
{
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

  std::shared_ptr<const MembraneLaw> make_membrane_law(const LawSettings &settings)
  {
    if (!MembraneLaws::find(settings.model))
      throw std::invalid_argument("no material law is registered as '" + settings.model + "'");
    return MembraneLaws::create(settings.model, settings);
  }
} // namespace cdea
