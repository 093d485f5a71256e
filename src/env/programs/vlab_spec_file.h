// Specification files read as the Virtual Laboratory's honda81 and clover
// read theirs (ENVIRO/honda81, ENVIRO/clover): line by line, the keyword is
// the text up to the first ':' or tab (strtok(line, "\t:")), matched exactly
// (case and spaces count); each value is the next token between delimiters
// the program chooses (honda81 "x,; \t:\n", so "100x100" is two numbers) and
// is read with atof, which takes the longest number at the token's start and
// 0 when there is none ("100view.pnl" reads 100). The real programs never
// stop on their file: an unknown keyword is reported and skipped, a missing
// or unreadable file leaves every default. Sylva does the same and warns
// (file:line) where the real program passes over something silently: a value
// that is not a number in full.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace sylva::env {

// The rest of one line after its keyword, cut into tokens as strtok does.
class SpecLineTokens {
 public:
  SpecLineTokens(std::string file, int line, std::string text, std::size_t start)
      : file_(std::move(file)), line_(line), text_(std::move(text)), at_(start) {}

  // The next token between any of `delimiters`, or nullopt at the end.
  std::optional<std::string> next(const char* delimiters);
  // The next token read with atof (a warning when the token is not a number
  // in full); nullopt at the end of the line.
  std::optional<double> next_number(const char* delimiters);
  // The next token read with atoi (a warning when the token is not a whole
  // number in full); nullopt at the end of the line.
  std::optional<int> next_integer(const char* delimiters);

  // A switch as these programs read one: the next token sets `flag` to
  // `value` when it is one of `sets`, and leaves it as it is otherwise (with
  // a warning unless the token is one of `leaves`).
  void next_switch(const char* delimiters, std::initializer_list<std::string_view> sets,
                   std::initializer_list<std::string_view> leaves, bool value, bool& flag);

  int line() const { return line_; }
  // "file:line: warning: " + message.
  void warn(const std::string& message) const;

 private:
  std::string file_;
  int line_;
  std::string text_;
  std::size_t at_;
};

// Reads `path` for `program`: calls `command(index, tokens)` for each line
// whose keyword is keywords[index]; warns about the others (blank lines are
// passed over silently) and, when the file cannot be read, says so and
// returns false.
bool read_vlab_spec_file(const std::filesystem::path& path, const std::string& program,
                         const std::vector<std::string>& keywords,
                         const std::function<void(std::size_t, SpecLineTokens&)>& command);

// atof: the longest number at the start of `text` (after blanks), 0 when
// there is none; `complete` says whether the number was all of `text`.
double leading_number(const std::string& text, bool* complete = nullptr);
// atoi: the longest whole number at the start of `text` ("2.5" reads 2), 0
// when there is none; clamped to the range of int.
int leading_integer(const std::string& text, bool* complete = nullptr);

}  // namespace sylva::env
