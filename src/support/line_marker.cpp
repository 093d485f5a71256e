#include "support/line_marker.h"

#include <algorithm>

namespace sylva {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// No preprocessor numbers real lines this far; refusing larger numbers keeps
// the count of the lines after a marker within int.
constexpr int kMaxLine = 1 << 30;

}  // namespace

std::optional<LineMarker> parse_line_marker(std::string_view text) {
  std::size_t i = 0;
  auto skip_blanks = [&] {
    const std::size_t start = i;
    while (i < text.size() && is_blank(text[i])) ++i;
    return i > start;
  };
  if (text.empty() || text[0] != '#') return std::nullopt;
  ++i;
  skip_blanks();
  if (text.substr(i).starts_with("line")) {
    i += 4;
    if (!skip_blanks()) return std::nullopt;
  }
  if (i >= text.size() || !is_digit(text[i])) return std::nullopt;
  LineMarker marker;
  while (i < text.size() && is_digit(text[i])) {
    const int digit = text[i++] - '0';
    if (marker.line > (kMaxLine - digit) / 10) return std::nullopt;
    marker.line = marker.line * 10 + digit;
  }
  if (!skip_blanks() || i >= text.size() || text[i] != '"') return std::nullopt;
  for (++i; i < text.size() && text[i] != '"'; ++i) {
    if (text[i] == '\\' && i + 1 < text.size()) ++i;
    marker.file += text[i];
  }
  if (i >= text.size()) return std::nullopt;  // no closing quote
  ++i;
  while (skip_blanks(), i < text.size() && is_digit(text[i])) {
    int flag = 0;
    while (i < text.size() && is_digit(text[i])) flag = std::min(flag * 10 + (text[i++] - '0'), 10);  // 1..4 only
    if (flag == 1) marker.enters_file = true;
    if (flag == 3) marker.system_header = true;
  }
  return marker;
}

}  // namespace sylva
