#pragma once
// Input files read whole and bounded: only a regular file is read (a FIFO, a
// device such as /dev/zero, a socket or a directory is refused without
// blocking), and never more than a limit, so no input can hang a command or
// fill its memory.

#include <cstddef>
#include <cstdint>
#include <functional>
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
    /// Which file was read (st_dev, st_ino of the open file): the same
    /// file under another name has the same pair.
    std::uint64_t device = 0, inode = 0;
  };

  /// How read_regular_file() reads.
  struct ReadOptions
  {
    /// Follow a symbolic link at @p path (a user's input: yes; a file cdea
    /// wrote itself, a journal or a checkpoint: no, a link there is not one).
    bool follow_links = true;
    /// With head_bytes > 0: the first head_bytes bytes (fewer if the file is
    /// shorter) go to check_head before the rest is read; it throws to stop
    /// (a file that is not what it should be is not read whole).
    std::size_t                                  head_bytes = 0;
    std::function<void(const std::string &head)> check_head;
  };

  /// The bytes of the regular file @p path, at most @p max_bytes of them.
  /// The file is opened once and checked on the open file (fstat), so a
  /// name swapped after a check cannot slip another file in.
  FileRead read_regular_file(const std::string &path, std::size_t max_bytes,
                             const ReadOptions &options = {});

  /// Whether @p path names a regular file (after symbolic links unless
  /// @p follow_links is false).
  bool is_regular_file(const std::string &path, bool follow_links = true);

  /// What a st_mode says a file is: "a regular file", "a directory", "a
  /// symbolic link", "a FIFO", "a device", "a socket".
  std::string file_kind(unsigned int st_mode);

  /// Whether the file name of @p path ends in @p extension (".csv", ".prm"),
  /// letters compared without case: cdea quotes lines of its own kinds of
  /// files in messages, and reads no other kind where it would.
  bool has_extension(const std::string &path, const std::string &extension);

  /// @p text with every byte outside printable ASCII written as \xNN, so
  /// that an invisible byte (a UTF-8 byte order mark, a tab) shows in a
  /// message.
  std::string printable(const std::string &text);
} // namespace cdea
