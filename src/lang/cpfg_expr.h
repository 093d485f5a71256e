// cpfg's expressions and statements (CPFG manual 3.2 and 5) as C++ text.
// Internal to the cpfg front end.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "support/diagnostic.h"

namespace sylva::lang::cpfg {

struct Pos {
  int file = 0;
  int line = 0;
  int column = 0;
};

// One logical line of the L-system file: physical lines joined as cpfg joins
// them (cpfg_lines.h), with each character's position.
struct Line {
  std::string text;
  std::vector<Pos> pos;  // one per character, plus one for the end
};

class Cursor {
 public:
  // `warnings` receives "file:line:column: warning: ..." for what is read past.
  Cursor(const Line& line, const std::vector<std::string>& files, std::vector<std::string>* warnings = nullptr)
      : line_(line), files_(files), warnings_(warnings) {}

  std::size_t at() const { return i_; }
  void set(std::size_t i) { i_ = i; }
  char peek(std::size_t ahead = 0) const { return i_ + ahead < line_.text.size() ? line_.text[i_ + ahead] : '\0'; }
  bool done() { skip_space(); return i_ >= line_.text.size(); }
  void skip_space() {
    while (i_ < line_.text.size() && (line_.text[i_] == ' ' || line_.text[i_] == '\t' || line_.text[i_] == '\r')) ++i_;
  }
  bool starts_with(const char* s) const { return line_.text.compare(i_, std::char_traits<char>::length(s), s) == 0; }
  // Skips spaces, then consumes `s` if it comes next.
  bool accept(const char* s) {
    skip_space();
    if (!starts_with(s)) return false;
    i_ += std::char_traits<char>::length(s);
    return true;
  }
  void expect(const char* s, const std::string& what) {
    if (!accept(s)) fail("expected " + what);
  }
  char get() { return i_ < line_.text.size() ? line_.text[i_++] : '\0'; }
  Pos pos() const { return line_.pos[std::min(i_, line_.text.size())]; }
  Pos pos_at(std::size_t i) const { return line_.pos[std::min(i, line_.text.size())]; }
  SourceLocation location() const { return location(pos()); }
  SourceLocation location(Pos p) const { return SourceLocation{files_[p.file], p.line, p.column}; }
  // "expected X, found Y"
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void fail_at(Pos p, const std::string& message) const { throw ModelError(location(p), message); }
  const std::string& text() const { return line_.text; }
  // How deeply the expression or statement being read is nested (cpfg_expr.cpp
  // bounds it).
  int& nesting() { return nesting_; }
  void warn_at(Pos p, const std::string& message) const {
    if (!warnings_) return;
    const SourceLocation at = location(p);
    warnings_->push_back(at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                         ": warning: " + message);
  }

 private:
  const Line& line_;
  const std::vector<std::string>& files_;
  std::vector<std::string>* warnings_;
  std::size_t i_ = 0;
  int nesting_ = 0;
};

// Names an expression may use.
struct Scope {
  std::set<std::string> formals;  // of the predecessor
  std::set<std::string> locals;   // assigned in the production's statements
  std::set<std::string> globals;  // assigned in Start/End blocks
  std::set<std::string> arrays;   // define: { array ... }
  bool control_block = false;     // assignments to new names make globals
  // Where warnings go ("file:line:column: warning: ..."); none: dropped.
  std::vector<std::string>* warnings = nullptr;
};

// The C++ name of a cpfg variable (kept apart from C++ keywords and helpers).
inline std::string variable(const std::string& name) { return "v_" + name; }

// An expression, up to a token that cannot continue it; C++ text of a double
// (conditions may be bool).
std::string expression(Cursor& c, Scope& scope);

// Statements up to the closing `}` (the `{` already read; the `}` is read).
std::string statements(Cursor& c, Scope& scope);

}  // namespace sylva::lang::cpfg
