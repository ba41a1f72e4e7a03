#pragma once
// The one table of the parameter file's entries, without deal.II: the core's
// subsections (input/parameters*.cc) and the plugins (the material laws of
// material/, the load terms of fe/) declare their entries here alike, each
// entry in one place with its default, its pattern, its documentation and
// where its value goes (deal.II's ParameterHandler::add_parameter, as step-44
// reads it: an entry declared and bound at once). input/ (parameters.h) turns
// the table into ParameterHandler entries, in the order of declaration, and
// hands each value read back to its entry: a bound variable, a function that
// parses a text, or ParameterValues by path for a plugin that is built from
// the values later (ASPECT's parse_parameters()). Range checks beyond the
// pattern stay with the code that owns the entry and throw InputError
// (text.h) naming it.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace cdea
{
  /// What an entry holds, and so its deal.II pattern: a number
  /// (Patterns::Double), an integer (Patterns::Integer), a flag
  /// (Patterns::Bool), one of a list of names (Patterns::Selection) or text
  /// (Patterns::Anything: a list or a name that its owner parses and checks).
  enum class EntryKind
  {
    number,
    integer,
    flag,
    selection,
    text
  };

  /// The bounds of a number or integer entry's pattern; none: deal.II's own
  /// (the largest double, the int range).
  struct EntryRange
  {
    std::optional<double> lower, upper;
  };
  inline EntryRange at_least(const double lower) { return {lower, std::nullopt}; }
  inline EntryRange between(const double lower, const double upper) { return {lower, upper}; }

  /// A value as read from the file, by the entry's kind: number -> double,
  /// integer -> long, flag -> bool, selection and text -> std::string.
  using EntryValue = std::variant<double, long, bool, std::string>;

  /// The names of a choice entry and the values they select, in the order the
  /// pattern lists them: one list for the entry and for the messages that
  /// name a choice (to_string()).
  template <typename Value>
  class Choices
  {
  public:
    Choices(std::initializer_list<std::pair<std::string, Value>> list)
      : list(list)
    {}
    /// deal.II's selection: "load stepping|arc length".
    std::string selection() const
    {
      std::string text;
      for (const auto &[name, value] : list)
        text += (text.empty() ? "" : "|") + name;
      return text;
    }
    /// The name of @p value ("" if it has none).
    std::string name(const Value value) const
    {
      for (const auto &[name, v] : list)
        if (v == value)
          return name;
      return {};
    }
    /// The value named @p name (the pattern admits no other name).
    Value value(const std::string &name) const
    {
      for (const auto &[n, v] : list)
        if (n == name)
          return v;
      return list.front().second;
    }

  private:
    std::vector<std::pair<std::string, Value>> list;
  };

  struct EntryDeclaration
  {
    std::string subsection;    ///< "Reservoir"
    std::string name;          ///< "Water volume (ml)"
    std::string default_value; ///< as the parameter file writes it: "150", "false"
    EntryKind   kind = EntryKind::number;
    std::string documentation;
    EntryRange  range;         ///< number and integer entries
    std::string options;       ///< selection: "a|b"
    /// false: an entry that another part declares (the core's
    /// "Loading/Gravity (m/s^2)", say) and this part reads as well.
    bool declared_here = true;
    /// Where the value read goes; empty: nowhere yet (a plugin's entry, bound
    /// to ParameterValues when the core appends it).
    std::function<void(const EntryValue &)> assign;

    /// "Subsection/Entry", the name in messages and in ParameterValues.
    std::string path() const { return subsection + "/" + name; }
  };

  class ParameterValues;

  /// What the subsections and the plugins declare, in the order of their
  /// calls. Entries belong to the subsection entered last.
  class ParameterDeclarations
  {
  public:
    void enter_subsection(const std::string &name) { subsection = name; }
    void leave_subsection() { subsection.clear(); }

    /// An entry whose value is assigned to @p value when the file is read.
    void add(const std::string &name, const std::string &default_value, double &value,
             const std::string &documentation, const EntryRange &range = {});
    void add(const std::string &name, const std::string &default_value, unsigned int &value,
             const std::string &documentation, const EntryRange &range = {});
    void add(const std::string &name, const std::string &default_value, int &value,
             const std::string &documentation, const EntryRange &range = {});
    void add(const std::string &name, const std::string &default_value, bool &value,
             const std::string &documentation);
    void add(const std::string &name, const std::string &default_value, std::string &value,
             const std::string &documentation);
    /// A choice: the value of the name read.
    template <typename Value>
    void add(const std::string &name, const std::string &default_value, Value &value,
             const Choices<Value> &choices, const std::string &documentation)
    {
      add_choice(name, default_value, choices.selection(), documentation,
                 [&value, choices](const EntryValue &v) {
                   value = choices.value(std::get<std::string>(v));
                 });
    }
    /// A choice among @p selection ("a|b") kept as its name.
    void add_choice(const std::string &name, const std::string &default_value,
                    const std::string &selection, const std::string &documentation,
                    std::function<void(const EntryValue &)> assign);
    /// Text that @p parse turns into its owner's values (and checks) as it is read.
    void add_parsed(const std::string &name, const std::string &default_value,
                    std::function<void(const std::string &)> parse,
                    const std::string &documentation);

    /// A plugin's entries, bound later to the ParameterValues it is built
    /// from (append() with values): a number, a flag, a text.
    void add_number(const std::string &name, const std::string &default_value,
                    const std::string &documentation);
    void add_flag(const std::string &name, const std::string &default_value,
                  const std::string &documentation);
    void add_text(const std::string &name, const std::string &default_value,
                  const std::string &documentation);
    /// A number declared elsewhere that the plugin reads too.
    void read_number(const std::string &name);

    /// @p entry after these.
    void append(EntryDeclaration entry);
    /// Every entry of @p other after these, as they are.
    void append(const ParameterDeclarations &other);
    /// Every entry of @p other after these, each unbound one bound to
    /// @p values by its path.
    void append(const ParameterDeclarations &other, ParameterValues &values);

    const std::vector<EntryDeclaration> &entries() const { return list; }

  private:
    std::string                   subsection;
    std::vector<EntryDeclaration> list;

    void push(const std::string &name, const std::string &default_value, EntryKind kind,
              const std::string &documentation, std::function<void(const EntryValue &)> assign,
              const EntryRange &range = {});
  };

  /// The values of declared entries by their path ("Reservoir/Water load"),
  /// as read from a parameter file (numbers in the file's units).
  class ParameterValues
  {
  public:
    void set_number(const std::string &path, double value);
    void set_flag(const std::string &path, bool value);
    void set_text(const std::string &path, const std::string &value);
    /// The value of @p path; std::invalid_argument naming it if there is none.
    double number(const std::string &path) const;
    bool   flag(const std::string &path) const;
    const std::string &text(const std::string &path) const;

  private:
    std::map<std::string, double> numbers;
    std::map<std::string, bool>   flags;
    std::map<std::string, std::string> texts;
  };
} // namespace cdea
