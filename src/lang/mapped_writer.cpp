#include "lang/mapped_writer.h"

namespace sylva::lang {
namespace {

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// Tokens past this column are not moved there: the padding of each one
// placed behind its own line marker would grow with the square of a long
// line (a generated axiom); the compiler's messages about them are clamped
// to the line instead.
constexpr int kPlacedColumns = 512;

}  // namespace

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

void MappedWriter::token(const Token& t) {
  move_to(t.file, t.line);
  if (t.kind == TokenKind::Verbatim) {
    append(t.text);
    line_ += count_lines(t.text);
    after_generated_ = false;
    return;
  }
  const int column = t.column > 1 ? t.column : 1;
  // Right after generated text the token needs a space of its own: the two
  // could otherwise read as one token.
  const bool room = column_ < column || (column_ == column && (at_line_start() || !after_generated_));
  if (!room && column > kPlacedColumns) {
    append(" " + t.text);
    after_generated_ = false;
    return;
  }
  if (!room) {
    new_line();
    marker(t.file, t.line);
  }
  pad_to(column);
  append(t.text);
  after_generated_ = false;
}

void MappedWriter::tokens(const Code& code) {
  for (const Token& t : code) token(t);
}

void MappedWriter::inline_text(const std::string& s) {
  if (!at_line_start()) append(" ");
  append(s);
  after_generated_ = true;
}

void MappedWriter::at(const Token& where, const std::string& s) {
  move_to(where.file, where.line);
  if (column_ < where.column) {
    pad_to(where.column);
    append(s);
    after_generated_ = true;
  } else {
    inline_text(s);
  }
}

void MappedWriter::block(const std::string& s) {
  if (!at_line_start()) new_line();
  append(s);
  if (!s.empty() && s.back() != '\n') new_line();
  file_ = -1;
}

void MappedWriter::append(const std::string& s) {
  if (s.empty()) return;
  text_ += s;
  const std::size_t newline = s.rfind('\n');
  column_ = newline == std::string::npos ? column_ + static_cast<int>(s.size()) : static_cast<int>(s.size() - newline);
}

void MappedWriter::new_line() {
  text_ += '\n';
  column_ = 1;
}

// The line after the marker is `line` of `file`.
void MappedWriter::marker(int file, int line) {
  append("# " + std::to_string(line) + " " + quoted(files_[file]) + "\n");
  file_ = file;
  line_ = line;
}

void MappedWriter::move_to(int file, int line) {
  if (file != file_ || line < line_ || line > line_ + 8) {
    if (!at_line_start()) new_line();
    marker(file, line);
    return;
  }
  while (line_ < line) {
    new_line();
    ++line_;
  }
}

void MappedWriter::pad_to(int column) {
  if (column > column_) append(std::string(static_cast<std::size_t>(column - column_), ' '));
}

}  // namespace sylva::lang
