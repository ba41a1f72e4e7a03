#pragma once
// The text of a parameter file around deal.II's reader: read bounded (a
// regular file only), its line ends made one, its includes expanded by cdea
// (each file read and checked as the main one; no loops), its structure
// checked before deal.II parses it (subsection and end balanced, the line and
// subsection named; a '#' that would cut a name), and deal.II's messages
// said with the file and line they are about, values that are not finite
// numbers the way cdea says them ("Material/Jlim must be a finite number,
// got 'inf'").

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace cdea
{
  /// The bytes of the parameter file @p path (a regular file of at most
  /// 64 MB); throws InputError naming it and why not.
  std::string read_parameter_file(const std::string &path);

  /// A parameter file as deal.II parses it: line ends made LF (CR LF, LF
  /// and a lone CR end a line alike), and each `include FILE` line replaced
  /// by the lines of FILE, read and checked under the same rules as the main
  /// file (regular, bounded, structure, names), FILE a parameter file
  /// (*.prm) named relative to the working directory as deal.II names it.
  /// Includes nest at most 16 deep, a file that includes itself (directly or
  /// not) is refused with the chain, and the whole text is at most 64 MB.
  struct PrmText
  {
    std::string text; ///< what deal.II parses
    std::string main; ///< the main file's own text, LF line ends
    /// Where line k + 1 of text comes from: the message prefix of its file
    /// ("in parameter file 'b.prm' (included from a.prm line 3): ") and its
    /// line there.
    struct Origin
    {
      unsigned int file;
      unsigned int line;
    };
    std::vector<Origin>      origins;
    std::vector<std::string> files; ///< the prefixes, [0] the main file's
    std::vector<std::string> names; ///< the files' names, [0] the main one
  };

  /// The PrmText of @p raw, the text of the parameter file @p name (or of
  /// in-process parameter text, @p is_file false), its structure checked
  /// against the subsections declared in @p prm. Throws InputError naming
  /// the file (and the files that include it) and the line: subsection and
  /// end unbalanced in a file, a '#' that would cut a name entry
  /// (Output/Base name, Output/Directory, Time/Table file), an include that
  /// cannot be read, loops or nests too deep.
  PrmText prepare_parameter_text(const std::string &raw, const std::string &name, bool is_file,
                                 const dealii::ParameterHandler &prm);

  /// deal.II's folded message @p message about @p text, with its prefix:
  /// the file and line the message is about (an included file's, where
  /// included), and cdea's own words where they say more: a value that is
  /// not a finite number (nan, inf) for a number entry named
  /// "line 2: Material/Jlim must be a finite number, got 'inf'".
  std::string explain_parse_error(const PrmText &text, const std::string &message);

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
