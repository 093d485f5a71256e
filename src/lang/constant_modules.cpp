#include "lang/constant_modules.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>
#include <unordered_map>

namespace sylva::lang {
namespace {

// A literal's value with the type C++ gives it.
struct Literal {
  enum Kind { kInteger, kDouble, kFloat } kind = kInteger;
  long long integer = 0;  // kInteger: an int or a long, by its size
  double real = 0;        // kDouble; kFloat: the float's value, exactly
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_space(char c) { return c == ' ' || c == '\t'; }

std::size_t digits_from(std::string_view s, std::size_t i) {
  while (i < s.size() && is_digit(s[i])) ++i;
  return i;
}

// A decimal integer literal without suffix, or a decimal floating literal
// with an optional f or F: the forms whose value the translator can take
// exactly as the compiler does. Others (hex, octal, separators, other
// suffixes) stay code.
std::optional<Literal> number(std::string_view s) {
  std::size_t i = digits_from(s, 0);
  const bool whole = i > 0;
  bool floating = false;
  if (i < s.size() && s[i] == '.') {
    floating = true;
    const std::size_t fraction = digits_from(s, i + 1);
    if (!whole && fraction == i + 1) return std::nullopt;
    i = fraction;
  } else if (!whole) {
    return std::nullopt;
  }
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    floating = true;
    std::size_t e = i + 1;
    if (e < s.size() && (s[e] == '+' || s[e] == '-')) ++e;
    const std::size_t end = digits_from(s, e);
    if (end == e) return std::nullopt;
    i = end;
  }
  const std::string_view digits = s.substr(0, i);
  const std::string_view suffix = s.substr(i);
  Literal literal;
  if (!floating) {
    if (!suffix.empty() || (digits.size() > 1 && digits[0] == '0')) return std::nullopt;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), literal.integer);
    if (ec != std::errc()) return std::nullopt;  // past long: the compiler's own business
    return literal;
  }
  if (suffix == "f" || suffix == "F") {
    float value = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
    literal.kind = Literal::kFloat;
    literal.real = value;
    return literal;
  }
  if (!suffix.empty()) return std::nullopt;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), literal.real);
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
  literal.kind = Literal::kDouble;
  return literal;
}

// `1.5`, `-3`, `(-30.0)`, `static_cast<float>(2)` (as the cpfg front end
// writes its constants): a number under any signs, parentheses and casts to
// float, read without recursion. Negation commutes with rounding to float,
// so the order of signs and casts does not matter.
std::optional<Literal> literal(std::string_view s) {
  static constexpr std::string_view kFloatCast = "static_cast<float>";
  std::size_t i = 0;
  int open = 0;
  bool negative = false, to_float = false;
  for (;;) {
    while (i < s.size() && is_space(s[i])) ++i;
    if (i == s.size()) return std::nullopt;
    if (s[i] == '(') {
      ++open;
      ++i;
    } else if (s[i] == '-' || s[i] == '+') {
      if (i + 1 < s.size() && s[i + 1] == s[i]) return std::nullopt;  // -- and ++
      negative ^= s[i] == '-';
      ++i;
    } else if (s.substr(i).starts_with(kFloatCast)) {
      i += kFloatCast.size();
      while (i < s.size() && is_space(s[i])) ++i;
      if (i == s.size() || s[i] != '(') return std::nullopt;
      to_float = true;
    } else {
      break;
    }
  }
  std::size_t end = i;
  while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '.' || s[end] == '\'' ||
                            ((s[end] == '+' || s[end] == '-') && end > i && (s[end - 1] == 'e' || s[end - 1] == 'E'))))
    ++end;
  std::optional<Literal> value = number(s.substr(i, end - i));
  if (!value) return std::nullopt;
  for (i = end; i < s.size(); ++i) {
    if (is_space(s[i])) continue;
    if (s[i] != ')' || open == 0) return std::nullopt;
    --open;
  }
  if (open != 0) return std::nullopt;
  if (negative) {
    value->integer = -value->integer;
    value->real = -value->real;
  }
  if (to_float && value->kind != Literal::kFloat) {
    const float f = value->kind == Literal::kInteger ? static_cast<float>(value->integer)
                                                     : static_cast<float>(value->real);
    if (std::isinf(f)) return std::nullopt;  // out of float's range: undefined
    value->kind = Literal::kFloat;
    value->real = f;
  }
  return value;
}

