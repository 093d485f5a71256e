// The C preprocessor's line markers: `# 12 "file" 1 3` (gcc -E's form) or
// `#line 12 "file"`: the line after the marker is line 12 of `file`.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace sylva {

struct LineMarker {
  int line = 0;
  std::string file;            // with the marker's backslash escapes undone
  bool enters_file = false;    // flag 1: the start of an #included file
  bool system_header = false;  // flag 3: the text comes from a system header
};

// The marker `text` (one line, without its newline) is, or nullopt when it
// is not a line marker (another directive, or text that starts with '#').
std::optional<LineMarker> parse_line_marker(std::string_view text);

}  // namespace sylva
