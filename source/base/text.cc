#include <cdea/base/text.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    std::string format(const double x)
    {
      std::ostringstream o;
      o << x;
      return o.str();
    }

    /// Round to 12 decimals: generated values equal the typed ones.
    constexpr double twelve_decimals = 1e12;
    double round12(const double x) { return std::round(x * twelve_decimals) / twelve_decimals; }

    constexpr std::size_t max_values = 100000;
  } // namespace

  InputError::InputError(const std::string &message)
    : std::runtime_error(clip_long_values(message))
  {}

  std::string clip_long_values(const std::string &message)
  {
    constexpr std::size_t longest_word = 80, kept = 60, longest = 1500;
    std::string           out;
    std::size_t           i = 0;
    while (i < message.size())
      {
        const std::size_t end = std::min(message.find(' ', i), message.size());
        if (end - i > longest_word)
          out += message.substr(i, kept) + "...[" + std::to_string(end - i) + " characters]";
        else
          out += message.substr(i, end - i);
        if (end < message.size())
          out += ' ';
        i = end + 1;
      }
    if (out.size() > longest)
      out = out.substr(0, longest - 300) + " ...[" + std::to_string(out.size()) +
            " characters in all]... " + out.substr(out.size() - 200);
    return out;
  }

  std::vector<std::string> split_list(const std::string &text, const char separator)
  {
    std::vector<std::string> pieces;
    std::size_t              begin = 0;
    while (begin < text.size())
      {
        const std::size_t end = std::min(text.find(separator, begin), text.size());
        pieces.push_back(text.substr(begin, end - begin));
        begin = end + 1;
      }
    return pieces;
  }

  bool ends_with_separator(const std::string &text, const char separator)
  {
    const auto last = text.find_last_not_of(" \t");
    return last != std::string::npos && text[last] == separator;
  }

  std::string trim_blanks(const std::string &text)
  {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
      return "";
    const auto last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
  }

  double parse_number(const std::string &token, const std::string &name, const std::string &text)
  {
    std::size_t used  = 0;
    double      value = 0.;
    try
      {
        value = std::stod(token, &used);
      }
    catch (const std::exception &)
      {
        used = 0;
      }
    if (used != token.size() || !std::isfinite(value))
      {
        // The whole entry as context only where it adds to the token: a long
        // token is echoed once.
        const bool context = text != token && token.size() <= 100;
        throw InputError(name + ": '" + token + "' is not a number" +
                         (context ? " (in '" + text + "')" : std::string()));
      }
    return value;
  }

  std::vector<double> parse_number_list(const std::string &text, const std::string &name)
  {
    std::vector<double> values;
    for (const std::string &item : split_list(text, ','))
      {
        const std::string token = trim_blanks(item);
        if (token.empty())
          throw InputError(name + ": empty entry in '" + text +
                           "' (expected numbers separated by ',')");
        values.push_back(parse_number(token, name, text));
      }
    if (values.empty())
      throw InputError(name + ": no value given (expected numbers separated by ',')");
    if (ends_with_separator(text, ','))
      throw InputError(name + ": empty entry at the end of '" + text + "'");
    return values;
  }

  void require_positive(const double value, const std::string &name)
  {
    if (!(value > 0.) || !std::isfinite(value))
      throw InputError(name + " must be positive, got " + format(value));
  }

  void require_range(const double value, const double lo, const double hi, const std::string &name,
                     const std::string &why, const bool zero_allowed)
  {
    if (zero_allowed && value == 0.)
      return;
    if (lo > 0. && value <= 0.)
      throw InputError(name + (zero_allowed ? " must be zero or positive, got " :
                                              " must be positive, got ") +
                       format(value));
    if (!(value >= lo && value <= hi))
      throw InputError(name + " must be " + (zero_allowed ? "0 or " : "") + "between " +
                       format(lo) + " and " + format(hi) + why + ", got " + format(value));
  }

  std::vector<double> expand_value_list(const std::string &text, const std::string &name)
  {
    // Items: numbers, or the marker "..." (represented by NaN in `items`).
    std::vector<double>      items;
    std::vector<std::string> tokens;
    for (const std::string &item : split_list(text, ','))
      {
        const std::string token = trim_blanks(item);
        if (token.empty())
          throw InputError(name + ": empty entry in '" + text +
                           "' (expected numbers separated by ',', and '...')");
        if (token == "...")
          {
            items.push_back(nan);
            tokens.push_back(token);
            continue;
          }
        items.push_back(parse_number(token, name, text));
        tokens.push_back(token);
      }
    if (ends_with_separator(text, ','))
      throw InputError(name + ": empty entry at the end of '" + text + "'");
    if (items.empty())
      throw InputError(name + ": no value given (expected numbers separated by ',')");

    std::vector<double> values;
    for (std::size_t i = 0; i < items.size(); ++i)
      {
        if (!std::isnan(items[i]))
          {
            values.push_back(items[i]);
            continue;
          }
        if (i < 2 || std::isnan(items[i - 1]) || std::isnan(items[i - 2]) ||
            i + 1 >= items.size() || std::isnan(items[i + 1]))
          throw InputError(name + ": '...' needs two numbers before it and one after it (in '" +
                           text + "')");
        const double a = items[i - 2], b = items[i - 1], c = items[i + 1];
        const double d = b - a;
        if (d == 0.)
          throw InputError(name + ": the two values before '...' are equal (" + format(a) +
                           "), so they define no sequence");
        const double steps = (c - b) / d;
        const double k_end = std::round(steps);
        if (k_end < 1.)
          throw InputError(name + ": " + tokens[i + 1] + " after '...' does not continue " +
                           tokens[i - 2] + ", " + tokens[i - 1] + " (step " + format(d) + ")");
        if (std::abs(steps - k_end) > 1e-6)
          throw InputError(name + ": " + tokens[i + 1] + " after '...' is not on the sequence " +
                           tokens[i - 2] + ", " + tokens[i - 1] + ", ... (step " + format(d) +
                           ")");
        if (k_end > double(max_values))
          throw InputError(name + ": '" + text + "' has more than " +
                           std::to_string(max_values) + " values");
        for (long k = 1; k < long(k_end); ++k)
          values.push_back(round12(b + k * d));
      }
    if (values.size() > max_values)
      throw InputError(name + ": '" + text + "' has more than " + std::to_string(max_values) +
                       " values");
    return values;
  }
} // namespace cdea
