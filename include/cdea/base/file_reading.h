#pragma once
// Input files read whole and bounded: only a regular file is read (a FIFO, a
// device such as /dev/zero, a socket or a directory is refused without
// blocking), and never more than a limit, so no input can hang a command or
// fill its memory.

#include <cstddef>
#include <string>

namespace cdea
{
  /// What read_regular_file() found.
  struct FileRead
  {
    bool        ok = false;
    std::string bytes; ///< the whole file if ok
    /// Why not, as the end of a sentence about the file: "it does not
    /// exist", "it is a directory", "it is not a regular file (a FIFO)", ...
    std::string error;
  };

  /// The bytes of the regular file @p path, at most @p max_bytes of them.
  FileRead read_regular_file(const std::string &path, std::size_t max_bytes);

  /// Whether @p path names a regular file (after symbolic links).
  bool is_regular_file(const std::string &path);

  /// @p text with every byte outside printable ASCII written as \xNN, so
  /// that an invisible byte (a UTF-8 byte order mark, a tab) shows in a
  /// message.
  std::string printable(const std::string &text);
} // namespace cdea
