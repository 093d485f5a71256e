#include "lang/literal_numbers.h"

#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace sylva::lang {
namespace {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

// The value of a number literal, integer or floating, with its sign; nothing
// when the text is anything else.
std::optional<long double> literal_value(std::string_view text) {
  text = trimmed(text);
  while (text.size() >= 2 && text.front() == '(' && text.back() == ')') text = trimmed(text.substr(1, text.size() - 2));
  bool negative = false;
  while (!text.empty() && (text.front() == '-' || text.front() == '+')) {
    negative ^= text.front() == '-';
    text = trimmed(text.substr(1));
    while (text.size() >= 2 && text.front() == '(' && text.back() == ')') text = trimmed(text.substr(1, text.size() - 2));
  }
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front()))) return std::nullopt;
  const std::string digits(text);
  const char* end = nullptr;
  const bool hex_or_binary = digits.size() > 1 && digits[0] == '0' && std::isalpha(static_cast<unsigned char>(digits[1]));
  long double value;
  if (hex_or_binary || digits.find_first_of(".eE") == std::string::npos) {
    // Whole numbers exactly, however long: strtold would round them.
    const int base = digits.size() > 1 && (digits[1] == 'x' || digits[1] == 'X')   ? 16
                     : digits.size() > 1 && (digits[1] == 'b' || digits[1] == 'B') ? 2
                     : digits.size() > 1 && digits[0] == '0'                       ? 8
                                                                                   : 10;
    const char* first = digits.c_str() + (base == 16 || base == 2 ? 2 : 0);
    unsigned long long whole = 0;
    auto [stop, error] = std::from_chars(first, digits.c_str() + digits.size(), whole, base);
    if (stop == first) return std::nullopt;
    value = error == std::errc::result_out_of_range ? HUGE_VALL : static_cast<long double>(whole);
    end = stop;
  } else {
    char* stop = nullptr;
    value = std::strtold(digits.c_str(), &stop);
    end = stop;
  }
  for (; *end; ++end)
    if (!std::strchr("uUlLfF", *end)) return std::nullopt;
  return negative ? -value : value;
}

}  // namespace

std::optional<int> nonnegative_int(std::string_view literal) {
  const std::string_view text = trimmed(literal);
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front()))) return std::nullopt;
  const std::optional<long double> value = literal_value(text);
  if (!value || *value > INT_MAX || *value != std::floor(*value)) return std::nullopt;
  return static_cast<int>(*value);
}

std::string range_error(std::string_view what, std::string_view expression, bool negative_allowed) {
  const std::optional<long double> value = literal_value(expression);
  if (!value) return {};
  const std::string written = std::string(what) + " " + std::string(trimmed(expression));
  if (*value > INT_MAX) return written + " is too large (at most " + std::to_string(INT_MAX) + ")";
  if (*value < INT_MIN || (!negative_allowed && *value < 0))
    return written + " is out of range (0 to " + std::to_string(INT_MAX) + ")";
  return {};
}

std::string setting_range_error(Setting::Kind kind, std::string_view expression) {
  if (kind == Setting::kRing) return {};
  return kind == Setting::kDerivationLength ? range_error("the derivation length", expression, true)
                                            : range_error("the maximum depth", expression, false);
}

}  // namespace sylva::lang
