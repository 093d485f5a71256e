// Commands in .e files and environmental parameter files compare without
// regard to case or runs of blanks: "turtle   Position" is "turtle position".
#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace sylva::env {

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

inline std::string normalized_keyword(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (is_blank(c)) {
      if (!out.empty() && out.back() != ' ') out.push_back(' ');
    } else {
      out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

}  // namespace sylva::env
