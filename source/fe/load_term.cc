#include <cdea/fe/load_term.h>

#include <map>
#include <stdexcept>

namespace cdea
{
  namespace
  {
    /// The registry by name, made on first use.
    std::map<std::string, LoadTermPlugin> &registry()
    {
      static std::map<std::string, LoadTermPlugin> terms;
      return terms;
    }
  } // namespace

  bool register_load_term(const LoadTermPlugin &plugin)
  {
    if (!registry().emplace(plugin.name, plugin).second)
      throw std::logic_error("two load terms are registered as '" + plugin.name + "'");
    return true;
  }

  std::vector<LoadTermPlugin> load_term_plugins()
  {
    std::vector<LoadTermPlugin> plugins;
    for (const auto &entry : registry())
      plugins.push_back(entry.second);
    return plugins;
  }

  ParameterDeclarations load_term_parameters()
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

  std::unique_ptr<LoadTerm> parse_load_term(const LoadTermPlugin &plugin,
                                            const ParameterValues &values)
  {
    std::unique_ptr<LoadTerm> term = plugin.create();
    term->parse_parameters(values);
    return term;
  }

  std::vector<std::unique_ptr<LoadTerm>> make_load_terms(const ParameterValues &values)
  {
    std::vector<std::unique_ptr<LoadTerm>> terms;
    for (const auto &entry : registry())
      if (auto term = parse_load_term(entry.second, values); term->active())
        terms.push_back(std::move(term));
    return terms;
  }
} // namespace cdea
