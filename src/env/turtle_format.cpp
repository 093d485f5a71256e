#include "env/turtle_format.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace sylva::env {
namespace {

constexpr const char* kFloatConversions = "fFeEgGaA";
constexpr const char* kIntConversions = "diouxX";

bool is_one_of(char c, const char* set) { return c != '\0' && std::strchr(set, c) != nullptr; }

// The conversion starting at text[at] == '%': its length, or 0 if it is not
// one we accept.
std::size_t conversion_length(std::string_view text, std::size_t at) {
  std::size_t k = at + 1;
  while (k < text.size() && is_one_of(text[k], "-+ #0")) ++k;
  for (int digits = 0; k < text.size() && text[k] >= '0' && text[k] <= '9'; ++k)
    if (++digits > 3) return 0;
  if (k < text.size() && text[k] == '.') {
    ++k;
    for (int digits = 0; k < text.size() && text[k] >= '0' && text[k] <= '9'; ++k)
      if (++digits > 3) return 0;
  }
  if (k >= text.size() || !(is_one_of(text[k], kFloatConversions) || is_one_of(text[k], kIntConversions))) return 0;
  return k + 1 - at;
}

}  // namespace

bool parse_turtle_format(std::string_view text, int max_values, TurtleFormat& out, std::string& error,
                         std::size_t& column) {
  out = TurtleFormat{std::string(text), 0};
  for (std::size_t at = 0; at < text.size(); ++at) {
    if (text[at] != '%') continue;
    if (at + 1 < text.size() && text[at + 1] == '%') {
      ++at;
      continue;
    }
    const std::size_t length = conversion_length(text, at);
    if (length == 0) {
      error = "expected a number conversion such as %g, %f or %.3f";
      column = at;
      return false;
    }
    if (++out.count > max_values) {
      error = "at most " + std::to_string(max_values) + (max_values == 1 ? " value" : " values") +
              " can be sent for this field";
      column = at;
      return false;
    }
    at += length - 1;
  }
  return true;
}

std::string format_turtle_values(const TurtleFormat& format, const float* values) {
  const std::string_view text = format.text;
  std::string out;
  int used = 0;
  char buffer[512];
  for (std::size_t at = 0; at < text.size(); ++at) {
    if (text[at] != '%') {
      out.push_back(text[at]);
      continue;
    }
    if (at + 1 < text.size() && text[at + 1] == '%') {
      out.push_back('%');
      ++at;
      continue;
    }
    const std::size_t length = conversion_length(text, at);
    const std::string spec(text.substr(at, length));
    const double value = used < format.count ? values[used] : 0.0;
    ++used;
    if (is_one_of(spec.back(), kIntConversions)) {
      // The integer part, as a C program passing an int would print it;
      // past the range of long long, the nearest end of it (converting would
      // be undefined).
      const double whole = std::trunc(value);
      long long as_int = 0;  // for infinities and NaN
      if (std::isfinite(whole))
        as_int = whole >= 0x1p63    ? std::numeric_limits<long long>::max()
                 : whole < -0x1p63 ? std::numeric_limits<long long>::min()
                                   : static_cast<long long>(whole);
      std::string ll_spec = spec.substr(0, spec.size() - 1) + "ll" + spec.back();
      std::snprintf(buffer, sizeof buffer, ll_spec.c_str(), as_int);
    } else {
      std::snprintf(buffer, sizeof buffer, spec.c_str(), value);
    }
    out += buffer;
    at += length - 1;
  }
  return out;
}

}  // namespace sylva::env
