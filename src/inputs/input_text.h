// Reading the text of input files: words with their line and column, numbers
// and flags, and errors that point at the word that was not what was expected.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/vec3.h"
#include "support/diagnostic.h"

namespace sylva::io {

// The whole file; a ModelError naming it ("cannot open the <what>") if it
// cannot be read.
std::string read_input_file(const std::string& path, const std::string& what);

// The file name's extension, lower case, without the dot ("" if none).
std::string extension_of(const std::string& path);
// The file name without folder and extension.
std::string stem_of(const std::string& path);
// `name` as written when absolute, otherwise relative to `base_file`'s folder.
std::string resolve_beside(const std::string& base_file, const std::string& name);

std::string to_lower(std::string_view text);

std::optional<float> parse_float(std::string_view text);
std::optional<double> parse_double(std::string_view text);
// Integers; a number with a zero fraction ("8.0") is accepted as well.
std::optional<int> parse_int(std::string_view text);
std::optional<bool> parse_flag(std::string_view text);  // on/off, yes/no, true/false

struct Word {
  std::string text;
  int line = 0;
  int column = 0;  // 1-based
};

// Splits one line into words: whitespace and commas separate them, a colon
// ends one ("X:0.5" is "X:" then "0.5"), and "quoted text" is one word.
std::vector<Word> split_words(std::string_view line, int line_number);

// The words of a whole file, read in order, with the helpers the readers
// need to say what they expected where.
// Sizes an input file may give, far above any real model's (the editors
// write tens of points and samples, surfaces of a few subdivisions): a file
// past them is damaged, and would otherwise make a run allocate gigabytes.
inline constexpr int kMaxPoints = 1'000'000;      // control points of a contour, function or curve
inline constexpr int kMaxSamples = 100'000;       // samples of a contour or function, sides of a contour
inline constexpr int kMaxMultiplicity = 1000;     // copies of one control point
inline constexpr int kMaxSubdivisions = 1000;     // of a surface patch, each way
inline constexpr int kMaxInputId = 10'000;        // a contour's or a function's number in a view file
inline constexpr int kMaxShadowMapSize = 16384;   // pixels, each way

class WordReader {
 public:
  WordReader(std::string file, std::string_view content);
  // The words of one line (of a command, say); `end` is where the line ends.
  WordReader(std::string file, std::vector<Word> words, Word end);

  const std::string& file() const { return file_; }
  bool at_end() const { return next_ >= words_.size(); }
  const Word& peek() const;  // at_end(): an empty word after the last line
  Word next(std::string_view what);

  float number(std::string_view what);
  int integer(std::string_view what);
  // A whole number of at most `most`: the sizes a file gives (points,
  // samples, subdivisions) are bounded far above any real model's, so that a
  // damaged file is refused at its line rather than allocated.
  int integer_at_most(std::string_view what, int most);
  geometry::Vec3 vec3(std::string_view what);
  // The next word must be `keyword` (compared ignoring case).
  void expect(std::string_view keyword);
  bool accept(std::string_view keyword);
  // The rest of the current word's line, trimmed, as one text (names may
  // hold spaces); skips the words it covers.
  std::string rest_of_line(std::string_view what);
  bool next_is_number() const { return !at_end() && parse_float(peek().text).has_value(); }

  [[noreturn]] void fail(const Word& at, const std::string& message) const;
  // "expected <what>, found 'x'" (or "found the end of the file/line").
  [[noreturn]] void expected(std::string_view what) const;

 private:
  std::string file_;
  std::vector<std::string> lines_;
  std::vector<Word> words_;
  std::size_t next_ = 0;
  Word end_;
  const char* end_name_ = "the end of the file";
};

SourceLocation location_of(const std::string& file, const Word& word);

// Blanks out /* */ and // comments, keeping every other character where it
// was, so line and column numbers stay those of the file.
std::string blank_comments(std::string_view text);

// A "name: arguments" line of a view or animation file. The name is lower
// case with single spaces ("Z  Buffer" is "z buffer"); the arguments are the
// words after the colon, with their columns in the line.
struct Command {
  std::string name;
  Word name_word;  // where the name starts
  std::vector<Word> arguments;
  Word end;        // just after the line's last character
};
// std::nullopt for a blank line; a command without a colon has only a name.
std::optional<Command> split_command(std::string_view line, int line_number);

// The editors' background image keys ("background:", "backgroundXY:"),
// which say nothing about the curve: read past them. False for other keys.
inline bool skip_editor_background(WordReader& in, const std::string& key) {
  if (key == "background:") {
    in.rest_of_line("the background image");
  } else if (key == "backgroundxy:") {
    in.number("the background's x offset");
    in.number("the background's y offset");
  } else {
    return false;
  }
  return true;
}

// A gallery file of the tools (.cset, .fset): "<kind>galleryver M m",
// "items: N", then N items, each read by read_item(in, default_name).
template <class Item, class ReadItem>
std::vector<Item> read_gallery(const std::string& path, const std::string& kind, const std::string& item_name,
                               ReadItem read_item) {
  WordReader in(path, read_input_file(path, item_name + " set file"));
  in.expect(kind + "galleryver");
  in.integer("the major version");
  in.integer("the minor version");
  in.expect("items:");
  Word count_word = in.peek();
  int count = in.integer("the number of " + item_name + "s");
  if (count < 0) in.fail(count_word, "expected a number of " + item_name + "s, found '" + count_word.text + "'");
  std::vector<Item> items;
  for (int i = 0; i < count; ++i) items.push_back(read_item(in, stem_of(path) + "_" + std::to_string(i + 1)));
  if (!in.at_end())
    in.expected("the end of the " + item_name + " set (it has " + std::to_string(count) + " items)");
  return items;
}

}  // namespace sylva::io
