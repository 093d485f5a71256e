#include "build/compiler_messages.h"

#include <map>
#include <regex>
#include <sstream>
#include <vector>

#include "lang/literal_numbers.h"
#include "support/whole_file.h"

namespace sylva::build {
namespace {


// GCC counts columns as a display does: a tab moves to the next multiple of
// 8, a character of several UTF-8 bytes is one column.
constexpr int kTabStop = 8;

struct LineColumns {
  int width = 0;         // the last column of the line
  int first_word = 1;    // the column of its first character that is not blank
};

LineColumns columns_of(const std::string& line) {
  LineColumns c;
  bool blank = true;
  for (char ch : line) {
    if ((static_cast<unsigned char>(ch) & 0xC0) == 0x80) continue;  // inside a character
    if (ch == '\r') continue;
    const int next = ch == '\t' ? (c.width / kTabStop + 1) * kTabStop : c.width + 1;
    if (blank && ch != ' ' && ch != '\t') {
      c.first_word = c.width + 1;
      blank = false;
    }
    c.width = next;
  }
  return c;
}

bool dropped(const std::string& line) {
  return (line.find("In function") != std::string::npos && line.find("sylva_") != std::string::npos) ||
         line.find("At global scope") != std::string::npos ||
         line.find("compilation terminated") != std::string::npos;
}

// A line under a message that shows its source: "   12 | text" echoes the
// line, "      |    ^~~" marks the column (and labels under it).
bool is_caret_line(const std::string& line) {
  static const std::regex caret(R"(^ +\|.*$)");
  return std::regex_match(line, caret);
}

}  // namespace

std::string compiler_messages(const std::string& err, const SourceLines& lines) {
  static const std::regex located(R"(^(.+?):(\d+):(\d+): ((?:fatal )?error|warning|note): (.*)$)");
  std::stringstream in(err);
  std::string line, kept;
  int moved_to = 0;  // the column the last message was moved to; 0: not moved
  bool caret_written = false;
  while (std::getline(in, line)) {
    if (dropped(line)) continue;
    std::smatch m;
    if (std::regex_match(line, m, located)) {
      moved_to = 0;
      // A number past int (a #line the compiler took) leaves the message as it is.
      const std::optional<int> line_number = lang::nonnegative_int(m[2].str());
      const std::optional<int> column_number = lang::nonnegative_int(m[3].str());
      const int column = column_number.value_or(0);
      if (std::optional<std::string> text =
              line_number && column_number ? lines(m[1].str(), *line_number) : std::nullopt) {
        const LineColumns c = columns_of(*text);
        if (column > c.width && column > 1) {
          // Inside generated code: where it starts is not known, the
          // statement the line begins with is.
          moved_to = c.first_word;
          caret_written = false;
          line = m[1].str() + ":" + m[2].str() + ":" + std::to_string(moved_to) + ": " + m[4].str() + ": " + m[5].str();
        }
      }
    } else if (moved_to > 0 && is_caret_line(line)) {
      // The compiler's caret stands past the line: one at the new column instead.
      if (!caret_written) kept += line.substr(0, line.find('|') + 1) + std::string(moved_to, ' ') + "^\n";
      caret_written = true;
      continue;
    }
    kept += line + "\n";
  }
  while (!kept.empty() && kept.back() == '\n') kept.pop_back();
  return kept;
}

std::string compiler_messages(const std::string& err) {
  std::map<std::string, std::vector<std::string>> files;
  return compiler_messages(err, [&files](const std::string& file, int line) -> std::optional<std::string> {
    auto it = files.find(file);
    if (it == files.end()) {
      std::vector<std::string> text_lines;
      if (WholeFile whole = read_whole_file(file)) {
        std::stringstream text(whole.bytes);
        for (std::string l; std::getline(text, l);) text_lines.push_back(l);
      }
      it = files.emplace(file, std::move(text_lines)).first;
    }
    if (line < 1 || static_cast<std::size_t>(line) > it->second.size()) return std::nullopt;
    return it->second[static_cast<std::size_t>(line - 1)];
  });
}

}  // namespace sylva::build
