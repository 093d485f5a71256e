#include "env/programs/vlab_spec_file.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <cstring>
#include <fstream>
#include <iostream>

namespace sylva::env {

std::optional<std::string> SpecLineTokens::next(const char* delimiters) {
  while (at_ < text_.size() && std::strchr(delimiters, text_[at_]) != nullptr) ++at_;
  if (at_ >= text_.size()) return std::nullopt;
  std::size_t end = at_;
  while (end < text_.size() && std::strchr(delimiters, text_[end]) == nullptr) ++end;
  std::string token = text_.substr(at_, end - at_);
  at_ = end < text_.size() ? end + 1 : end;  // strtok ends the token on the delimiter it found
  return token;
}

std::optional<double> SpecLineTokens::next_number(const char* delimiters) {
  std::optional<std::string> token = next(delimiters);
  if (!token) return std::nullopt;
  bool complete = false;
  const double value = leading_number(*token, &complete);
  if (!complete) warn("'" + *token + "' is not a number; read as " + std::to_string(value) + ", as atof reads it");
  return value;
}

std::optional<int> SpecLineTokens::next_integer(const char* delimiters) {
  std::optional<std::string> token = next(delimiters);
  if (!token) return std::nullopt;
  bool complete = false;
  const int value = leading_integer(*token, &complete);
  if (!complete) warn("'" + *token + "' is not a whole number; read as " + std::to_string(value) + ", as atoi reads it");
  return value;
}

void SpecLineTokens::next_switch(const char* delimiters, std::initializer_list<std::string_view> sets,
                                 std::initializer_list<std::string_view> leaves, bool value, bool& flag) {
  const std::optional<std::string> token = next(delimiters);
  if (!token) return;
  for (std::string_view word : sets)
    if (*token == word) {
      flag = value;
      return;
    }
  for (std::string_view word : leaves)
    if (*token == word) return;
  std::string expected;
  for (std::string_view word : sets) expected += (expected.empty() ? "'" : " or '") + std::string(word) + "'";
  warn("'" + *token + "' is not " + expected + "; the setting is left as it was, as the real program leaves it");
}

void SpecLineTokens::warn(const std::string& message) const {
  std::cerr << file_ << ":" << line_ << ": warning: " << message << "\n";
}

double leading_number(const std::string& text, bool* complete) {
  const char* start = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(start, &end);
  if (complete) *complete = end != start && *end == '\0';
  return end == start ? 0.0 : value;
}

int leading_integer(const std::string& text, bool* complete) {
  const char* start = text.c_str();
  char* end = nullptr;
  const long long value = std::strtoll(start, &end, 10);
  if (complete) *complete = end != start && *end == '\0';
  if (end == start) return 0;
  return static_cast<int>(std::clamp<long long>(value, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

bool read_vlab_spec_file(const std::filesystem::path& path, const std::string& program,
                         const std::vector<std::string>& keywords,
                         const std::function<void(std::size_t, SpecLineTokens&)>& command) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::cerr << path.string() << ": warning: " << program
              << " cannot open its specification file; every setting keeps its default, as in the real " << program
              << "\n";
    return false;
  }
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    // A '\r' before the newline stays in the last token, as it does for
    // fgets and strtok ("on\r" is not "on").
    SpecLineTokens tokens(path.string(), number, line, 0);
    const std::optional<std::string> keyword = tokens.next("\t:");
    if (!keyword || keyword->find_first_not_of(' ') == std::string::npos) continue;  // blank
    std::size_t index = 0;
    while (index < keywords.size() && keywords[index] != *keyword) ++index;
    if (index == keywords.size()) {
      tokens.warn(program + " does not know '" + *keyword + "'; the line is ignored, as " + program +
                  " ignores it (keywords are matched exactly, case and spaces included)");
      continue;
    }
    command(index, tokens);
  }
  return true;
}

}  // namespace sylva::env
