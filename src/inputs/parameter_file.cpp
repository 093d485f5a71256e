#include "inputs/parameter_file.h"

#include <cctype>
#include <sstream>

#include "inputs/input_text.h"

namespace sylva::io {

namespace {

bool identifier(const std::string& text) {
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text[0]))) return false;
  for (char c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

}  // namespace

std::vector<Parameter> read_parameter_file(const std::string& path) {
  std::istringstream lines(read_input_file(path, "parameter file"));
  std::vector<Parameter> parameters;
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::vector<Word> words = split_words(line, number);
    if (words.empty() || words[0].text.rfind("//", 0) == 0) continue;
    auto fail = [&](const Word& at, const std::string& expected) {
      throw ModelError(SourceLocation{path, at.line, at.column}, "expected " + expected + ", found '" + at.text + "'");
    };
    // "#define" or "# define".
    std::size_t k = 0;
    if (words[0].text == "#" && words.size() > 1 && words[1].text == "define") k = 2;
    else if (words[0].text == "#define") k = 1;
    else fail(words[0], "'#define name value'");
    auto fail_at_end = [&](const std::string& expected) {
      throw ModelError(SourceLocation{path, number, static_cast<int>(line.size()) + 1},
                       "expected " + expected + ", found the end of the line");
    };
    if (k >= words.size()) fail_at_end("a parameter name");
    if (!identifier(words[k].text)) fail(words[k], "a parameter name");
    if (k + 1 >= words.size()) fail_at_end("the value of " + words[k].text);
    std::optional<float> value = parse_float(words[k + 1].text);
    if (!value) fail(words[k + 1], "a number (the value of " + words[k].text + ")");
    if (k + 2 < words.size()) fail(words[k + 2], "the end of the line");
    parameters.push_back(Parameter{words[k].text, *value});
  }
  return parameters;
}

}  // namespace sylva::io
