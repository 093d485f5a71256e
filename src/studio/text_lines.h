// The lines of a text file as views into it, for the studio's small readers
// and editors: they report line numbers and must leave every other byte of a
// file as it was.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace sylva::studio {

struct TextLine {
  std::string_view text;  // without its "\n" or "\r\n"
  std::size_t offset = 0;  // of the line's first byte in the whole text
  int number = 0;          // 1-based
};

// A final line without "\n" is a line; the empty text has none.
std::vector<TextLine> split_lines(std::string_view text);

// `text` without blanks (spaces, tabs, carriage returns) at either end.
std::string_view trim_blanks(std::string_view text);

// The blank-separated words of `text`, as awk's default field splitting
// finds them.
std::vector<std::string_view> split_words(std::string_view text);

}  // namespace sylva::studio
