#pragma once
// Entries of the parameter file that a plugin declares and reads (a material
// law of material/, a load term of fe/), without deal.II: ASPECT's
// declare_parameters() / parse_parameters() pair in plain C++, so that the
// files of a law or a term need no deal.II header. input/
// (parameters_plugins.h) turns the declarations into ParameterHandler entries
// and hands the values read back as ParameterValues; range checks stay with
// the plugin, which throws InputError (text.h) naming the entry.

#include <map>
#include <string>
#include <vector>

namespace cdea
{
  /// What an entry holds: deal.II's Patterns::Double() or Patterns::Bool(),
  /// or text (Patterns::Anything(): a list or a name that the plugin parses
  /// and checks itself).
  enum class EntryKind
  {
    number,
    flag,
    text
  };

  struct EntryDeclaration
  {
    std::string subsection;    ///< "Reservoir"
    std::string name;          ///< "Water volume (ml)"
    std::string default_value; ///< as the parameter file writes it: "150", "false"
    EntryKind   kind = EntryKind::number;
    std::string documentation;
    /// false: an entry that another part declares (the core, say
    /// "Loading/Gravity (m/s^2)") and the plugin reads as well.
    bool declared_here = true;

    /// "Subsection/Entry", the name in messages and in ParameterValues.
    std::string path() const { return subsection + "/" + name; }
  };

  /// What a plugin's declare_parameters() fills, in the order of its calls.
  class ParameterDeclarations
  {
  public:
    void declare_number(const std::string &subsection, const std::string &name,
                        const std::string &default_value, const std::string &documentation);
    void declare_flag(const std::string &subsection, const std::string &name,
                      const std::string &default_value, const std::string &documentation);
    void declare_text(const std::string &subsection, const std::string &name,
                      const std::string &default_value, const std::string &documentation);
    /// A number declared elsewhere that the plugin reads too.
    void read_number(const std::string &subsection, const std::string &name);
    /// Every entry of @p other after these.
    void append(const ParameterDeclarations &other);

    const std::vector<EntryDeclaration> &entries() const { return list; }

  private:
    std::vector<EntryDeclaration> list;
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
