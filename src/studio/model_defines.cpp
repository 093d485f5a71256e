#include "studio/model_defines.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>

#include "studio/panel_message.h"
#include "studio/text_lines.h"

namespace sylva::studio {

namespace {

// The source with every comment's characters turned into spaces (line breaks
// kept), so that lines keep their numbers and what is left is code. String
// and character literals are stepped over so that "/*" in one opens nothing.
std::string without_comments(std::string_view source) {
  std::string code(source);
  enum class State { Code, Line, Block, String, Char } state = State::Code;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    const char next = i + 1 < code.size() ? code[i + 1] : '\0';
    switch (state) {
      case State::Code:
        if (c == '/' && (next == '/' || next == '*')) {
          state = next == '/' ? State::Line : State::Block;
          code[i] = code[i + 1] = ' ';
          ++i;
        } else if (c == '"') {
          state = State::String;
        } else if (c == '\'') {
          state = State::Char;
        }
        break;
      case State::Line:
        if (c == '\n') state = State::Code;
        else code[i] = ' ';
        break;
      case State::Block:
        if (c == '*' && next == '/') {
          state = State::Code;
          code[i] = code[i + 1] = ' ';
          ++i;
        } else if (c != '\n') {
          code[i] = ' ';
        }
        break;
      case State::String:
      case State::Char:
        if (c == '\\') ++i;
        else if (c == (state == State::String ? '"' : '\'') || c == '\n') state = State::Code;
        break;
    }
  }
  return code;
}

// "#if" and the like, whether written "#if" or "# if"; empty for other lines.
std::string_view directive_of(const std::vector<std::string_view>& words, std::size_t& argument) {
  if (words.empty() || words[0][0] != '#') return {};
  if (words[0].size() > 1) {
    argument = 1;
    return words[0].substr(1);
  }
  argument = 2;
  return words.size() > 1 ? words[1] : std::string_view{};
}

struct Number {
  double value = 0;
  bool integral = false;
};

// A C integer or floating literal, optionally signed.
std::optional<Number> number_of(std::string_view text) {
  std::string_view body = text;
  const bool negative = !body.empty() && body[0] == '-';
  if (!body.empty() && (body[0] == '-' || body[0] == '+')) body.remove_prefix(1);
  const bool hex = body.size() > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X');
  const std::string_view suffixes = hex ? "uUlL" : "uUlLfF";
  const std::size_t suffix_at = body.find_last_not_of(suffixes) + 1;
  const std::string_view suffix = body.substr(suffix_at);
  body = body.substr(0, suffix_at);
  if (body.empty() || body[0] == '-' || body[0] == '+') return std::nullopt;

  Number number;
  number.integral = body.find_first_of(hex ? "." : ".eE") == std::string_view::npos &&
                    suffix.find_first_of("fF") == std::string_view::npos;
  const char* end = body.data() + body.size();
  std::from_chars_result parsed{};
  if (number.integral) {
    const int base = hex ? 16 : (body.size() > 1 && body[0] == '0' ? 8 : 10);
    long long integer = 0;
    parsed = std::from_chars(body.data() + (hex ? 2 : 0), end, integer, base);
    number.value = static_cast<double>(integer);
  } else {
    if (hex || suffix.find_first_of("uU") != std::string_view::npos) return std::nullopt;
    parsed = std::from_chars(body.data(), end, number.value);
  }
  if (parsed.ec != std::errc() || parsed.ptr != end) return std::nullopt;
  if (negative) number.value = -number.value;
  return number;
}

bool is_mathematical_constant(double value) {
  using std::numbers::pi;
  for (double constant : {pi, 2 * pi, pi / 2, pi / 180, 180 / pi, std::numbers::e})
    if (std::abs(std::abs(value) - constant) <= 1e-4 * constant) return true;
  return false;
}

// n × 10^exponent as the double nearest that decimal.
double decimal(long long n, int exponent) {
  return std::stod(std::to_string(n) + "e" + std::to_string(exponent));
}

}  // namespace

std::vector<ModelDefine> find_model_defines(std::string_view source) {
  const std::string code = without_comments(source);
  std::vector<ModelDefine> defines;
  int skipping = 0;  // depth inside an "#if 0" block; 0 when not in one
  for (const TextLine& line : split_lines(code)) {
    const std::vector<std::string_view> words = split_words(line.text);
    std::size_t argument = 0;
    const std::string_view directive = directive_of(words, argument);
    const bool opens = directive == "if" || directive == "ifdef" || directive == "ifndef";
    if (skipping > 0) {
      if (opens) ++skipping;
      else if (directive == "endif") --skipping;
      else if ((directive == "else" || directive == "elif") && skipping == 1) skipping = 0;
      continue;
    }
    if (directive == "if" && argument < words.size() && words[argument] == "0") {
      skipping = 1;
      continue;
    }
    // awkped matches "#define" as the line's first word and rewrites the
    // third; a value must be that word alone.
    if (words.size() != 3 || words[0] != "#define") continue;
    const std::string_view name = words[1];
    if (name[0] == '_' || name.find('(') != std::string_view::npos) continue;
    const std::optional<Number> number = number_of(words[2]);
    if (!number || (!number->integral && is_mathematical_constant(number->value))) continue;
    if (std::any_of(defines.begin(), defines.end(), [&](const ModelDefine& d) { return d.name == name; })) continue;
    defines.push_back({std::string(name), std::string(words[2]), number->value, number->integral, line.number,
                       propose_slider_range(number->value, number->integral)});
  }
  return defines;
}

SliderRange propose_slider_range(double value, bool integral) {
  if (integral) {
    const double reach = std::max(10.0, 2 * std::abs(value));
    return {value < 0 ? -reach : 0, reach, 1};
  }
  if (value == 0) return {0, 1, 0.01};
  const double magnitude = std::abs(value);
  int exponent = static_cast<int>(std::floor(std::log10(magnitude) + 1e-12)) - 2;
  // A value written with more decimals (137.51) needs them in the step, or
  // the slider could not stand on it.
  for (int decimals = 0; decimals <= 15; ++decimals) {
    const double scaled = magnitude * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) <= 1e-9 * scaled) {
      exponent = std::min(exponent, -decimals);
      break;
    }
  }
  const auto steps = static_cast<long long>(std::ceil(2 * magnitude / std::pow(10.0, exponent) - 1e-6));
  const double reach = decimal(steps, exponent);
  return {value < 0 ? -reach : 0, reach, decimal(1, exponent)};
}

std::string define_value_text(const ModelDefine& define, double value) {
  if (define.integral) return std::to_string(std::llround(value));
  std::string text = shortest_number_text(value);
  if (text.find_first_of(".en") == std::string::npos) text += ".0";
  const std::size_t suffix_at = define.value_text.find_last_not_of("fFlL") + 1;
  return text + define.value_text.substr(suffix_at);
}

}  // namespace sylva::studio
