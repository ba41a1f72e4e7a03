#include <cdea/base/parameter_declarations.h>

#include <stdexcept>

namespace cdea
{
  void ParameterDeclarations::push(const std::string &name, const std::string &default_value,
                                   const EntryKind kind, const std::string &documentation,
                                   std::function<void(const EntryValue &)> assign,
                                   const EntryRange &range)
  {
    EntryDeclaration e;
    e.subsection    = subsection;
    e.name          = name;
    e.default_value = default_value;
    e.kind          = kind;
    e.documentation = documentation;
    e.range         = range;
    e.assign        = std::move(assign);
    list.push_back(std::move(e));
  }

  void ParameterDeclarations::add(const std::string &name, const std::string &default_value,
                                  double &value, const std::string &documentation,
                                  const EntryRange &range)
  {
    push(name, default_value, EntryKind::number, documentation,
         [&value](const EntryValue &v) { value = std::get<double>(v); }, range);
  }

  void ParameterDeclarations::add(const std::string &name, const std::string &default_value,
                                  unsigned int &value, const std::string &documentation,
                                  const EntryRange &range)
  {
    push(name, default_value, EntryKind::integer, documentation,
         [&value](const EntryValue &v) { value = static_cast<unsigned int>(std::get<long>(v)); },
         range);
  }

  void ParameterDeclarations::add(const std::string &name, const std::string &default_value,
                                  int &value, const std::string &documentation,
                                  const EntryRange &range)
  {
    push(name, default_value, EntryKind::integer, documentation,
         [&value](const EntryValue &v) { value = static_cast<int>(std::get<long>(v)); }, range);
  }

  void ParameterDeclarations::add(const std::string &name, const std::string &default_value,
                                  bool &value, const std::string &documentation)
  {
    push(name, default_value, EntryKind::flag, documentation,
         [&value](const EntryValue &v) { value = std::get<bool>(v); });
  }

  void ParameterDeclarations::add(const std::string &name, const std::string &default_value,
                                  std::string &value, const std::string &documentation)
  {
    push(name, default_value, EntryKind::text, documentation,
         [&value](const EntryValue &v) { value = std::get<std::string>(v); });
  }

  void ParameterDeclarations::add_choice(const std::string &name,
                                         const std::string &default_value,
                                         const std::string &selection,
                                         const std::string &documentation,
                                         std::function<void(const EntryValue &)> assign)
  {
    push(name, default_value, EntryKind::selection, documentation, std::move(assign));
    list.back().options = selection;
  }

  void ParameterDeclarations::add_parsed(const std::string &name, const std::string &default_value,
                                         std::function<void(const std::string &)> parse,
                                         const std::string &documentation)
  {
    push(name, default_value, EntryKind::text, documentation,
         [parse = std::move(parse)](const EntryValue &v) { parse(std::get<std::string>(v)); });
  }

  void ParameterDeclarations::add_number(const std::string &name, const std::string &default_value,
                                         const std::string &documentation)
  {
    push(name, default_value, EntryKind::number, documentation, {});
  }

  void ParameterDeclarations::add_flag(const std::string &name, const std::string &default_value,
                                       const std::string &documentation)
  {
    push(name, default_value, EntryKind::flag, documentation, {});
  }

  void ParameterDeclarations::add_text(const std::string &name, const std::string &default_value,
                                       const std::string &documentation)
  {
    push(name, default_value, EntryKind::text, documentation, {});
  }

  void ParameterDeclarations::read_number(const std::string &name)
  {
    push(name, "", EntryKind::number, "", {});
    list.back().declared_here = false;
  }

  void ParameterDeclarations::append(EntryDeclaration entry)
  {
    list.push_back(std::move(entry));
  }

  void ParameterDeclarations::append(const ParameterDeclarations &other)
  {
    list.insert(list.end(), other.list.begin(), other.list.end());
  }

  void ParameterDeclarations::append(const ParameterDeclarations &other, ParameterValues &values)
  {
    for (EntryDeclaration e : other.list)
      {
        if (!e.assign)
          e.assign = [&values, path = e.path()](const EntryValue &v) {
            if (const double *x = std::get_if<double>(&v))
              values.set_number(path, *x);
            else if (const bool *b = std::get_if<bool>(&v))
              values.set_flag(path, *b);
            else if (const std::string *t = std::get_if<std::string>(&v))
              values.set_text(path, *t);
            else
              values.set_number(path, double(std::get<long>(v)));
          };
        list.push_back(std::move(e));
      }
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
