#include <cdea/base/parameter_declarations.h>

#include <stdexcept>

namespace cdea
{
  void ParameterDeclarations::declare_number(const std::string &subsection,
                                             const std::string &name,
                                             const std::string &default_value,
                                             const std::string &documentation)
  {
    list.push_back({subsection, name, default_value, EntryKind::number, documentation, true});
  }

  void ParameterDeclarations::declare_flag(const std::string &subsection, const std::string &name,
                                           const std::string &default_value,
                                           const std::string &documentation)
  {
    list.push_back({subsection, name, default_value, EntryKind::flag, documentation, true});
  }

  void ParameterDeclarations::declare_text(const std::string &subsection, const std::string &name,
                                           const std::string &default_value,
                                           const std::string &documentation)
  {
    list.push_back({subsection, name, default_value, EntryKind::text, documentation, true});
  }

  void ParameterDeclarations::read_number(const std::string &subsection, const std::string &name)
  {
    list.push_back({subsection, name, "", EntryKind::number, "", false});
  }

  void ParameterDeclarations::append(const ParameterDeclarations &other)
  {
    list.insert(list.end(), other.list.begin(), other.list.end());
  }

  void ParameterValues::set_number(const std::string &path, const double value)
  {
    numbers[path] = value;
  }

  void ParameterValues::set_flag(const std::string &path, const bool value)
  {
    flags[path] = value;
  }

  void ParameterValues::set_text(const std::string &path, const std::string &value)
  {
    texts[path] = value;
  }

  double ParameterValues::number(const std::string &path) const
  {
    const auto it = numbers.find(path);
    if (it == numbers.end())
      throw std::invalid_argument("no value of the number " + path + " was read");
    return it->second;
  }

  bool ParameterValues::flag(const std::string &path) const
  {
    const auto it = flags.find(path);
    if (it == flags.end())
      throw std::invalid_argument("no value of the flag " + path + " was read");
    return it->second;
  }

  const std::string &ParameterValues::text(const std::string &path) const
  {
    const auto it = texts.find(path);
    if (it == texts.end())
      throw std::invalid_argument("no value of the text entry " + path + " was read");
    return it->second;
  }
} // namespace cdea
