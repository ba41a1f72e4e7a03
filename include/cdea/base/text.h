#pragma once
// Text the user typed: the one error type for bad input, the one splitter of
// lists ("5, 5; 5, 6.5" at ';', then at ','), and the one parser of number
// lists ("1, 1.7, 3"; "1.2, 1.25, ..., 2.6"). Every message names the
// parameter it is about and what is allowed.

#include <stdexcept>
#include <string>
#include <vector>

namespace cdea
{
  /// Bad user input: the message names the parameter and what is allowed.
  class InputError : public std::runtime_error
  {
  public:
    /// Long values in @p message are shortened (clip_long_values()).
    explicit InputError(const std::string &message);
  };

  /// An input file that does not exist (Python: FileNotFoundError, a
  /// command: the same message and exit code as any InputError).
  class MissingFileError : public InputError
  {
  public:
    using InputError::InputError;
  };

  /// @p message with every word longer than 80 characters cut to its first
  /// 60 and a count, and the whole kept below about 1500 characters: a
  /// 1 MB value in the input is not echoed back whole.
  std::string clip_long_values(const std::string &message);

  /// One finite number, the whole of @p token; otherwise an InputError naming
  /// the parameter @p name and the entry @p text it came from.
  double parse_number(const std::string &token, const std::string &name, const std::string &text);

  /// An InputError "NAME must be positive, got VALUE" unless 0 < value < infinity.
  void require_positive(double value, const std::string &name);

  /// An InputError naming @p name unless @p value lies in [lo, hi] (with
  /// @p zero_allowed, or is 0): "must be positive" (or "zero or positive")
  /// for a value <= 0 when lo > 0, else "must be [0 or ]between LO and HI" +
  /// @p why + ", got VALUE".
  void require_range(double value, double lo, double hi, const std::string &name,
                     const std::string &why, bool zero_allowed = false);

  /// @p text cut at every @p separator, the pieces as they are (blanks kept).
  /// As std::getline() reads them: an empty @p text has no piece, and a
  /// separator at the very end closes the last piece without opening another
  /// (callers that refuse a trailing separator check ends_with_separator()).
  std::vector<std::string> split_list(const std::string &text, char separator);

  /// Whether the last character of @p text other than blanks is @p separator.
  bool ends_with_separator(const std::string &text, char separator);

  /// @p text without its leading and trailing blanks (spaces and tabs).
  std::string trim_blanks(const std::string &text);

  /// Parse "1, 1.7, 3" into numbers; @p name is used in error messages.
  std::vector<double> parse_number_list(const std::string &text, const std::string &name);

  /// Parse a list of numbers separated by ',' in which the item '...'
  /// continues the arithmetic sequence of the two values before it up to the
  /// value after it ("1.2, 1.25, 1.3, ..., 2.6"). The value after '...' must lie
  /// on that sequence. Generated values are rounded to 12 decimals, so that
  /// "1.6, 1.7, ..., 2" gives exactly the doubles of "1.8" and "1.9".
  /// Throws InputError naming @p name.
  std::vector<double> expand_value_list(const std::string &text, const std::string &name);
} // namespace cdea
