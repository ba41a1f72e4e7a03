#pragma once
// The text of a parameter file around deal.II's reader: read bounded (a
// regular file only), its structure checked before deal.II parses it
// (subsection and end balanced, the line and subsection named; a '#' that
// would cut a name), and deal.II's messages about values that are not finite
// numbers said the way cdea says them ("Material/Jlim must be a finite
// number, got 'inf'").

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{
  /// The bytes of the parameter file @p path (a regular file of at most
  /// 64 MB); throws InputError naming it and why not.
  std::string read_parameter_file(const std::string &path);

  /// Checks the subsection/end structure of the prm text @p text against
  /// the subsections declared in @p prm (messages start with @p where, "in
  /// parameter file 'x.prm': ", then "line N: "), and
  /// that no name entry (Output/Base name, Output/Directory, Time/Table file)
  /// holds a '#' right after a character of the name (deal.II would cut the
  /// name there: a comment). Throws InputError naming the line.
  void check_prm_structure(const std::string &text, const std::string &where,
                           const dealii::ParameterHandler &prm);

  /// deal.II's folded message @p message about the prm text @p text, or
  /// cdea's own where it says more: a value that is not a finite number
  /// (nan, inf) for a number entry named "Subsection/Entry must be a finite
  /// number, got 'inf'" with its line.
  std::string explain_parse_error(const std::string &text, const std::string &message);

  /// The same for the override @p key = @p value ("" if deal.II's message
  /// @p message is to stay).
  std::string explain_override_error(const std::string &key, const std::string &value,
                                     const std::string &message);

  /// Throws InputError if the override @p key = @p value holds a '#': a
  /// parameter file cuts a value there (a comment), so the parameter files
  /// cdea writes (the results' parameters, optimize's and fit's replays)
  /// could not hold it.
  void check_override_value(const std::string &key, const std::string &value);
} // namespace cdea
