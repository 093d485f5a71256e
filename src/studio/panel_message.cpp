#include "studio/panel_message.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "studio/text_lines.h"

namespace sylva::studio {

namespace {

// ---- reading a template ---------------------------------------------------

class TemplateReader {
 public:
  TemplateReader(std::string_view text, const SourceLocation& where) : text_(text), where_(where) {
    words_ = split_words(text);
  }

  MessageTemplate read() {
    if (words_.empty()) fail(0, "a message ('d NAME %d SCALE' or 'n LINE WORD EXPONENT %d')");
    MessageTemplate message;
    if (words_[0] == "d") {
      message.form = MessageTemplate::Form::Define;
      message.define = word(1, "the name of a #define after 'd'");
      message.fixed_value = value(2);
      message.scale = scale(3);
    } else if (words_[0] == "n") {
      message.form = MessageTemplate::Form::Word;
      message.line = positive(1, "a line number after 'n'");
      message.word = positive(2, "a word number after the line number");
      message.exponent = static_cast<int>(integer(3, "a power of ten after the word number"));
      message.fixed_value = value(4);
    } else {
      message.form = MessageTemplate::Form::ScaledWord;
      message.line = positive(0, "a message beginning with 'd', 'n' or a line number");
      message.word = positive(1, "a word number after the line number");
      message.fixed_value = value(2);
      message.scale = scale(3);
    }
    return message;
  }

 private:
  [[noreturn]] void fail(std::size_t index, const std::string& expected) const {
    SourceLocation at = where_;
    const std::size_t offset = index < words_.size() ? words_[index].data() - text_.data() : text_.size();
    at.column += static_cast<int>(offset);
    throw ModelError(at, "expected " + expected + " in the message '" + std::string(text_) + "'");
  }

  std::string_view word(std::size_t index, const std::string& expected) const {
    if (index >= words_.size()) fail(index, expected);
    return words_[index];
  }

  long long integer(std::size_t index, const std::string& expected) const {
    const std::string_view text = word(index, expected);
    long long number = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (error != std::errc() || end != text.data() + text.size()) fail(index, expected);
    return number;
  }

