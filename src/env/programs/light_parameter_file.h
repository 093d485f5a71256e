// The parameter files of the light programs (clover, chiba, takenaka): one
// "keyword: values" command per line, as in EnviroManual section 3.2. Blank
// lines and lines starting with '#' are skipped. Keywords are matched without
// regard to case or repeated spaces. Numbers may be separated by spaces,
// commas or 'x' ("grid size: 64x64x64").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "env/program.h"

namespace sylva::env::light {

struct ParameterLine {
  std::string file;     // for error messages
  std::string program;  // e.g. "clover", prefixed to error messages
  int line = 0;
  int keyword_column = 0;
  std::string keyword;  // lower case, single spaces
  std::string values;   // the text after ':'
  int values_column = 0;  // column of values[0]
};

// The column of the first character after ':' that is not a space.
int first_value_column(const ParameterLine& line);

// Throws ModelError pointing at `column` of `line` with "program: message".
[[noreturn]] void fail_at(const ParameterLine& line, int column, const std::string& message);

// The parameter file named on the "executable:" line (its first argument
// that is not an option), resolved against the .e file's folder.
std::filesystem::path parameter_file_path(const ProgramInvocation& invocation, const std::string& program);

// Reads `path` into its commands. Throws ModelError if the file cannot be read
// or a line has no ':'.
std::vector<ParameterLine> read_parameter_file(const std::filesystem::path& path, const std::string& program);

// The values of a command. Each throws ModelError, naming `what` and the
// position of the offending text, when the values are not as expected.
std::vector<double> read_numbers(const ParameterLine& line, std::size_t count, const std::string& what);
double read_number(const ParameterLine& line, const std::string& what);
double read_number_in(const ParameterLine& line, double low, double high, const std::string& what);
double read_number_at_least(const ParameterLine& line, double low, const std::string& what);
std::vector<int> read_positive_integers(const ParameterLine& line, std::size_t count, const std::string& what);
bool read_flag(const ParameterLine& line);  // yes/no, on/off, true/false, 1/0
std::string read_word(const ParameterLine& line, const std::string& what);

// Error for a keyword the program does not know, listing those it does.
[[noreturn]] void fail_unknown_keyword(const ParameterLine& line, const std::vector<std::string>& known);

// Error for a command the file must contain but does not.
[[noreturn]] void fail_missing(const std::filesystem::path& path, const std::string& program,
                               const std::string& command);

}  // namespace sylva::env::light
