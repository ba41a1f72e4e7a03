#include <deal.II/base/parameter_handler.h>

#include <cdea/base/file_reading.h>
#include <cdea/base/text.h>
#include <cdea/input/prm_text.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

namespace cdea
{
  namespace
  {
    constexpr std::size_t max_parameter_file_bytes = std::size_t(64) << 20;

    /// An open subsection: its name and the line that opened it.
    struct Open
    {
      std::string  name;
      unsigned int line;
    };

    std::string path_of(const std::vector<Open> &open)
    {
      std::string path;
      for (const Open &o : open)
        path += (path.empty() ? "" : "/") + o.name;
      return path;
    }

    std::vector<std::string> names_of(const std::vector<Open> &open)
    {
      std::vector<std::string> names;
      for (const Open &o : open)
        names.push_back(o.name);
      return names;
    }

    /// One logical line of prm text as deal.II's ParameterHandler reads it
    /// (parse_input(), scan_line()): the physical lines trimmed, a line
    /// ending in '\' joined with the next, numbered by its last physical
    /// line; the content without its comment ('#' on), tabs as blanks,
    /// trimmed.
    struct Line
    {
      unsigned int number;
      std::string  raw, content;
    };

    std::string trimmed(const std::string &text)
    {
      const auto first = std::find_if_not(text.begin(), text.end(),
                                          [](unsigned char c) { return std::isspace(c); });
      const auto last  = std::find_if_not(text.rbegin(), text.rend(),
                                         [](unsigned char c) { return std::isspace(c); });
      return first < last.base() ? std::string(first, last.base()) : std::string();
    }

    std::vector<Line> lines_of(const std::string &text)
    {
      std::vector<Line>  lines;
      std::istringstream in(text);
      std::string        piece, joined;
      bool               continued = false;
      for (unsigned int number = 1; std::getline(in, piece); ++number)
        {
          piece = trimmed(piece);
          const bool continues = !piece.empty() && piece.back() == '\\';
          if (continues)
            piece.pop_back();
          joined    = continued ? joined + piece : piece;
          continued = continues;
          if (continues)
            continue;
          std::string content = joined.substr(0, joined.find('#'));
          std::replace(content.begin(), content.end(), '\t', ' ');
          lines.push_back({number, joined, trimmed(content)});
        }
      return lines;
    }

    bool starts_with(const std::string &text, const char *lower, const char *upper)
    {
      return text.rfind(lower, 0) == 0 || text.rfind(upper, 0) == 0;
    }

    bool is_end(const Line &l)
    {
      return l.content == "end" || l.content == "END";
    }

    /// The subsection a "subsection NAME" line opens, or "".
    std::string opened(const Line &l)
    {
      return starts_with(l.content, "subsection ", "SUBSECTION ") ? trimmed(l.content.substr(11)) :
                                                                     std::string();
    }

    /// "set NAME = VALUE": the name and the raw value (comment included).
    bool set_line(const Line &l, std::string &entry, std::string &raw_value)
    {
      const auto equal = l.content.find('=');
      if (!starts_with(l.content, "set ", "SET ") || equal == std::string::npos)
        return false;
      entry     = trimmed(l.content.substr(4, equal - 4));
      raw_value = l.raw.substr(l.raw.find('=') + 1);
      return true;
    }

    /// A name entry whose value has a '#' right after a character of it.
    void check_name_cut(const Line &l, const std::vector<Open> &open, const std::string &where)
    {
      static const char *const names[] = {"Output/Base name", "Output/Directory",
                                          "Time/Table file"};
      std::string entry, raw;
      if (!set_line(l, entry, raw))
        return;
      const std::string key = path_of(open) + "/" + entry;
      if (std::find(std::begin(names), std::end(names), key) == std::end(names))
        return;
      const auto hash = raw.find('#');
      if (hash == std::string::npos || hash == 0 || raw[hash - 1] == ' ' || raw[hash - 1] == '\t')
        return;
      throw InputError(where + key + " = '" +
                       trim_blanks(raw) + "': '#' starts a comment in a parameter file, so " +
                       "the value would be cut to '" + trim_blanks(raw.substr(0, hash)) +
                       "'; choose a name without '#'");
    }
  } // namespace

  std::string read_parameter_file(const std::string &path)
  {
    const FileRead read = read_regular_file(path, max_parameter_file_bytes);
    if (read.ok)
      return read.bytes;
    if (read.error == "it does not exist")
      throw InputError("cannot read parameter file '" + path +
                       "': it does not exist, is not a regular file or is not readable");
    throw InputError("cannot read parameter file '" + path + "': " + read.error);
  }