  int positive(std::size_t index, const std::string& expected) const {
    const long long number = integer(index, expected);
    if (number < 1 || number > 1'000'000'000) fail(index, expected);
    return static_cast<int>(number);
  }

  std::optional<long long> value(std::size_t index) const {
    if (word(index, "%d or an integer value") == "%d") return std::nullopt;
    return integer(index, "%d or an integer value");
  }

  // Optional: awkped's manual gives "d SIZE 5" as dividing by nothing.
  double scale(std::size_t index) const {
    if (index >= words_.size()) return 1;
    const std::string_view text = words_[index];
    double number = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (error != std::errc() || end != text.data() + text.size() || number == 0 || !std::isfinite(number))
      fail(index, "a scale (a number other than 0) after the value");
    return number;
  }

  std::string_view text_;
  SourceLocation where_;
  std::vector<std::string_view> words_;
};

// ---- editing a file ---------------------------------------------------------

struct Replacement {
  std::size_t offset = 0;  // in the whole text
  std::size_t length = 0;
  std::string text;
  int line = 0;
};

FileEdit spliced(std::string_view text, const std::vector<Replacement>& replacements) {
  FileEdit edit;
  std::size_t copied = 0;
  for (const Replacement& r : replacements) {
    edit.text.append(text.substr(copied, r.offset - copied)).append(r.text);
    copied = r.offset + r.length;
    edit.changed_lines.push_back(r.line);
  }
  edit.text.append(text.substr(copied));
  return edit;
}

FileEdit unchanged(std::string_view text, std::string problem) {
  return FileEdit{std::string(text), {}, std::move(problem)};
}

std::size_t offset_in(const TextLine& line, std::string_view part) {
  return line.offset + static_cast<std::size_t>(part.data() - line.text.data());
}

// awkped: the WORDth blank-separated word; awk keeps a comma after the new
// value when the old word had one ("1, 2, 3" lists).
FileEdit replace_word(std::string_view text, int line_number, int word_number, const std::string& value) {
  const std::vector<TextLine> lines = split_lines(text);
  if (line_number > static_cast<int>(lines.size()))
    return unchanged(text, "the file has no line " + std::to_string(line_number));
  const TextLine& line = lines[line_number - 1];
  const std::vector<std::string_view> words = split_words(line.text);
  if (word_number > static_cast<int>(words.size()))
    return unchanged(text, "line " + std::to_string(line_number) + " has no word " + std::to_string(word_number));
  const std::string_view old = words[word_number - 1];
  const std::string replacement = value + (old.find(',') != std::string_view::npos ? "," : "");
  return spliced(text, {{offset_in(line, old), old.size(), replacement, line_number}});
}

bool is_number_char(char c) { return c == '-' || c == '.' || (c >= '0' && c <= '9'); }

// The number ped's patterns find for `field` on a line: after the first ':',
// after the first ',', or between a second ',' and the one before it (blanks
// after the punctuation allowed). npos when the line has none.
std::size_t ped_field_start(std::string_view line, int field) {
  const auto skip_spaces = [&](std::size_t at) {
    while (at < line.size() && line[at] == ' ') ++at;
    return at;
  };
  const auto skip_number = [&](std::size_t at) {
    while (at < line.size() && is_number_char(line[at])) ++at;
    return at;
  };
  if (field == 1 || field == 2) {
    const std::size_t mark = line.find(field == 1 ? ':' : ',');
    return mark == std::string_view::npos ? mark : skip_spaces(mark + 1);
  }
  for (std::size_t comma = line.find(','); comma != std::string_view::npos; comma = line.find(',', comma + 1)) {
    const std::size_t after = skip_number(skip_spaces(comma + 1));
    if (after < line.size() && line[after] == ',') return skip_spaces(after + 1);
  }
  return std::string_view::npos;
}

FileEdit replace_ped_field(std::string_view text, int line_number, int field, const std::string& value) {
  if (field > 3) return unchanged(text, "ped edits fields 1 to 3 only, not " + std::to_string(field));
  const std::vector<TextLine> lines = split_lines(text);
  if (line_number > static_cast<int>(lines.size()))
    return unchanged(text, "the file has no line " + std::to_string(line_number));
  const TextLine& line = lines[line_number - 1];
  const std::size_t start = ped_field_start(line.text, field);
  if (start == std::string_view::npos)
    return unchanged(text, "line " + std::to_string(line_number) + " has no field " + std::to_string(field) +
                               " (a number after ':' or ',')");
  std::size_t end = start;
  while (end < line.text.size() && is_number_char(line.text[end])) ++end;
  return spliced(text, {{line.offset + start, end - start, value, line_number}});
}

// value × 10^exponent, written by moving the decimal point in value's
// digits so that no binary rounding creeps in (48, -1 -> "4.8").
std::string decimal_shift_text(long long value, int exponent) {
  std::string digits = std::to_string(value < 0 ? -static_cast<unsigned long long>(value)
                                                : static_cast<unsigned long long>(value));
  if (value == 0) return "0";
  if (exponent >= 0) {
    digits.append(static_cast<std::size_t>(exponent), '0');
  } else {
    const std::size_t fraction = static_cast<std::size_t>(-exponent);
    if (digits.size() <= fraction) digits.insert(0, fraction - digits.size() + 1, '0');
    digits.insert(digits.size() - fraction, ".");
    while (digits.back() == '0') digits.pop_back();
    if (digits.back() == '.') digits.pop_back();
  }
  return (value < 0 ? "-" : "") + digits;
}

}  // namespace

MessageTemplate parse_message(std::string_view text, const SourceLocation& where) {
  return TemplateReader(text, where).read();
}

std::string shortest_number_text(double value) {
  if (value == 0) return "0";  // not "-0"
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string message_value_text(const MessageTemplate& message, long long value) {
  const long long sent = message.fixed_value.value_or(value);
  if (message.form == MessageTemplate::Form::Word) return decimal_shift_text(sent, message.exponent);
  return shortest_number_text(static_cast<double>(sent) / message.scale);
}

FileEdit apply_message(std::string_view text, const MessageTemplate& message, long long value,
                       ParameterEditor editor) {
  const std::string number = message_value_text(message, value);
  if (editor == ParameterEditor::Ped && message.form != MessageTemplate::Form::Word)
    return unchanged(text, "ped understands only 'n LINE FIELD EXPONENT VALUE' messages");
  switch (message.form) {
    case MessageTemplate::Form::Define:
      return set_define(text, message.define, number);
    case MessageTemplate::Form::Word:
      if (editor == ParameterEditor::Ped) return replace_ped_field(text, message.line, message.word, number);
      return replace_word(text, message.line, message.word, number);
    case MessageTemplate::Form::ScaledWord:
      return replace_word(text, message.line, message.word, number);
  }
  return unchanged(text, "an unknown message form");
}

FileEdit set_define(std::string_view text, std::string_view name, std::string_view value_text) {
  std::vector<Replacement> replacements;
  for (const TextLine& line : split_lines(text)) {
    const std::vector<std::string_view> words = split_words(line.text);
    if (words.size() < 2 || words[0] != "#define" || words[1] != name) continue;
    if (words.size() == 2) {
      replacements.push_back({offset_in(line, words[1]) + words[1].size(), 0, " " + std::string(value_text), line.number});
      continue;
    }
    // A comment written against the value ("4// size") stays a comment.
    std::string_view old = words[2];
    old = old.substr(0, std::min(old.find("//"), old.find("/*")));
    replacements.push_back({offset_in(line, old), old.size(), std::string(value_text), line.number});
  }
  if (replacements.empty()) return unchanged(text, "no line '#define " + std::string(name) + "' in the file");
  return spliced(text, replacements);
}

}  // namespace sylva::studio
