#pragma once
// Where the parameters of a run come from: a parameter file (the command
// line), or prm text handed over in-process (the Python module), either with
// overrides "Subsection/Entry" = value set after it (the command line's
// `--set`, the Python module's `overrides`). One reader for both, so that bad
// input gives the same message whichever way it came; and the one writer of
// parameter files derived from the input (the design commands' replays).

#include <string>
#include <utility>
#include <vector>

namespace cdea
{
  struct Parameters;

  struct ParameterInput
  {
    /// A parameter file (a name ending in .prm, or .json/.xml as deal.II reads them).
    static ParameterInput file(const std::string &path);
    /// The text of a .prm file; "" gives every default.
    static ParameterInput text(const std::string &prm_text);

    bool        is_text = false;
    std::string source; ///< the path, or the text
    /// Entries set after the file or text, in this order, e.g.
    /// {"Loading/Mass (g)", "300"}: the subsection, '/', the entry's name.
    std::vector<std::pair<std::string, std::string>> overrides;
  };

  /// Read and validate (Parameters::scene(), validate_ranges(),
  /// validate_time(), validate_load_terms()) the parameters of @p input. Throws InputError with a
  /// message that names the file (or "parameter text"), the line or the
  /// parameter; an override that names no declared entry, or whose value the
  /// entry does not allow, is named by its key. Entries set twice become
  /// Parameters::input_warnings. @p text receives every parameter as deal.II
  /// writes them back (for the results file), overrides included.
  Parameters read_parameters(const ParameterInput &input, std::string *text = nullptr);

  /// The same for the parameter file @p filename without overrides.
  Parameters read_parameters(const std::string &filename, std::string *text = nullptr);

  /// One entry of a parameter file to set: subsection, entry, value.
  struct ParameterChange
  {
    std::string subsection, entry, value;
  };

  /// Writes the parameters of @p input (overrides included) with @p changes
  /// applied to @p path (all entries, as deal.II prints them; replaced only
  /// once complete), after the comment lines @p comment. Throws
  /// std::runtime_error naming @p path.
  void write_changed_parameters(const ParameterInput &input, const std::string &path,
                                const std::vector<ParameterChange> &changes,
                                const std::string                  &comment);
} // namespace cdea
