// The messages a panel sends and what the parameter editors do with them
// (VLAB Tools manual, 2.3 and 11.2). A panel writes an item's message
// template with "%d" replaced by the item's value; "panel P | awkped F" or
// "panel P | ped F" then edits F:
//   d NAME VALUE [SCALE]    awkped: every line whose first two words are
//                           "#define NAME" gets VALUE/SCALE as its third word
//   n LINE WORD EXP VALUE   awkped: word WORD of line LINE gets VALUE×10^EXP;
//                           ped: field WORD (1: the number after the line's
//                           ':', 2 and 3: the numbers after its first and
//                           second ',') gets VALUE×10^EXP
//   LINE WORD VALUE [SCALE] awkped: word WORD of line LINE gets VALUE/SCALE
// Unlike awk, which joins a line it edits back with single spaces, an edit
// here replaces only the number's characters: the rest of the line (spacing,
// a trailing comment, "\r\n") and every other line stay byte for byte.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/diagnostic.h"

namespace sylva::studio {

enum class ParameterEditor { Awkped, Ped };

struct MessageTemplate {
  enum class Form { Define, Word, ScaledWord };
  Form form = Form::Define;
  std::string define;  // Define: the name after "d"
  int line = 0;        // Word, ScaledWord: 1-based line of the edited file
  int word = 0;        // Word, ScaledWord: 1-based word (awkped) or field (ped)
  int exponent = 0;    // Word: the value is multiplied by 10^exponent
  double scale = 1;    // Define, ScaledWord: the value is divided by scale
  // The value written in the template itself (a button's "d LEFT 1 1");
  // none when the template has "%d" there, to be replaced by the item's.
  std::optional<long long> fixed_value;
};

// Throws ModelError at `where` (the template's first character; columns
// counted from there) naming what was expected.
MessageTemplate parse_message(std::string_view text, const SourceLocation& where);

// The number a message with `value` writes into the file, printed so that it
// reads back as exactly that number: d SIZE 46 10 -> "4.6", 40/1 -> "40",
// n 2 2 -1 48 -> "4.8". A fixed value in the template wins over `value`.
std::string message_value_text(const MessageTemplate& message, long long value);

// The shortest text that reads back as `value` ("4.6", "40", "1e-07").
std::string shortest_number_text(double value);

struct FileEdit {
  std::string text;                // the file's new text
  std::vector<int> changed_lines;  // 1-based; empty when nothing matched
  // Why nothing changed, worded for the user ("no line '#define SIZE ...'");
  // empty when something did.
  std::string problem;
};

// What `editor` does to a file's `text` on receiving `message` with `value`.
FileEdit apply_message(std::string_view text, const MessageTemplate& message, long long value,
                       ParameterEditor editor);

// Awkped's "d" edit with a ready value text: every line whose first two words
// are "#define" and `name` gets `value_text` as its third word (appended when
// it has none). "# define" with a blank after '#' is not matched, as awkped
// does not match it.
FileEdit set_define(std::string_view text, std::string_view name, std::string_view value_text);

}  // namespace sylva::studio
