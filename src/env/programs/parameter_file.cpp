#include "env/programs/parameter_file.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "env/keyword.h"

namespace sylva::env {
namespace {



// Words separated by spaces and commas, from `start` on.
std::vector<ParameterWord> split_values(const std::string& line, std::size_t start, int line_number) {
  std::vector<ParameterWord> words;
  std::size_t i = start;
  while (i < line.size()) {
    if (is_blank(line[i]) || line[i] == ',') {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < line.size() && !is_blank(line[end]) && line[end] != ',') ++end;
    words.push_back({line.substr(i, end - i), line_number, static_cast<int>(i) + 1});
    i = end;
  }
  return words;
}

// "radius:, 3d case:" (collision) or "'radius:', '3d case:'" (light).
std::string name_list(const std::vector<std::string>& names, ParameterDialect dialect) {
  std::string list;
  for (const std::string& name : names) {
    std::string item = dialect == ParameterDialect::light ? "'" + name + ":'" : name + ":";
    list += (list.empty() ? "" : ", ") + item;
  }
  return list;
}

}  // namespace

ParameterCommand::ParameterCommand(std::string file, std::string program, ParameterDialect dialect, std::string name,
                                   ParameterWord name_word, std::vector<ParameterWord> values,
                                   ParameterWord rest_of_line, int line_end_column, int values_end_column)
    : file_(std::move(file)),
      program_(std::move(program)),
      dialect_(dialect),
      name_(std::move(name)),
      name_word_(std::move(name_word)),
      values_(std::move(values)),
      rest_of_line_(std::move(rest_of_line)),
      line_end_column_(line_end_column),
      values_end_column_(values_end_column) {}

SourceLocation ParameterCommand::location() const { return {file_, name_word_.line, name_word_.column}; }

void ParameterCommand::fail(const ParameterWord& at, const std::string& message) const {
  // A default word (no value to point at) still names this command's file.
  throw ModelError(SourceLocation{file_, at.line, at.column},
                   dialect_ == ParameterDialect::light ? program_ + ": " + message : message);
}

void ParameterCommand::fail(int column, const std::string& message) const {
  fail(ParameterWord{"", name_word_.line, column}, message);
}

ParameterFile::ParameterFile(const std::filesystem::path& path, const std::string& program,
                             const std::vector<std::string>& known_names, ParameterDialect dialect)
    : file_(path.string()), program_(program), known_names_(known_names), dialect_(dialect) {
  bool light = dialect == ParameterDialect::light;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw ModelError(SourceLocation{file_, 0, 0}, light ? program + ": cannot read the parameter file"
                                                        : "cannot open the " + program + " parameter file");
  std::vector<std::string> known;
  for (const std::string& name : known_names) known.push_back(normalized_keyword(name));
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::size_t first = 0;
    while (first < line.size() && is_blank(line[first])) ++first;
    if (first == line.size() || line[first] == '#') continue;
    std::size_t colon = line.find(':');
    SourceLocation at{file_, line_number, static_cast<int>(first) + 1};
    if (colon == std::string::npos)
      throw ModelError(at, light ? program + ": expected a command 'keyword: values' (e.g. 'transmittance: 0.5'), "
                                             "found '" + line.substr(first) + "'"
                                 : "expected 'name: value' (one of " + name_list(known_names, dialect) +
                                       "), found no colon");
    ParameterWord name_word{line.substr(first, colon - first), line_number, static_cast<int>(first) + 1};
    std::string name = normalized_keyword(name_word.text);
    if (!light && std::find(known.begin(), known.end(), name) == known.end())
      throw ModelError(at, "unknown " + program + " parameter '" + name + ":'; expected one of " +
                               name_list(known_names, dialect));
    std::size_t rest = colon + 1;
    while (rest < line.size() && is_blank(line[rest])) ++rest;
    std::size_t rest_end = line.size();
    while (rest_end > rest && is_blank(line[rest_end - 1])) --rest_end;
    ParameterWord rest_word{line.substr(rest, rest_end - rest), line_number, static_cast<int>(rest) + 1};
    int values_end = rest < rest_end ? static_cast<int>(rest_end) + 1 : static_cast<int>(colon) + 2;
    commands_.emplace_back(file_, program, dialect, name, name_word, split_values(line, colon + 1, line_number),
                           rest_word, static_cast<int>(line.size()) + 1, values_end);
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
  if (!command) fail_missing(name, example);
  return *command;
}

void ParameterFile::fail_missing(const std::string& name, const std::string& example) const {
  throw ModelError(SourceLocation{file_, 0, 0},
                   dialect_ == ParameterDialect::light
                       ? program_ + ": the parameter file has no '" + example + "' line"
                       : "the " + program_ + " parameter file needs '" + name + ":' (e.g. '" + example + "')");
}

void ParameterFile::fail_unknown(const ParameterCommand& command) const {
  const std::string message = dialect_ == ParameterDialect::light
                                  ? "unknown command '" + command.name() + ":'; expected one of "
                                  : "unknown " + program_ + " parameter '" + command.name() + ":'; expected one of ";
  command.fail(command.name_word(), message + name_list(known_names_, dialect_));
}

}  // namespace sylva::env
