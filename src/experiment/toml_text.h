// Plan text as toml++ 3.3.0 can read it. Its test for non-ASCII whitespace
// reaches __builtin_unreachable for many code points (U+039B, say), and it
// asks that test wherever whitespace may stand: between tokens, and after a
// backslash in a multi-line basic string ("""...""", where a backslash at a
// line's end trims the whitespace that follows). So before toml++ sees it:
//   - a non-ASCII character outside strings and comments, which TOML never
//     allows there, is an error at its line and column;
//   - in multi-line basic strings, non-ASCII characters are written as the
//     \uXXXX or \UXXXXXXXX escapes of the same code points, and a backslash
//     followed by one is an error (it starts no escape).
// Comments, literal strings and one-line basic strings are passed as they
// are. Columns count code points, as toml++'s do; in a multi-line basic
// string holding non-ASCII characters, toml++'s columns for what follows on
// the same line are those of the escaped text.
#pragma once

#include <string>

namespace sylva::experiment {

// Throws ModelError naming `path`, the line and the column.
std::string toml_text_for_parser(const std::string& text, const std::string& path);

}  // namespace sylva::experiment
