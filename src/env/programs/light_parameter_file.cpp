#include "env/programs/light_parameter_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "support/diagnostic.h"

namespace sylva::env::light {

namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// "Grid   Size" -> "grid size".
std::string normalized_keyword(const std::string& text) {
  std::string out;
  bool pending_space = false;
  for (char c : text) {
    if (is_space(c)) {
      pending_space = !out.empty();
      continue;
    }
    if (pending_space) out.push_back(' ');
    pending_space = false;
    out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return out;
}

struct Token {
  std::string text;
  int column = 0;
};

// Words of `line.values`, split at spaces and commas.
std::vector<Token> words(const ParameterLine& line) {
  std::vector<Token> tokens;
  const std::string& s = line.values;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (is_space(s[i]) || s[i] == ',')) ++i;
    if (i >= s.size()) break;
    std::size_t start = i;
    while (i < s.size() && !is_space(s[i]) && s[i] != ',') ++i;
    tokens.push_back({s.substr(start, i - start), line.values_column + static_cast<int>(start)});
  }
  return tokens;
}

bool parse_double(const std::string& text, double& value) {
  if (text.empty()) return false;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (*first == '+') ++first;
  auto [end, error] = std::from_chars(first, last, value);
  return error == std::errc() && end == last && std::isfinite(value);
}

// The numbers of a line; "64x64x64" counts as three.
std::vector<std::pair<double, int>> numbers_with_columns(const ParameterLine& line, const std::string& what) {
  std::vector<std::pair<double, int>> numbers;
  for (const Token& token : words(line)) {
    double value = 0;
    if (parse_double(token.text, value)) {
      numbers.emplace_back(value, token.column);
      continue;
    }
    if (token.text == "x" || token.text == "X") continue;  // "64 x 64"
    // "64x64": split at every 'x', each part must be a number.
    std::vector<std::pair<double, int>> parts;
    std::size_t start = 0;
    bool all_numbers = true;
    while (start <= token.text.size()) {
      std::size_t x = token.text.find_first_of("xX", start);
      if (x == std::string::npos) x = token.text.size();
      if (!parse_double(token.text.substr(start, x - start), value)) {
        all_numbers = false;
        break;
      }
      parts.emplace_back(value, token.column + static_cast<int>(start));
      start = x + 1;
    }
    if (!all_numbers) fail_at(line, token.column, "expected a number (" + what + "), found '" + token.text + "'");
    numbers.insert(numbers.end(), parts.begin(), parts.end());
  }
  return numbers;
}

int end_column(const ParameterLine& line) {
  std::size_t end = line.values.size();
  while (end > 0 && is_space(line.values[end - 1])) --end;
  return line.values_column + static_cast<int>(end);
}

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

int first_value_column(const ParameterLine& line) {
  std::size_t first = 0;
  while (first < line.values.size() && is_space(line.values[first])) ++first;
  return line.values_column + static_cast<int>(first);
}

void fail_at(const ParameterLine& line, int column, const std::string& message) {
  throw ModelError(SourceLocation{line.file, line.line, column}, line.program + ": " + message);
}

std::filesystem::path parameter_file_path(const ProgramInvocation& invocation, const std::string& program) {
  std::vector<std::string> files = invocation.positional_arguments();
  if (files.empty()) {
    throw ModelError(SourceLocation{invocation.e_file, invocation.e_file_line, 0},
                     program + ": expected a parameter file after the program name, e.g. 'executable: " + program +
                         " -e field.e " + program + ".par'");
  }
  return invocation.resolve(files.front());
}

