// The parameter files of the Virtual Laboratory's environmental programs:
// one "name: values" command per line (EnviroManual section 3), e.g.
//
//   radius: 0.5
//   3d case: on
//   grid size: 20 x 20, 5
//
// Names are matched ignoring case and repeated spaces. Blank lines and lines
// starting with '#' are skipped. Values are separated by spaces or commas;
// where a command takes several numbers, 'x' separates them too
// ("64x64x64"). Every error names the file, line and column and says what
// was expected there.
#pragma once

#include <charconv>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/diagnostic.h"

namespace sylva::env {

// The collision programs (honda81, ecosystem, density, arvo) and the light
// programs (clover, chiba, takenaka) word their errors differently and check
// names at different times. The reader keeps both, so that neither
// family's errors change:
enum class ParameterDialect {
  // Messages name the program in their text ("cannot open the honda81
  // parameter file"); an unknown name is an error as soon as the file is
  // read, before any value is looked at; commands are looked up by name.
  collision,
  // Every message starts with "program: "; commands are taken in file order
  // and an unknown name is reported when the program meets it
  // (ParameterFile::fail_unknown), so the first wrong line is the one named.
  light,
};

// The whole of `text` read as a number, a leading '+' allowed; nullopt when
// it is not one. Read as `Number` itself (float or double), not narrowed from
// a wider type, so that every decimal gives the nearest value. cpfg
// background files (arvo's obstacles) write their numbers the same way.
template <class Number>
std::optional<Number> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  Number value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

struct ParameterWord {
  std::string text;
  int line = 0;
  int column = 0;  // 1-based
};

// One "name: values" line.
class ParameterCommand {
 public:
  ParameterCommand(std::string file, std::string program, ParameterDialect dialect, std::string name,
                   ParameterWord name_word, std::vector<ParameterWord> values, ParameterWord rest_of_line,
                   int line_end_column, int values_end_column);

  const std::string& name() const { return name_; }  // lower case, single spaces, without the colon
  const ParameterWord& name_word() const { return name_word_; }
  const std::vector<ParameterWord>& values() const { return values_; }
  // The column of the first value (the end of the line when there is none).
  int first_value_column() const { return rest_of_line_.column; }
  SourceLocation location() const;

  // Throws ModelError at `at` (a column of this line), "program: " first in
  // the light dialect.
  [[noreturn]] void fail(const ParameterWord& at, const std::string& message) const;
  [[noreturn]] void fail(int column, const std::string& message) const;

  // Value readers worded as the collision programs' errors are.
  // The single value of the command, read as a number, integer or flag.
  float number() const;
  int integer() const;
  bool flag() const;  // on/off, yes/no, true/false, 1/0
  // Exactly `count` numbers ("10 x 10 x 5", "10,10,5"). With
  // `optional_last`, count - 1 are enough and the last one is `fallback`.
  std::vector<float> numbers(int count, bool optional_last = false, float fallback = 0) const;
  // The rest of the line after the colon, trimmed (a file name may hold spaces).
  const std::string& text() const;

  // Value readers worded as the light programs' errors are: each says
  // `what` was expected and, for a wrong count, how many numbers it found.
  // Numbers are finite; "64x64x64" is three of them.
  std::vector<double> read_numbers(std::size_t count, const std::string& what) const;
  double read_number(const std::string& what) const;
  double read_number_in(double low, double high, const std::string& what) const;
  double read_number_at_least(double low, const std::string& what) const;
  std::vector<int> read_positive_integers(std::size_t count, const std::string& what) const;
  bool read_flag() const;  // yes/no, on/off, true/false, 1/0
  std::string read_word(const std::string& what) const;

 private:
  void expect_count(std::size_t count, const std::string& what) const;
  std::vector<std::pair<double, int>> numbers_with_columns(const std::string& what) const;

  std::string file_;
  std::string program_;
  ParameterDialect dialect_;
  std::string name_;
  ParameterWord name_word_;
  std::vector<ParameterWord> values_;
  ParameterWord rest_of_line_;
  int line_end_column_ = 0;    // just past the last character, spaces included
  int values_end_column_ = 0;  // just past the last value (after the colon when there is none)
};

class ParameterFile {
 public:
  // Reads `path`; `program` names the program in messages. `known_names` are
  // the commands the program understands, as the messages list them.
  ParameterFile(const std::filesystem::path& path, const std::string& program,
                const std::vector<std::string>& known_names, ParameterDialect dialect);

  const std::vector<ParameterCommand>& commands() const { return commands_; }
  // The last command called `name`, or nullptr.
  const ParameterCommand* find(const std::string& name) const;
  // As find(), but a missing command is an error (fail_missing).
  const ParameterCommand& require(const std::string& name, const std::string& example) const;

  // A command the file must contain but does not; `example` shows one.
  [[noreturn]] void fail_missing(const std::string& name, const std::string& example) const;
  // A command the program does not know, listing those it does.
  [[noreturn]] void fail_unknown(const ParameterCommand& command) const;

  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::string program_;
  std::vector<std::string> known_names_;
  ParameterDialect dialect_;
  std::vector<ParameterCommand> commands_;
};

}  // namespace sylva::env
