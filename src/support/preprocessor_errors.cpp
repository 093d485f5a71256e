#include "support/preprocessor_errors.h"

#include <charconv>
#include <regex>
#include <sstream>

namespace sylva {
namespace {

int number(const std::ssub_match& digits) {
  const std::string text = digits.str();
  int n = 0;
  std::from_chars(text.data(), text.data() + text.size(), n);  // past int: 0, no line
  return n;
}

}  // namespace

std::optional<ModelError> first_preprocessor_error(const std::string& err, const std::string& argument,
                                                   const std::string& path) {
  static const std::regex error(R"(^(.*?):(\d+):(?:(\d+):)? (?:fatal )?error: (.*)$)");
  // "In file included from a.l:3:" then "                 from b.l:7:": the
  // last names the file the user gave.
  static const std::regex included(R"(^(?:In file included| +) from (.*):(\d+)[:,]$)");
  auto named = [&](const std::string& file) { return file == argument ? path : file; };
  std::istringstream in(err);
  std::string line, included_from;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, included)) {
      included_from = named(m[1].str()) + ":" + m[2].str();
    } else if (std::regex_match(line, m, error)) {
      const int column = m[3].matched ? number(m[3]) : 1;
      std::string message = m[4].str();
      if (!included_from.empty()) message += " (in a file included from " + included_from + ")";
      return ModelError(SourceLocation{named(m[1].str()), number(m[2]), column}, message);
    } else {
      included_from.clear();
    }
  }
  return std::nullopt;
}

}  // namespace sylva
