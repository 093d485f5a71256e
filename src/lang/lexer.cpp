#include <cctype>
#include <cstring>
#include <optional>
#include <string_view>
#include <unordered_map>

#include "lang/token.h"
#include "support/line_marker.h"

namespace sylva::lang {
namespace {

// Longest first, so that maximal munch picks "<<=" over "<<" over "<".
const char* const kPunctuators[] = {
    "<<=", ">>=", "...", "->*", "<=>", "::", "->", "++", "--", "<<", ">>", "<=", ">=", "==", "!=",
    "&&", "||", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", ".*", "##",
};

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '$'; }

class Lexer {
 public:
  explicit Lexer(TokenStream& out) : out_(out) {}

  void line_marker(const LineMarker& marker) {
    const std::string& file = marker.file;
    current_file_ = file_index(file);
    current_line_ = marker.line;
    system_ = marker.system_header;
    if (marker.enters_file && is_lpfgall(file)) lpfgall_seen_ = true;
    if (!file.empty() && file[0] != '<') note_dependency(file);
  }

  void source_line(std::string_view line) {
    if (system_ || !lpfgall_seen_) {
      // lpfgall.h taken from its precompiled header leaves this pragma in
      // place of its text.
      if (is_lpfgall_pch(line)) lpfgall_seen_ = true;
      verbatim(line);
    } else if (!line.empty() && line.find_first_not_of(" \t") != std::string_view::npos &&
               line[line.find_first_not_of(" \t")] == '#') {
      verbatim(line);  // #pragma and friends pass through
    } else {
      tokenize(line);
    }
    ++current_line_;
  }

  bool lpfgall_seen() const { return lpfgall_seen_; }

 private:
  static bool is_lpfgall(std::string_view file) {
    return file == "lpfgall.h" || (file.size() > 10 && file.substr(file.size() - 10) == "/lpfgall.h");
  }

  static bool is_lpfgall_pch(std::string_view line) {
    constexpr std::string_view pragma = "#pragma GCC pch_preprocess \"", suffix = ".gch\"";
    if (line.substr(0, pragma.size()) != pragma || line.size() < pragma.size() + suffix.size() ||
        line.substr(line.size() - suffix.size()) != suffix)
      return false;
    return is_lpfgall(line.substr(pragma.size(), line.size() - pragma.size() - suffix.size()));
  }

  int file_index(const std::string& name) {
    auto [it, inserted] = file_ids_.emplace(name, static_cast<int>(out_.files.size()));
    if (inserted) out_.files.push_back(name);
    return it->second;
  }

  void note_dependency(const std::string& file) {
    if (seen_deps_.emplace(file, 0).second) out_.dependencies.push_back(file);
  }

  void verbatim(std::string_view line) {
    if (!out_.tokens.empty() && out_.tokens.back().kind == TokenKind::Verbatim &&
        out_.tokens.back().file == current_file_ && verbatim_next_line_ == current_line_) {
      out_.tokens.back().text.append(line).push_back('\n');
    } else {
      Token t;
      t.kind = TokenKind::Verbatim;
      t.text.assign(line).push_back('\n');
      t.file = current_file_;
      t.line = current_line_;
      t.column = 1;
      out_.tokens.push_back(std::move(t));
    }
    verbatim_next_line_ = current_line_ + 1;
  }

  void tokenize(std::string_view line) {
    std::size_t i = 0;
    bool space = true;
    while (i < line.size()) {
      char c = line[i];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        space = true;
        ++i;
        continue;
      }
      Token t;
      t.file = current_file_;
      t.line = current_line_;
      t.column = static_cast<int>(i) + 1;
      t.space_before = space;
      space = false;
      std::size_t start = i;
      if (is_ident_start(c)) {
        while (i < line.size() && is_ident_char(line[i])) ++i;
        // String and character prefixes: u8"..", L'..', R"(..)".
        if (i < line.size() && (line[i] == '"' || line[i] == '\'')) {
          std::string_view prefix = line.substr(start, i - start);
          if (prefix == "u8" || prefix == "u" || prefix == "U" || prefix == "L" || prefix == "R" ||
              prefix == "u8R" || prefix == "uR" || prefix == "UR" || prefix == "LR") {
            i = quoted_end(line, i, prefix.back() == 'R');
            t.kind = line[start + prefix.size()] == '"' ? TokenKind::String : TokenKind::Character;
            t.text = std::string(line.substr(start, i - start));
            out_.tokens.push_back(std::move(t));
            continue;
          }
        }
        t.kind = TokenKind::Identifier;
      } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                 (c == '.' && i + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[i + 1])))) {
        ++i;
        while (i < line.size()) {
          char d = line[i];
          if ((d == '+' || d == '-') && (line[i - 1] == 'e' || line[i - 1] == 'E' || line[i - 1] == 'p' ||
                                         line[i - 1] == 'P')) {
            ++i;
          } else if (is_ident_char(d) || d == '.' || d == '\'') {
            ++i;
          } else {
            break;
          }
        }
        t.kind = TokenKind::Number;
      } else if (c == '"' || c == '\'') {
        i = quoted_end(line, i, false);
        t.kind = c == '"' ? TokenKind::String : TokenKind::Character;
      } else {
        t.kind = TokenKind::Punct;
        std::size_t length = 1;
        for (const char* p : kPunctuators) {
          std::size_t n = std::strlen(p);
          if (line.substr(i, n) == p) {
            length = n;
            break;
          }
        }
        i += length;
      }
      t.text = std::string(line.substr(start, i - start));
      out_.tokens.push_back(std::move(t));
    }
  }

  // Index just past the closing quote of the literal opening at `i`.
  static std::size_t quoted_end(std::string_view line, std::size_t i, bool raw) {
    char quote = line[i];
    if (raw) {
      std::size_t open = line.find('(', i);
      if (open == std::string_view::npos) return line.size();
      std::string close = ")" + std::string(line.substr(i + 1, open - i - 1)) + "\"";
      std::size_t end = line.find(close, open);
      return end == std::string_view::npos ? line.size() : end + close.size();
    }
    ++i;
    while (i < line.size() && line[i] != quote) {
      if (line[i] == '\\') ++i;
      ++i;
    }
    return std::min(i + 1, line.size());
  }

  TokenStream& out_;
  std::unordered_map<std::string, int> file_ids_;
  std::unordered_map<std::string, int> seen_deps_;
  int current_file_ = 0;
  int current_line_ = 1;
  int verbatim_next_line_ = -1;
  bool system_ = false;
  bool lpfgall_seen_ = false;
};

}  // namespace

TokenStream tokenize_preprocessed(const std::string& text, bool* lpfgall_seen) {
  TokenStream stream;
  stream.files.push_back("<unknown>");
  Lexer lexer(stream);
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    if (std::optional<LineMarker> marker = parse_line_marker(line)) {
      lexer.line_marker(*marker);
    } else {
      lexer.source_line(line);
    }
    pos = end + 1;
  }
  Token end_token;
  end_token.kind = TokenKind::End;
  if (!stream.tokens.empty()) {
    end_token.file = stream.tokens.back().file;
    end_token.line = stream.tokens.back().line;
  }
  stream.tokens.push_back(end_token);
  if (lpfgall_seen) *lpfgall_seen = lexer.lpfgall_seen();
  return stream;
}

}  // namespace sylva::lang
