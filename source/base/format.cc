#include <cdea/base/format.h>
#include <cdea/base/units.h>

#include <cstdio>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace cdea
{
  std::string format_kV(const std::vector<double> &volts, const int digits)
  {
    std::ostringstream o;
    o.precision(digits);
    for (std::size_t i = 0; i < volts.size(); ++i)
      o << (i ? ", " : "") << units::kV.from_si(volts[i]);
    return o.str() + " kV";
  }

  std::string format_kV(const double volts, const int digits)
  {
    return format_kV(std::vector<double>{volts}, digits);
  }

  std::string format_number(const double value, const int digits)
  {
    std::ostringstream o;
    o.precision(digits);
    o << value;
    return o.str();
  }

  std::string format_fixed(const double value, const int decimals, const int width)
  {
    std::ostringstream o;
    o << std::fixed << std::setprecision(decimals) << std::setw(width) << value;
    return o.str();
  }

  std::string exact_number(const double value)
  {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
  }

  std::string format_fixed_or_dash(const double value, const int decimals)
  {
    return std::isnan(value) ? "-" : format_fixed(value, decimals);
  }

  std::string format_fixed_list(const std::vector<double> &values, const int decimals,
                                const double factor)
  {
    std::string s;
    for (std::size_t i = 0; i < values.size(); ++i)
      s += (i ? " " : "") + format_fixed(values[i] * factor, decimals);
    return s;
  }

  std::string shorten_at_word(const std::string &text, const std::size_t width)
  {
    if (text.size() <= width)
      return text;
    const std::string more = " ...";
    // The last blank that leaves room for the marker; a first word longer
    // than that is kept whole.
    std::size_t cut = text.rfind(' ', width - more.size());
    if (cut == std::string::npos || cut == 0)
      cut = text.find(' ');
    if (cut == std::string::npos)
      return text;
    while (cut > 0 && (text[cut - 1] == ' ' || text[cut - 1] == ',' || text[cut - 1] == ':'))
      --cut;
    return text.substr(0, cut) + more;
  }
  std::string format_bytes(const double bytes)
  {
    const char *units[] = {"bytes", "kB", "MB", "GB", "TB"};
    double      value   = bytes;
    int         unit    = 0;
    for (; unit < 4 && value >= 999.5; ++unit)
      value /= 1e3;
    return format_number(value, 3) + " " + units[unit];
  }
} // namespace cdea
