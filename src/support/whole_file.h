// Files read or written whole.
#pragma once

#include <functional>
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

// Receives a file's content piece by piece, in order.
using ContentSink = std::function<void(std::string_view)>;
// Produces a file's content by handing it to the sink in pieces. It may
// throw: the file is then left as it was.
using ContentProducer = std::function<void(const ContentSink&)>;

// The same, with the content handed over in pieces, so that it need never
// be whole in memory. An exception from `produce` removes the temporary
// file and passes on.
int write_file_atomically(const std::string& path, const ContentProducer& produce);
}  // namespace sylva
