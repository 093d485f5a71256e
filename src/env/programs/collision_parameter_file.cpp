#include "env/programs/collision_parameter_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace sylva::env::collision {
namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// "3d   Case" -> "3d case": names are compared by their words.
std::string normalise_name(const std::string& text) {
  std::string name;
  for (char c : text) {
    if (is_space(c)) {
      if (!name.empty() && name.back() != ' ') name.push_back(' ');
    } else {
      name.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  while (!name.empty() && name.back() == ' ') name.pop_back();
  return name;
}

// Words separated by spaces and commas, from `start` on.
std::vector<ParameterWord> split_values(const std::string& line, std::size_t start, int line_number) {
  std::vector<ParameterWord> words;
  std::size_t i = start;
  while (i < line.size()) {
    if (is_space(line[i]) || line[i] == ',') {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < line.size() && !is_space(line[end]) && line[end] != ',') ++end;
    words.push_back({line.substr(i, end - i), line_number, static_cast<int>(i) + 1});
    i = end;
  }
  return words;
}

std::optional<float> to_float(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  float value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::string quoted(const ParameterWord& word) { return "'" + word.text + "'"; }

}  // namespace

ParameterCommand::ParameterCommand(std::string file, std::string name, ParameterWord name_word,
                                   std::vector<ParameterWord> values, ParameterWord rest_of_line,
                                   ParameterWord line_end)
    : file_(std::move(file)),
      name_(std::move(name)),
      name_word_(std::move(name_word)),
      values_(std::move(values)),
      rest_of_line_(std::move(rest_of_line)),
      line_end_(std::move(line_end)) {}

SourceLocation ParameterCommand::location() const { return {file_, name_word_.line, name_word_.column}; }

void ParameterCommand::fail(const ParameterWord& at, const std::string& message) const {
  throw ModelError(SourceLocation{file_, at.line, at.column}, message);
}

void ParameterCommand::expect_count(std::size_t count, const std::string& what) const {
  if (values_.size() < count) fail(line_end_, "expected " + what + " after '" + name_ + ":', found the end of the line");
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
  std::string word = lower(values_[0].text);
  if (word == "on" || word == "yes" || word == "true" || word == "1") return true;
  if (word == "off" || word == "no" || word == "false" || word == "0") return false;
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
    fail(line_end_, "expected " + (optional_last ? std::to_string(needed) + " or " + what : what) + " after '" + name_ +
                        ":', found the end of the line");
  if (static_cast<int>(result.size()) < count) result.push_back(fallback);
  return result;
}

const std::string& ParameterCommand::text() const {
  if (rest_of_line_.text.empty()) fail(line_end_, "expected a value after '" + name_ + ":', found the end of the line");
  return rest_of_line_.text;
}

ParameterFile::ParameterFile(const std::filesystem::path& path, const std::string& program,
                             const std::vector<std::string>& known_names)
    : file_(path.string()), program_(program) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ModelError(SourceLocation{file_, 0, 0}, "cannot open the " + program + " parameter file");
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::size_t first = 0;
    while (first < line.size() && is_space(line[first])) ++first;
    if (first == line.size() || line[first] == '#') continue;
    std::size_t colon = line.find(':');
    ParameterWord name_word{line.substr(first, colon == std::string::npos ? std::string::npos : colon - first),
                            line_number, static_cast<int>(first) + 1};
    std::string known;
    for (const std::string& name : known_names) known += (known.empty() ? "" : ", ") + name + ":";
    if (colon == std::string::npos)
      throw ModelError(SourceLocation{file_, line_number, static_cast<int>(first) + 1},
                       "expected 'name: value' (one of " + known + "), found no colon");
    std::string name = normalise_name(name_word.text);
    if (std::find(known_names.begin(), known_names.end(), name) == known_names.end())
      throw ModelError(SourceLocation{file_, line_number, static_cast<int>(first) + 1},
                       "unknown " + program + " parameter '" + name + ":'; expected one of " + known);
    std::size_t rest = colon + 1;
    while (rest < line.size() && is_space(line[rest])) ++rest;
    std::size_t rest_end = line.size();
    while (rest_end > rest && is_space(line[rest_end - 1])) --rest_end;
    ParameterWord rest_word{line.substr(rest, rest_end - rest), line_number, static_cast<int>(rest) + 1};
    ParameterWord line_end{"", line_number, static_cast<int>(line.size()) + 1};
    commands_.emplace_back(file_, name, name_word, split_values(line, colon + 1, line_number), rest_word, line_end);
  }
}

const ParameterCommand* ParameterFile::find(const std::string& name) const {
  const ParameterCommand* found = nullptr;
  for (const ParameterCommand& command : commands_)
    if (command.name() == name) found = &command;
  return found;
}

const ParameterCommand& ParameterFile::require(const std::string& name, const std::string& example) const {
  const ParameterCommand* command = find(name);
  if (!command)
    throw ModelError(SourceLocation{file_, 0, 0},
                     "the " + program_ + " parameter file needs '" + name + ":' (e.g. '" + example + "')");
  return *command;
}

}  // namespace sylva::env::collision
