#include <cdea/fe/load_term.h>

namespace cdea
{
  std::vector<std::unique_ptr<LoadTerm>> make_load_terms(const ParameterValues &values)
  {
    std::vector<std::unique_ptr<LoadTerm>> terms;
    for (const LoadTerms::Plugin &plugin : LoadTerms::plugins())
      if (auto term = plugin.create(values); term->active())
        terms.push_back(std::move(term));
    return terms;
  }
} // namespace cdea
