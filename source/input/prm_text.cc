#include <deal.II/base/parameter_handler.h>

#include <cdea/base/file_reading.h>
#include <cdea/base/text.h>
#include <cdea/input/prm_text.h>

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
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

    /// One logical line of prm text as deal.II's ParameterHandler reads it
    /// (parse_input(), scan_line()): the physical lines trimmed, a line
    /// ending in '\' joined with the next, numbered by its last physical
    /// line; the content without its comment ('#' on), tabs as blanks,
    /// trimmed.
    struct Line
    {
      unsigned int number; ///< its last physical line
      std::string  raw, content;
      unsigned int first; ///< its first physical line
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
      unsigned int       first     = 1;
      for (unsigned int number = 1; std::getline(in, piece); ++number)
        {
          piece = trimmed(piece);
          const bool continues = !piece.empty() && piece.back() == '\\';
          if (continues)
            piece.pop_back();
          if (!continued)
            first = number;
          joined    = continued ? joined + piece : piece;
          continued = continues;
          if (continues)
            continue;
          std::string content = joined.substr(0, joined.find('#'));
          std::replace(content.begin(), content.end(), '\t', ' ');
          lines.push_back({number, joined, trimmed(content), first});
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
    void check_name_cut(const Line &l, const std::string &section, const std::string &where)
    {
      static const char *const names[] = {"Output/Base name", "Output/Directory",
                                          "Time/Table file"};
      std::string entry, raw;
      if (!set_line(l, entry, raw))
        return;
      const std::string key = section + "/" + entry;
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
      throw MissingFileError("cannot read parameter file '" + path +
                       "': it does not exist, is not a regular file or is not readable");
    throw InputError("cannot read parameter file '" + path + "': " + read.error);
  }

  namespace
  {
    constexpr unsigned int max_include_depth = 16;

    /// CR LF and a lone CR end a line as LF does (a file saved on Windows
    /// or by an old Mac editor reads as it shows).
    std::string with_lf_line_ends(const std::string &text)
    {
      std::string out;
      out.reserve(text.size());
      for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] != '\r')
          out += text[i];
        else if (i + 1 == text.size() || text[i + 1] != '\n')
          out += '\n';
      return out;
    }

    std::vector<std::string> physical_lines(const std::string &text)
    {
      std::vector<std::string> lines;
      std::istringstream       in(text);
      for (std::string line; std::getline(in, line);)
        lines.push_back(line);
      return lines;
    }

    bool is_include(const Line &l)
    {
      return starts_with(l.content, "include ", "INCLUDE ");
    }

    /// A file on the chain of includes: which file it is, and the line of
    /// the include being expanded in it.
    struct Link
    {
      std::string   name;
      std::uint64_t device = 0, inode = 0;
      unsigned int  line   = 0;
    };

    /// The text of a main file with its includes in place, line by line.
    class Expansion
    {
    public:
      Expansion(const dealii::ParameterHandler &prm, PrmText &out, const bool is_file)
        : prm(prm)
        , out(out)
        , is_file(is_file)
      {}

      /// The file at the end of @p self (LF line ends), its lines inside
      /// the subsections @p outer of the files including it.
      void add(const std::string &text, const std::vector<std::string> &outer, const Link &self);

    private:
      const dealii::ParameterHandler &prm;
      PrmText                        &out;
      const bool                      is_file;
      std::vector<Link>               chain;

      /// "in parameter file 'c.prm' (included from b.prm line 2, from a.prm line 3): ".
      std::string prefix() const
      {
        std::string where = chain.size() == 1 && !is_file ?
                              std::string("in parameter text") :
                              "in parameter file '" + chain.back().name + "'";
        for (std::size_t k = chain.size() - 1; k-- > 0;)
          where += std::string(k + 2 == chain.size() ? " (included from " : ", from ") +
                   (k == 0 && !is_file ? std::string("the parameter text") : chain[k].name) +
                   " line " + std::to_string(chain[k].line) + (k == 0 ? ")" : "");
        return where + ": ";
      }

      /// "a.prm line 3 -> b.prm line 1 -> " for a message about a loop.
      std::string chain_text() const
      {
        std::string text;
        for (const Link &k : chain)
          text += (k.name.empty() ? std::string("the parameter text") : k.name) + " line " +
                  std::to_string(k.line) + " -> ";
        return text;
      }

      void emit(const std::string &line, const unsigned int file, const unsigned int number)
      {
        out.text += line;
        out.text += '\n';
        out.origins.push_back({file, number});
        if (out.text.size() > max_parameter_file_bytes)
          throw InputError(out.files.front() + "with its includes the parameter text is larger "
                           "than 64 MB");
      }

      void check_line(const Line &l, const std::string &at, const std::vector<std::string> &outer,
                      std::vector<Open> &open) const;
      void include(const Line &l, const std::string &at, std::vector<std::string> sections);
    };

    void Expansion::check_line(const Line &l, const std::string &at,
                               const std::vector<std::string> &outer,
                               std::vector<Open> &open) const
    {
      std::vector<std::string> path = outer;
      for (const Open &o : open)
        path.push_back(o.name);
      std::string section;
      for (const std::string &name : path)
        section += (section.empty() ? "" : "/") + name;
      if (const std::string sub = opened(l); !sub.empty())
        {
          path.push_back(sub);
          if (!prm.subsection_path_exists(path) && path.size() > 1)
            throw InputError(
              at + "subsection '" + sub + "' inside subsection '" + section + "' (" +
              (open.empty() ? std::string("where this file is included") :
                              "opened on line " + std::to_string(open.back().line)) +
              "), which has none: is its " + "'end' missing before line " +
              std::to_string(l.number) + "?");
          open.push_back({sub, l.number});
        }
      else if (is_end(l))
        {
          if (open.empty())
            throw InputError(at + "'end' without a subsection to close (every subsection " +
                             (chain.size() > 1 ? "this file opens is closed already; an "
                                                 "included file closes only its own)" :
                                                 "before it is closed already)"));
          open.pop_back();
        }
      else
        check_name_cut(l, section, at);
    }

    void Expansion::add(const std::string &text, const std::vector<std::string> &outer,
                        const Link &self)
    {
      chain.push_back(self);
      const unsigned int file = static_cast<unsigned int>(out.files.size());
      out.files.push_back(prefix());
      out.names.push_back(self.name.empty() ? std::string("parameter text") : self.name);
      const std::string              where    = out.files.back();
      const std::vector<std::string> physical = physical_lines(text);
      std::vector<Open>              open;
      unsigned int                   passed = 0; // physical lines handed on
      for (const Line &l : lines_of(text))
        {
          const std::string at = where + "line " + std::to_string(l.number) + ": ";
          check_line(l, at, outer, open);
          if (!is_include(l))
            {
              for (; passed < l.number; ++passed)
                emit(physical[passed], file, passed + 1);
              continue;
            }
          std::vector<std::string> sections = outer;
          for (const Open &o : open)
            sections.push_back(o.name);
          chain.back().line = l.number;
          include(l, at, sections);
          passed = l.number;
        }
      if (!open.empty())
        throw InputError(where + "subsection '" + path_of(open) + "' (opened on line " +
                         std::to_string(open.back().line) + ") has no 'end'");
      if (passed < physical.size() && chain.size() > 1)
        throw InputError(where + "line " + std::to_string(physical.size()) + ": the last "
                         "line ends in '\\', which would continue it into the file that "
                         "includes this one; remove the '\\'");
      for (; passed < physical.size(); ++passed)
        emit(physical[passed], file, passed + 1);
      chain.pop_back();
    }

    /// An "include FILE" line: FILE read as the main file is (a regular
    /// parameter file, bounded), checked for loops and depth, and added.
    void Expansion::include(const Line &l, const std::string &at,
                            std::vector<std::string> sections)
    {
      const std::string file = trimmed(l.content.substr(8));
      const std::string cannot = at + "cannot include '" + file + "': ";
      // Only a parameter file: deal.II's messages quote the lines of what it
      // reads, which must not be any readable file (include /etc/shadow).
      if (!has_extension(file, ".prm"))
        throw InputError(cannot + "only a parameter file (a name ending in .prm) can be "
                         "included");
      if (chain.size() > max_include_depth)
        throw InputError(cannot + "includes nest more than " +
                         std::to_string(max_include_depth) + " deep: " + chain_text() + file);
      const FileRead read = read_regular_file(file, max_parameter_file_bytes);
      if (!read.ok)
        throw InputError(cannot + read.error);
      for (const Link &k : chain)
        if (k.inode != 0 && k.device == read.device && k.inode == read.inode)
          throw InputError(cannot + "it is " +
                           (&k == &chain.back() ? std::string("this file itself") :
                                                  "'" + k.name + "', which includes this file") +
                           ", an include loop: " + chain_text() + file);
      add(with_lf_line_ends(read.bytes), sections, {file, read.device, read.inode, 0});
    }
  } // namespace

  PrmText prepare_parameter_text(const std::string &raw, const std::string &name,
                                 const bool is_file, const dealii::ParameterHandler &prm)
  {
    PrmText out;
    out.main = with_lf_line_ends(raw);
    Link main{is_file ? name : std::string(), 0, 0, 0};
    // The main file's identity, for a loop back to it.
    if (struct stat st = {}; is_file && ::stat(name.c_str(), &st) == 0)
      {
        main.device = std::uint64_t(st.st_dev);
        main.inode  = std::uint64_t(st.st_ino);
      }
    Expansion(prm, out, is_file).add(out.main, {}, main);
    return out;
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

  namespace
  {
    /// "Loading/" (or "" at the top): the subsections open before @p line.
    std::string subsection_path_at(const std::string &text, const unsigned int line)
    {
      std::vector<Open> open;
      for (const Line &l : lines_of(text))
        {
          if (l.number >= line)
            break;
          if (const std::string sub = opened(l); !sub.empty())
            open.push_back({sub, l.number});
          else if (is_end(l) && !open.empty())
            open.pop_back();
        }
      return open.empty() ? "" : path_of(open) + "/";
    }

    /// The bound of a deal.II number pattern, or "" where there is none
    /// (MAX_DOUBLE, or an int's extreme).
    std::string bound(const std::string &text)
    {
      if (text.find("MAX_DOUBLE") != std::string::npos)
        return "";
      const std::string digits = text.substr(text[0] == '-' ? 1 : 0);
      return digits == "2147483647" || digits == "2147483648" ? "" : text;
    }

    /// What a value of the pattern [Double 0...1 (inclusive)] or [Integer
    /// range 1...64 (inclusive)] must be, in words: "a number from 0 to 1".
    std::string pattern_in_words(const std::string &pattern)
    {
      const bool  integer = pattern.rfind("Integer", 0) == 0;
      std::string what    = integer ? "a whole number" : "a number";
      const auto  dots    = pattern.find("...");
      if (dots == std::string::npos)
        return what;
      const auto        low_begin = pattern.rfind(' ', dots) + 1;
      const auto        high_end  = pattern.find_first_of(" ]", dots);
      const std::string low  = bound(pattern.substr(low_begin, dots - low_begin));
      const std::string high = bound(pattern.substr(dots + 3, high_end - dots - 3));
      if (!low.empty() && !high.empty())
        return what + " from " + low + " to " + high;
      if (!low.empty())
        return what + " >= " + low;
      return high.empty() ? what : what + " <= " + high;
    }
  } // namespace

  std::string explain_parse_error(const PrmText &t, const std::string &message)
  {
    // deal.II: "Line <N> of file <F>: The entry value V for the entry named E
    // does not match the given pattern: [Double ...]", or "... No entry with
    // name <E> was declared in the current subsection.", N a line of t.text.
    std::string number, file, value, entry;
    std::size_t at = 0;
    if (message.rfind("Line <", 0) != 0 || !between(message, at, "Line <", ">", number) ||
        !between(message, at, " of file <", ">: ", file) || number.empty() ||
        number.size() > 9 || number.find_first_not_of("0123456789") != std::string::npos)
      return t.files.front() + message;
    const unsigned int    line   = unsigned(std::stoul(number));
    const PrmText::Origin origin = line >= 1 && line <= t.origins.size() ?
                                     t.origins[line - 1] :
                                     PrmText::Origin{0, line};
    const std::string where = t.files[origin.file] + "line " + std::to_string(origin.line) + ": ";
    const std::string rest  = message.substr(at);
    const std::string path  = subsection_path_at(t.text, line);
    if (std::size_t k = at; between(message, k, "No entry with name <", "> was declared", entry))
      return where + (path.empty() ? "there is no entry '" + entry + "' outside a subsection" :
                                     "subsection " + path.substr(0, path.size() - 1) +
                                       " has no entry '" + entry + "'") +
             " (cdea print-parameters lists every parameter)";
    if (!between(message, at, "The entry value ", " for the entry named ", value) ||
        !between(message, at, "", " does not match the given pattern: [", entry) ||
        (message.compare(at, 6, "Double") != 0 && message.compare(at, 7, "Integer") != 0))
      return t.files[origin.file] + "Line <" + std::to_string(origin.line) + "> of file <" +
             t.names[origin.file] + ">: " + rest;
    if (not_finite(value))
      return where + path + entry + " must be a finite number, got '" + value + "'";
    return where + path + entry + " must be " + pattern_in_words(message.substr(at)) +
           ", got '" + value + "'";
  }

  std::string explain_override_error(const std::string &key, const std::string &value,
                                     const std::string &message)
  {
    const auto pattern = message.find("given pattern <[");
    if (pattern == std::string::npos ||
        (message.compare(pattern + 16, 6, "Double") != 0 &&
         message.compare(pattern + 16, 7, "Integer") != 0))
      return "";
    if (not_finite(value))
      return key + " must be a finite number, got '" + value + "'";
    return key + " must be " + pattern_in_words(message.substr(pattern + 16)) + ", got '" +
           value + "'";
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