std::vector<ParameterLine> read_parameter_file(const std::filesystem::path& path, const std::string& program) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ModelError(SourceLocation{path.string(), 0, 0}, program + ": cannot read the parameter file");
  std::vector<ParameterLine> lines;
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    std::size_t first = 0;
    while (first < text.size() && is_space(text[first])) ++first;
    if (first == text.size() || text[first] == '#') continue;
    std::size_t colon = text.find(':');
    ParameterLine line;
    line.file = path.string();
    line.program = program;
    line.line = number;
    line.keyword_column = static_cast<int>(first) + 1;
    if (colon == std::string::npos) {
      fail_at(line, line.keyword_column,
              "expected a command 'keyword: values' (e.g. 'transmittance: 0.5'), found '" + text.substr(first) + "'");
    }
    line.keyword = normalized_keyword(text.substr(first, colon - first));
    line.values = text.substr(colon + 1);
    if (!line.values.empty() && line.values.back() == '\r') line.values.pop_back();
    line.values_column = static_cast<int>(colon) + 2;
    lines.push_back(std::move(line));
  }
  return lines;
}

std::vector<double> read_numbers(const ParameterLine& line, std::size_t count, const std::string& what) {
  std::vector<std::pair<double, int>> found = numbers_with_columns(line, what);
  if (found.size() < count) {
    fail_at(line, end_column(line),
            "expected " + plural(count, "number") + " after '" + line.keyword + ":' (" + what + "), found " +
                std::to_string(found.size()));
  }
  if (found.size() > count) {
    fail_at(line, found[count].second,
            "expected " + plural(count, "number") + " after '" + line.keyword + ":' (" + what + "), found more");
  }
  std::vector<double> values;
  for (const auto& [value, column] : found) values.push_back(value);
  return values;
}

double read_number(const ParameterLine& line, const std::string& what) { return read_numbers(line, 1, what)[0]; }

double read_number_in(const ParameterLine& line, double low, double high, const std::string& what) {
  double value = read_number(line, what);
  if (value < low || value > high) {
    std::ostringstream message;
    message << "expected " << what << " between " << low << " and " << high << ", found " << value;
    fail_at(line, words(line).front().column, message.str());
  }
  return value;
}

double read_number_at_least(const ParameterLine& line, double low, const std::string& what) {
  double value = read_number(line, what);
  if (value < low) {
    std::ostringstream message;
    message << "expected " << what << " of " << low << " or more, found " << value;
    fail_at(line, words(line).front().column, message.str());
  }
  return value;
}

std::vector<int> read_positive_integers(const ParameterLine& line, std::size_t count, const std::string& what) {
  read_numbers(line, count, what);  // the count is right
  std::vector<int> integers;
  for (const auto& [value, column] : numbers_with_columns(line, what)) {
    if (value < 1 || value != std::floor(value) || value > 1e6) {
      std::ostringstream message;
      message << "expected a positive whole number (" << what << "), found " << value;
      fail_at(line, column, message.str());
    }
    integers.push_back(static_cast<int>(value));
  }
  return integers;
}

bool read_flag(const ParameterLine& line) {
  std::vector<Token> tokens = words(line);
  if (tokens.size() == 1) {
    std::string word = lower(tokens[0].text);
    if (word == "yes" || word == "on" || word == "true" || word == "1") return true;
    if (word == "no" || word == "off" || word == "false" || word == "0") return false;
  }
  int column = tokens.empty() ? end_column(line) : tokens[0].column;
  fail_at(line, column, "expected yes or no (also on/off) after '" + line.keyword + ":'");
}

std::string read_word(const ParameterLine& line, const std::string& what) {
  std::size_t first = 0;
  while (first < line.values.size() && is_space(line.values[first])) ++first;
  std::size_t last = line.values.size();
  while (last > first && is_space(line.values[last - 1])) --last;
  if (first == last) fail_at(line, end_column(line), "expected " + what + " after '" + line.keyword + ":'");
  return line.values.substr(first, last - first);
}

void fail_unknown_keyword(const ParameterLine& line, const std::vector<std::string>& known) {
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "" : ", ") + ("'" + k + ":'");
  fail_at(line, line.keyword_column, "unknown command '" + line.keyword + ":'; expected one of " + list);
}

void fail_missing(const std::filesystem::path& path, const std::string& program, const std::string& command) {
  throw ModelError(SourceLocation{path.string(), 0, 0}, program + ": the parameter file has no '" + command + "' line");
}

}  // namespace sylva::env::light
