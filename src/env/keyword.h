// Commands in .e files and environmental parameter files compare without
// regard to case or runs of blanks: "turtle   Position" is "turtle position".
#pragma once

#include <cctype>
#include <optional>
#include <string>
#include <string_view>

namespace sylva::env {

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

inline std::string lowercase(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A yes/no value in any case: yes, on, true, 1 or no, off, false, 0;
// std::nullopt for anything else.
inline std::optional<bool> parse_switch(std::string_view text) {
  const std::string word = lowercase(text);
  if (word == "yes" || word == "on" || word == "true" || word == "1") return true;
  if (word == "no" || word == "off" || word == "false" || word == "0") return false;
  return std::nullopt;
}

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
