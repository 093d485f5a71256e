#include "lang/cpfg_lines.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "support/line_marker.h"

namespace sylva::lang::cpfg {
namespace {

std::string lower(const std::string& s) {
  std::string out;
  for (char c : s) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The source files the line markers name, read once each.
class SourceFiles {
 public:
  // Whether line `n` (1-based) of `file` starts with a tab; nothing when the
  // file cannot be read or has no such line.
  std::optional<bool> tab_led(const std::string& file, int n) {
    const std::string* text = line(file, n);
    if (!text) return std::nullopt;
    return !text->empty() && (*text)[0] == '\t';
  }

  // A preprocessor directive (#define ...): the preprocessor leaves its line empty.
  bool directive(const std::string& file, int n) {
    const std::string* text = line(file, n);
    if (!text) return false;
    std::size_t i = text->find_first_not_of(" \t");
    if (i == std::string::npos || (*text)[i] != '#') return false;
    i = text->find_first_not_of(" \t", i + 1);
    return i == std::string::npos || std::isalnum(static_cast<unsigned char>((*text)[i]));
  }

 private:
  const std::string* line(const std::string& file, int n) {
    auto it = files_.find(file);
    if (it == files_.end()) {
      std::optional<std::vector<std::string>> lines;
      std::ifstream in(file, std::ios::binary);
      if (in) {
        lines.emplace();
        std::string l;
        while (std::getline(in, l)) lines->push_back(l);
      }
      it = files_.emplace(file, std::move(lines)).first;
    }
    if (!it->second || n < 1 || static_cast<std::size_t>(n) > it->second->size()) return nullptr;
    return &(*it->second)[static_cast<std::size_t>(n) - 1];
  }

  std::map<std::string, std::optional<std::vector<std::string>>> files_;
};

// How far into a statement cpfg's lexer is: in symbols (modules) or in an
// expression part, and how many expression `{` are open. cpfg's lexer reads
// past newlines only inside those braces; a `{` among symbols is a polygon.
class StatementState {
 public:
  // A new statement: keywords whose text after the colon is an expression.
  void begin(const std::string& text) {
    expression_ = false;
    nesting_ = braces_ = 0;
    from_ = 0;
    const std::string l = lower(text);
    std::size_t b = l.find_first_not_of(" \t");
    if (b == std::string::npos) return;
    static const char* const kExpressionKeys[] = {"seed:",       "derivation length:", "derivationlength:",
                                                  "maximum depth:", "define:",         "start:",
                                                  "end:",        "starteach:",         "start each:",
                                                  "endeach:",    "end each:"};
    static const char* const kOtherKeys[] = {"lsystem:", "axiom:", "consider:", "ignore:", "homomorphism:",
                                             "decomposition:"};
    for (const char* key : kExpressionKeys)
      if (l.compare(b, std::char_traits<char>::length(key), key) == 0) {
        expression_ = true;
        from_ = b + std::char_traits<char>::length(key);
        return;
      }
    for (const char* key : kOtherKeys)
      if (l.compare(b, std::char_traits<char>::length(key), key) == 0) {
        from_ = b + std::char_traits<char>::length(key);
        return;
      }
  }

  // Reads the statement's text from where the last call stopped.
  void scan(const std::string& s) {
    std::size_t i = std::max(from_, done_);
    while (i < s.size()) {
      const char c = s[i];
      if (!expression_) {
        if (s.compare(i, 3, "-->") == 0 || s.compare(i, 3, "-o>") == 0) {
          i += 3;
          continue;
        }
        if (c == ':' || c == '(') {
          expression_ = true;
          nesting_ = 1;
        }
        ++i;
        continue;
      }
      if (s.compare(i, 3, "-->") == 0 || s.compare(i, 3, "-o>") == 0 || s.compare(i, 2, "->") == 0) {
        expression_ = false;
        i += s[i + 1] == '>' ? 2 : 3;
        continue;
      }
      if (c == '"') {
        const std::size_t e = s.find('"', i + 1);
        i = e == std::string::npos ? s.size() : e + 1;
        continue;
      }
      if (c == '(' || c == '{') ++nesting_;
      if (c == '{') ++braces_;
      if (c == ')' || c == '}') --nesting_;
      if (c == '}' && braces_ > 0) --braces_;
      if (c == ')' && nesting_ == 0) expression_ = false;
      ++i;
    }
    done_ = i;
  }

  void reset() { done_ = 0; }
  bool in_block() const { return braces_ > 0; }

 private:
  bool expression_ = false;
  int nesting_ = 0, braces_ = 0;
  std::size_t from_ = 0, done_ = 0;
};

}  // namespace

std::vector<Line> read_logical_lines(const std::string& text, std::vector<std::string>& files,
                                     const std::string& main_file) {
  std::vector<Line> lines;
  SourceFiles sources;
  StatementState state;
  auto file_index = [&](const std::string& name) {
    auto it = std::find(files.begin(), files.end(), name);
    if (it != files.end()) return static_cast<int>(it - files.begin());
    files.push_back(name);
    return static_cast<int>(files.size() - 1);
  };
  files.push_back(main_file);
  std::istringstream in(text);
  std::string raw, file_name = main_file;
  int file = 0, line = 1;
  // The last line that had text: its file and line.
  int last_file = -1, last_line = 0;
  while (std::getline(in, raw)) {
    if (std::optional<LineMarker> marker = parse_line_marker(raw)) {
      file_name = marker->file;
      file = file_index(file_name);
      line = marker->line;
      continue;
    }
    const int this_line = line++;
    if (raw.find_first_not_of(" \t\r") == std::string::npos) continue;

    // cpfg's "\n\t": every newline from the last line with text to this one
    // must be followed by a tab (blank lines in between too).
    bool tab_chain = !lines.empty() && last_file == file && last_line < this_line;
    for (int k = last_line + 1; tab_chain && k <= this_line; ++k) {
      std::optional<bool> tab = sources.tab_led(file_name, k);
      if (!tab) {
        tab_chain = k == this_line && last_line + 1 == this_line && raw[0] == '\t';
        break;
      }
      tab_chain = *tab && (k == this_line || !sources.directive(file_name, k));
    }
    const bool continues = !lines.empty() && (state.in_block() || tab_chain);
    if (!continues) {
      lines.emplace_back();
      state.reset();
    }
    Line& l = lines.back();
    if (continues) {
      l.text += ' ';
      l.pos.push_back(l.pos.back());
    }
    for (std::size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] == '\r') continue;
      l.text += raw[k];
      l.pos.push_back(Pos{file, this_line, static_cast<int>(k) + 1});
    }
    if (!continues) state.begin(l.text);
    state.scan(l.text);
    last_file = file;
    last_line = this_line;
  }
  for (Line& l : lines) l.pos.push_back(Pos{l.pos.back().file, l.pos.back().line, l.pos.back().column + 1});
  return lines;
}

}  // namespace sylva::lang::cpfg
