// The value readers of ParameterCommand (parameter_file.h).
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>

#include "env/keyword.h"
#include "env/programs/parameter_file.h"

namespace sylva::env {
namespace {


std::optional<float> to_float(std::string_view text) { return parse_number<float>(text); }

std::optional<double> to_finite_double(std::string_view text) {
  std::optional<double> value = parse_number<double>(text);
  if (value && !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::string quoted(const ParameterWord& word) { return "'" + word.text + "'"; }

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

// Collision wording.

void ParameterCommand::expect_count(std::size_t count, const std::string& what) const {
  ParameterWord line_end{"", name_word_.line, line_end_column_};
  if (values_.size() < count) fail(line_end, "expected " + what + " after '" + name_ + ":', found the end of the line");
  if (values_.size() > count) fail(values_[count], "expected the end of the line after " + what + ", found " + quoted(values_[count]));
}

float ParameterCommand::number() const {
  expect_count(1, "a number");
  auto value = to_float(values_[0].text);
  if (!value) fail(values_[0], "expected a number, found " + quoted(values_[0]));
  return *value;
}

int ParameterCommand::integer() const {
  expect_count(1, "an integer");
  auto value = to_float(values_[0].text);
  if (!value || *value != static_cast<float>(static_cast<long long>(*value)) || std::abs(*value) > 2e9f)
    fail(values_[0], "expected an integer, found " + quoted(values_[0]));
  return static_cast<int>(*value);
}

bool ParameterCommand::flag() const {
  expect_count(1, "on or off");
  if (const std::optional<bool> on = parse_switch(values_[0].text)) return *on;
  fail(values_[0], "expected on or off, found " + quoted(values_[0]));
}

std::vector<float> ParameterCommand::numbers(int count, bool optional_last, float fallback) const {
  // Split "10x10" into 10 and 10, keeping each piece's column.
  std::vector<ParameterWord> pieces;
  for (const ParameterWord& word : values_) {
    std::size_t i = 0;
    while (i < word.text.size()) {
      if (word.text[i] == 'x' || word.text[i] == 'X') {
        ++i;
        continue;
      }
      std::size_t end = i;
      while (end < word.text.size() && word.text[end] != 'x' && word.text[end] != 'X') ++end;
      pieces.push_back({word.text.substr(i, end - i), word.line, word.column + static_cast<int>(i)});
      i = end;
    }
  }
  std::string what = std::to_string(count) + " numbers";
  int needed = optional_last ? count - 1 : count;
  std::vector<float> result;
  for (const ParameterWord& piece : pieces) {
    if (static_cast<int>(result.size()) == count)
      fail(piece, "expected the end of the line after " + what + ", found " + quoted(piece));
    auto value = to_float(piece.text);
    if (!value) fail(piece, "expected a number, found " + quoted(piece));
    result.push_back(*value);
  }
  if (static_cast<int>(result.size()) < needed)
    fail(line_end_column_, "expected " + (optional_last ? std::to_string(needed) + " or " + what : what) +
                               " after '" + name_ + ":', found the end of the line");
  if (static_cast<int>(result.size()) < count) result.push_back(fallback);
  return result;
}

const std::string& ParameterCommand::text() const {
  if (rest_of_line_.text.empty())
    fail(line_end_column_, "expected a value after '" + name_ + ":', found the end of the line");
  return rest_of_line_.text;
}

// Light wording.

// The numbers of the line with their columns. A word is a number, a lone
// 'x' ("64 x 64", skipped) or numbers joined by single 'x's ("64x64").
std::vector<std::pair<double, int>> ParameterCommand::numbers_with_columns(const std::string& what) const {
  std::vector<std::pair<double, int>> numbers;
  for (const ParameterWord& word : values_) {
    if (auto value = to_finite_double(word.text)) {
      numbers.emplace_back(*value, word.column);
      continue;
    }
    if (word.text == "x" || word.text == "X") continue;
    std::vector<std::pair<double, int>> parts;
    std::size_t start = 0;
    while (start <= word.text.size()) {
      std::size_t x = word.text.find_first_of("xX", start);
      if (x == std::string::npos) x = word.text.size();
      auto value = to_finite_double(std::string_view(word.text).substr(start, x - start));
      if (!value) fail(word, "expected a number (" + what + "), found " + quoted(word));
      parts.emplace_back(*value, word.column + static_cast<int>(start));
      start = x + 1;
    }
    numbers.insert(numbers.end(), parts.begin(), parts.end());
  }
  return numbers;
}

std::vector<double> ParameterCommand::read_numbers(std::size_t count, const std::string& what) const {
  std::vector<std::pair<double, int>> found = numbers_with_columns(what);
  std::string expected = "expected " + plural(count, "number") + " after '" + name_ + ":' (" + what + "), found ";
  if (found.size() < count) fail(values_end_column_, expected + std::to_string(found.size()));
  if (found.size() > count) fail(found[count].second, expected + "more");
  std::vector<double> values;
  for (const auto& [value, column] : found) values.push_back(value);
  return values;
}

double ParameterCommand::read_number(const std::string& what) const { return read_numbers(1, what)[0]; }

double ParameterCommand::read_number_in(double low, double high, const std::string& what) const {
  double value = read_number(what);
  if (value < low || value > high) {
    std::ostringstream message;
    message << "expected " << what << " between " << low << " and " << high << ", found " << value;
    fail(values_.front(), message.str());
  }
  return value;
}

double ParameterCommand::read_number_at_least(double low, const std::string& what) const {
  double value = read_number(what);
  if (value < low) {
    std::ostringstream message;
    message << "expected " << what << " of " << low << " or more, found " << value;
    fail(values_.front(), message.str());
  }
  return value;
}

std::vector<int> ParameterCommand::read_positive_integers(std::size_t count, const std::string& what) const {
  read_numbers(count, what);  // the count is right
  std::vector<int> integers;
  for (const auto& [value, column] : numbers_with_columns(what)) {
    if (value < 1 || value != std::floor(value) || value > 1e6) {
      std::ostringstream message;
      message << "expected a positive whole number (" << what << "), found " << value;
      fail(column, message.str());
    }
    integers.push_back(static_cast<int>(value));
  }
  return integers;
}

bool ParameterCommand::read_flag() const {
  if (values_.size() == 1) {
    if (const std::optional<bool> on = parse_switch(values_[0].text)) return *on;
  }
  fail(values_.empty() ? values_end_column_ : values_[0].column,
       "expected yes or no (also on/off) after '" + name_ + ":'");
}

std::string ParameterCommand::read_word(const std::string& what) const {
  if (rest_of_line_.text.empty()) fail(values_end_column_, "expected " + what + " after '" + name_ + ":'");
  return rest_of_line_.text;
}

}  // namespace sylva::env
