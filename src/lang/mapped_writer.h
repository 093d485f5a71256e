// Writes the generated C++ so that its lines map back to the model: every
// token of the model stands on the line and at the column it came from, with
// line markers (`# 12 "plant.l"`) in between, so that a compiler error about
// it points there.
#pragma once

#include <string>
#include <vector>

#include "lang/model_ir.h"

namespace sylva::lang {

// `s` as a C++ string literal.
std::string quoted(const std::string& s);

class MappedWriter {
 public:
  explicit MappedWriter(const std::vector<std::string>& files) : files_(files) {}

  // A token of the model at its line and column: on a new line behind a line
  // marker where generated text already took its place.
  void token(const Token& t);
  void tokens(const Code& code);

  // Generated text on the current line, attributed to the current position.
  void inline_text(const std::string& s);

  // Generated text attributed to `where`: it starts at its column where the
  // line still has room, so an error at its start points there.
  void at(const Token& where, const std::string& s);

  // Generated lines not attributed to the model.
  void block(const std::string& s);

  std::string take() { return std::move(text_); }

 private:
  void append(const std::string& s);
  void new_line();
  void marker(int file, int line);
  void move_to(int file, int line);
  void pad_to(int column);
  bool at_line_start() const { return column_ == 1; }

  const std::vector<std::string>& files_;
  std::string text_;
  int file_ = -1;
  int line_ = 0;
  int column_ = 1;  // where the next character goes on the current line
  bool after_generated_ = false;  // the last text written was not the model's
};

}  // namespace sylva::lang
