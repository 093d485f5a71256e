// Files read or written whole.
#pragma once

#include <string>
#include <string_view>

namespace sylva {

struct WholeFile {
  // Why a file could not be read; each caller words its own message.
  enum class Failure { None, IsFolder, CannotOpen, CannotRead };
  std::string bytes;
  Failure failure = Failure::None;
  explicit operator bool() const { return failure == Failure::None; }
};

// The file's bytes. A folder opens as a stream on Linux and reads as
// nothing, so it is a failure of its own rather than an empty file.
WholeFile read_whole_file(const std::string& path);

// Writes `content` to a temporary file beside `path` and renames it over
// `path` once complete, so readers never see half a file. A file replaced
// keeps its permission bits. Returns 0, or the errno of what failed (the
// temporary file removed, `path` untouched).
int write_file_atomically(const std::string& path, std::string_view content);

}  // namespace sylva
