// The parameter files of the Virtual Laboratory's environmental programs:
// one "name: values" command per line (EnviroManual section 3), e.g.
//
//   radius: 0.5
//   3d case: on
//   grid size: 20 x 20, 5
//
// Names are matched ignoring case and repeated spaces. Blank lines and lines
// starting with '#' are skipped. Every error names the file, line and column
// and says what was expected there.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "support/diagnostic.h"

namespace sylva::env::collision {

struct ParameterWord {
  std::string text;
  int line = 0;
  int column = 0;  // 1-based
};

class ParameterCommand {
 public:
  ParameterCommand(std::string file, std::string name, ParameterWord name_word, std::vector<ParameterWord> values,
                   ParameterWord rest_of_line, ParameterWord line_end);

  const std::string& name() const { return name_; }  // lower case, single spaces, without the colon
  const std::vector<ParameterWord>& values() const { return values_; }

  // The single value of the command, read as a number, integer or flag.
  float number() const;
  int integer() const;
  bool flag() const;  // on/off, yes/no, true/false, 1/0
  // Exactly `count` numbers; they may be separated by spaces, commas or 'x'
  // ("10 x 10 x 5", "10,10,5"). With `optional_last`, count - 1 are enough and
  // the last one is returned as `fallback`.
  std::vector<float> numbers(int count, bool optional_last = false, float fallback = 0) const;
  // The rest of the line after the colon, trimmed (a file name may hold spaces).
  const std::string& text() const;

  [[noreturn]] void fail(const ParameterWord& at, const std::string& message) const;
  SourceLocation location() const;

 private:
  void expect_count(std::size_t count, const std::string& what) const;

  std::string file_;
  std::string name_;
  ParameterWord name_word_;
  std::vector<ParameterWord> values_;
  ParameterWord rest_of_line_;
  ParameterWord line_end_;
};

class ParameterFile {
 public:
  // Reads `path`; `program` names the program in messages. Every command must
  // be one of `known_names` (lower case, without colons).
  ParameterFile(const std::filesystem::path& path, const std::string& program,
                const std::vector<std::string>& known_names);

  const std::vector<ParameterCommand>& commands() const { return commands_; }
  // The last command called `name`, or nullptr.
  const ParameterCommand* find(const std::string& name) const;
  // As find(), but a missing command is an error pointing at the file.
  const ParameterCommand& require(const std::string& name, const std::string& example) const;

  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::string program_;
  std::vector<ParameterCommand> commands_;
};

}  // namespace sylva::env::collision