  namespace
  {
    /// An "include FILE" line: deal.II reads FILE, which must then be a
    /// regular file of bounded size too.
    void check_include(const Line &l, const std::string &where)
    {
      if (!starts_with(l.content, "include ", "INCLUDE "))
        return;
      const std::string file = trimmed(l.content.substr(8));
      const FileRead    read = read_regular_file(file, max_parameter_file_bytes);
      if (!read.ok)
        throw InputError(where + "cannot include '" + file + "': " + read.error);
    }
  } // namespace

  void check_prm_structure(const std::string &text, const std::string &name,
                           const dealii::ParameterHandler &prm)
  {
    std::vector<Open> open;
    for (const Line &l : lines_of(text))
      {
        const std::string where = name + "line " + std::to_string(l.number) + ": ";
        const std::string sub   = opened(l);
        if (!sub.empty())
          {
            std::vector<std::string> path = names_of(open);
            path.push_back(sub);
            if (!prm.subsection_path_exists(path) && !open.empty())
              throw InputError(where + "subsection '" + sub + "' inside subsection '" +
                               path_of(open) + "' (opened on line " +
                               std::to_string(open.back().line) + "), which has none: is its " +
                               "'end' missing before line " + std::to_string(l.number) + "?");
            open.push_back({sub, l.number});
          }
        else if (is_end(l))
          {
            if (open.empty())
              throw InputError(where + "'end' without a subsection to close (every "
                               "subsection before it is closed already)");
            open.pop_back();
          }
        else
          {
            check_name_cut(l, open, where);
            check_include(l, where);
          }
      }
    if (!open.empty())
      throw InputError(name + "subsection '" + path_of(open) + "' (opened on line " +
                       std::to_string(open.back().line) + ") has no 'end'");
  }

  namespace
  {
    /// "nan", "inf", "-infinity", "NaN(1)": what strtod reads as no finite
    /// number (compared by hand: a regular expression would recurse over a
    /// value of a megabyte).
    bool not_finite(const std::string &value)
    {
      std::string v = trimmed(value);
      if (v.size() > 40)
        return false;
      if (!v.empty() && (v[0] == '+' || v[0] == '-'))
        v.erase(0, 1);
      for (char &c : v)
        c = char(std::tolower(static_cast<unsigned char>(c)));
      return v == "inf" || v == "infinity" || v.rfind("nan", 0) == 0;
    }

    /// The text of @p message between @p before and @p after, from @p at on
    /// (at moves past it); false if they are not there.
    bool between(const std::string &message, std::size_t &at, const std::string &before,
                 const std::string &after, std::string &text)
    {
      const auto begin = message.find(before, at);
      if (begin == std::string::npos)
        return false;
      const auto end = message.find(after, begin + before.size());
      if (end == std::string::npos)
        return false;
      text = message.substr(begin + before.size(), end - begin - before.size());
      at   = end + after.size();
      return true;
    }
  } // namespace

  std::string explain_parse_error(const std::string &text, const std::string &message)
  {
    // deal.II: "Line <N> of file <F>: The entry value V for the entry named E
    // does not match the given pattern: [Double ...]".
    std::string number, file, value, entry, pattern;
    std::size_t at = 0;
    if (message.rfind("Line <", 0) != 0 || !between(message, at, "Line <", ">", number) ||
        !between(message, at, " of file <", ">: ", file) ||
        !between(message, at, "The entry value ", " for the entry named ", value) ||
        !between(message, at, "", " does not match the given pattern: [", entry) ||
        (message.compare(at, 6, "Double") != 0 && message.compare(at, 7, "Integer") != 0) ||
        !not_finite(value) || number.empty() || number.size() > 9 ||
        number.find_first_not_of("0123456789") != std::string::npos)
      return message;
    const unsigned int line = unsigned(std::stoul(number));
    std::vector<Open>  open;
    for (const Line &l : lines_of(text))
      {
        if (l.number >= line)
          break;
        if (const std::string sub = opened(l); !sub.empty())
          open.push_back({sub, l.number});
        else if (is_end(l) && !open.empty())
          open.pop_back();
      }
    return "line " + number + ": " + path_of(open) + (open.empty() ? "" : "/") + entry +
           " must be a finite number, got '" + value + "'";
  }

  std::string explain_override_error(const std::string &key, const std::string &value,
                                     const std::string &message)
  {
    const bool number = message.find("given pattern <[Double") != std::string::npos ||
                        message.find("given pattern <[Integer") != std::string::npos;
    if (!number || !not_finite(value))
      return "";
    return key + " must be a finite number, got '" + value + "'";
  }

  void check_override_value(const std::string &key, const std::string &value)
  {
    if (value.find('#') != std::string::npos)
      throw InputError("override '" + key + "' = '" + value +
                       "': '#' starts a comment in a parameter file, so the parameter files "
                       "cdea writes (the results' parameters, the replays of optimize and "
                       "fit) could not hold it; choose a value without '#'");
  }
} // namespace cdea
