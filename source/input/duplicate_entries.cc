#include <cdea/input/duplicate_entries.h>

#include <map>
#include <sstream>

namespace cdea
{
  std::vector<std::string> duplicate_entry_warnings(const std::string &prm_text,
                                                    const std::string &filename)
  {
    std::vector<std::string>              warnings;
    std::vector<std::string>              sections;
    std::map<std::string, unsigned int>   first_line;
    std::istringstream                    in(prm_text);
    std::string                           line, logical;
    unsigned int                          number = 0, start = 0;
    const auto trim = [](const std::string &s) {
      const auto a = s.find_first_not_of(" \t\r");
      const auto b = s.find_last_not_of(" \t\r");
      return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
    };
    while (std::getline(in, line))
      {
        ++number;
        if (logical.empty())
          start = number;
        // A trailing backslash continues the line (deal.II's syntax).
        const std::string stripped = trim(line.substr(0, line.find('#')));
        if (!stripped.empty() && stripped.back() == '\\')
          {
            logical += stripped.substr(0, stripped.size() - 1) + ' ';
            continue;
          }
        logical += stripped;
        const std::string statement = trim(logical);
        logical.clear();
        if (statement.rfind("subsection", 0) == 0)
          sections.push_back(trim(statement.substr(10)));
        else if (statement == "end")
          {
            if (!sections.empty())
              sections.pop_back();
          }
        else if (statement.rfind("set", 0) == 0)
          {
            const auto equal = statement.find('=');
            if (equal == std::string::npos)
              continue;
            std::string name;
            for (const auto &s : sections)
              name += s + "/";
            // deal.II folds runs of blanks in names.
            std::string entry;
            for (const char c : trim(statement.substr(3, equal - 3)))
              if (c != ' ' || entry.empty() || entry.back() != ' ')
                entry += c;
            name += entry;
            const auto [it, fresh] = first_line.emplace(name, start);
            if (!fresh)
              warnings.push_back(filename + " line " + std::to_string(start) + ": " + name +
                                 " is set again (first on line " +
                                 std::to_string(it->second) + "); the last value is used");
          }
      }
    return warnings;
  }
} // namespace cdea