// Appends the bytes of `value` converted to T as an implicit conversion
// would; false where that conversion is undefined.
template <class T>
bool append_as(const Literal& value, std::string& bytes) {
  T converted;
  if constexpr (std::is_same_v<T, bool>) {
    converted = value.kind == Literal::kInteger ? value.integer != 0 : value.real != 0;
  } else if constexpr (std::is_floating_point_v<T>) {
    converted = value.kind == Literal::kInteger ? static_cast<T>(value.integer) : static_cast<T>(value.real);
    if (std::isinf(converted)) return false;
  } else if (value.kind == Literal::kInteger) {
    converted = static_cast<T>(value.integer);  // modulo 2^N, as C++20 defines it
  } else {
    const double truncated = std::trunc(value.real);
    if (!(truncated >= static_cast<double>(std::numeric_limits<T>::min()) &&
          truncated <= static_cast<double>(std::numeric_limits<T>::max()) && std::abs(truncated) < 0x1p62))
      return false;
    converted = static_cast<T>(static_cast<long long>(truncated));
  }
  char raw[sizeof(T)];
  std::memcpy(raw, &converted, sizeof raw);
  bytes.append(raw, sizeof raw);
  return true;
}

using Appender = bool (*)(const Literal&, std::string&);

// The built-in types a parameter's type is spelled as (the L+C parser joins
// its words with one space); other names may be typedefs or classes.
Appender appender_for(const std::string& type) {
  static const std::unordered_map<std::string, Appender> appenders = {
      {"float", &append_as<float>},
      {"double", &append_as<double>},
      {"bool", &append_as<bool>},
      {"char", &append_as<char>},
      {"signed char", &append_as<signed char>},
      {"unsigned char", &append_as<unsigned char>},
      {"short", &append_as<short>},
      {"short int", &append_as<short>},
      {"unsigned short", &append_as<unsigned short>},
      {"int", &append_as<int>},
      {"signed", &append_as<int>},
      {"signed int", &append_as<int>},
      {"unsigned", &append_as<unsigned>},
      {"unsigned int", &append_as<unsigned>},
      {"long", &append_as<long>},
      {"long int", &append_as<long>},
      {"unsigned long", &append_as<unsigned long>},
      {"long long", &append_as<long long>},
      {"unsigned long long", &append_as<unsigned long long>},
  };
  auto it = appenders.find(type);
  return it == appenders.end() ? nullptr : it->second;
}

std::optional<Literal> literal_argument(const Code& arg) {
  std::string text;
  for (const Token& t : arg) {
    if (t.kind != TokenKind::Identifier && t.kind != TokenKind::Number && t.kind != TokenKind::Punct)
      return std::nullopt;
    text += t.text;
    text += ' ';
  }
  return literal(text);
}

template <void (*put)(unsigned char*&, abi::ModuleId)>
void append_id(abi::ModuleId id, std::string& bytes) {
  unsigned char raw[4];
  unsigned char* end = raw;
  put(end, id);
  bytes.append(reinterpret_cast<const char*>(raw), static_cast<std::size_t>(end - raw));
}

}  // namespace

std::optional<std::string> constant_module_bytes(abi::ModuleId id, const std::vector<std::string>& param_types,
                                                 const std::vector<Code>& args) {
  if (args.size() != param_types.size()) return std::nullopt;
  std::string bytes;
  if (args.empty()) {
    append_id<abi::put_parameterless>(id, bytes);
    return bytes;
  }
  append_id<abi::put_leading_id>(id, bytes);
  for (std::size_t k = 0; k < args.size(); ++k) {
    const Appender append = appender_for(param_types[k]);
    if (!append) return std::nullopt;
    const std::optional<Literal> value = literal_argument(args[k]);
    if (!value || !append(*value, bytes)) return std::nullopt;
  }
  append_id<abi::put_trailing_id>(id, bytes);
  return bytes;
}

std::string bytes_literal(const std::string& bytes) {
  std::string text = "\"";
  text.reserve(bytes.size() * 4 + 2);
  for (unsigned char c : bytes) {
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\' && c != '?') {
      text += static_cast<char>(c);
    } else {
      // Always three octal digits, so a digit after it is not read into it.
      const char octal[] = {'\\', static_cast<char>('0' + (c >> 6)), static_cast<char>('0' + ((c >> 3) & 7)),
                            static_cast<char>('0' + (c & 7))};
      text.append(octal, sizeof octal);
    }
  }
  return text + "\"";
}

}  // namespace sylva::lang
