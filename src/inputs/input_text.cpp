#include "inputs/input_text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "support/whole_file.h"

namespace sylva::io {

namespace fs = std::filesystem;

std::string read_input_file(const std::string& path, const std::string& what) {
  WholeFile file = read_whole_file(path);
  switch (file.failure) {
    case WholeFile::Failure::None: return std::move(file.bytes);
    case WholeFile::Failure::IsFolder:
      throw ModelError(SourceLocation{path, 0, 0}, "cannot open the " + what + ": it is a folder");
    case WholeFile::Failure::CannotOpen: throw ModelError(SourceLocation{path, 0, 0}, "cannot open the " + what);
    case WholeFile::Failure::CannotRead: break;
  }
  throw ModelError(SourceLocation{path, 0, 0}, "cannot read the " + what);
}

std::string extension_of(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  return to_lower(ext);
}

std::string stem_of(const std::string& path) { return fs::path(path).stem().string(); }

std::string resolve_beside(const std::string& base_file, const std::string& name) {
  fs::path p(name);
  if (p.is_absolute()) return name;
  fs::path folder = fs::path(base_file).parent_path();
  return folder.empty() ? name : (folder / p).string();
}

std::string to_lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

namespace {
template <class Number>
std::optional<Number> parse_number(std::string_view text) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  if (text.empty() || text[0] == '+') return std::nullopt;
  Number value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}
}  // namespace

std::optional<float> parse_float(std::string_view text) { return parse_number<float>(text); }
std::optional<double> parse_double(std::string_view text) { return parse_number<double>(text); }

std::optional<int> parse_int(std::string_view text) {
  std::optional<float> value = parse_float(text);
  if (!value || std::trunc(*value) != *value || std::fabs(*value) > 2e9f) return std::nullopt;
  return static_cast<int>(*value);
}

std::optional<bool> parse_flag(std::string_view text) {
  std::string t = to_lower(text);
  if (t == "on" || t == "yes" || t == "true") return true;
  if (t == "off" || t == "no" || t == "false") return false;
  return std::nullopt;
}

std::vector<Word> split_words(std::string_view line, int line_number) {
  std::vector<Word> words;
  std::size_t i = 0;
  auto separator = [](char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; };
  while (i < line.size()) {
    if (separator(line[i])) {
      ++i;
      continue;
    }
    std::size_t start = i;
    std::string text;
    if (line[i] == '"') {
      ++i;
      while (i < line.size() && line[i] != '"') text += line[i++];
      if (i < line.size()) ++i;
    } else {
      while (i < line.size() && !separator(line[i])) {
        text += line[i];
        if (line[i++] == ':') break;
      }
    }
    words.push_back(Word{std::move(text), line_number, static_cast<int>(start) + 1});
  }
  return words;
}

WordReader::WordReader(std::string file, std::string_view content) : file_(std::move(file)) {
  std::size_t start = 0;
  while (start <= content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string_view::npos) end = content.size();
    std::string_view line = content.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines_.emplace_back(line);
    for (Word& w : split_words(line, static_cast<int>(lines_.size()))) words_.push_back(std::move(w));
    start = end + 1;
  }
  end_.line = static_cast<int>(lines_.size());
  end_.column = lines_.empty() ? 1 : static_cast<int>(lines_.back().size()) + 1;
  // A final newline ends the last line rather than starting an empty one.
  if (lines_.size() > 1 && lines_.back().empty()) {
    end_.line -= 1;
    end_.column = static_cast<int>(lines_[lines_.size() - 2].size()) + 1;
  }
}

WordReader::WordReader(std::string file, std::vector<Word> words, Word end)
    : file_(std::move(file)), words_(std::move(words)), end_(std::move(end)), end_name_("the end of the line") {}

const Word& WordReader::peek() const { return at_end() ? end_ : words_[next_]; }

Word WordReader::next(std::string_view what) {
  if (at_end()) expected(what);
  return words_[next_++];
}

float WordReader::number(std::string_view what) {
  if (at_end() || !parse_float(peek().text)) expected(what);
  return *parse_float(words_[next_++].text);
}

int WordReader::integer(std::string_view what) {
  if (at_end() || !parse_int(peek().text)) expected(what);
  return *parse_int(words_[next_++].text);
}

int WordReader::integer_at_most(std::string_view what, int most) {
  const Word at = peek();
  const int value = integer(what);
  if (value > most)
    fail(at, std::string(what) + " " + at.text + " is past the limit of " + std::to_string(most) +
                 ", far above any real model's (is the file damaged?)");
  return value;
}

geometry::Vec3 WordReader::vec3(std::string_view what) {
  std::string w(what);
  float x = number(w + " (x)");
  float y = number(w + " (y)");
  float z = number(w + " (z)");
  return {x, y, z};
}

void WordReader::expect(std::string_view keyword) {
  if (!accept(keyword)) expected("'" + std::string(keyword) + "'");
}

bool WordReader::accept(std::string_view keyword) {
  if (at_end() || to_lower(peek().text) != to_lower(keyword)) return false;
  ++next_;
  return true;
}

std::string WordReader::rest_of_line(std::string_view what) {
  if (at_end()) expected(what);
  const Word& first = words_[next_];
  if (lines_.empty()) {
    std::string text = words_[next_++].text;
    while (!at_end() && words_[next_].line == first.line) text += " " + words_[next_++].text;
    return text;
  }
  const std::string& line = lines_[static_cast<std::size_t>(first.line - 1)];
  std::string text = line.substr(static_cast<std::size_t>(first.column - 1));
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  while (!at_end() && words_[next_].line == first.line) ++next_;
  return text;
}

void WordReader::fail(const Word& at, const std::string& message) const {
  throw ModelError(location_of(file_, at), message);
}

void WordReader::expected(std::string_view what) const {
  std::string found = at_end() ? std::string(end_name_) : "'" + peek().text + "'";
  fail(peek(), "expected " + std::string(what) + ", found " + found);
}

SourceLocation location_of(const std::string& file, const Word& word) {
  return SourceLocation{file, word.line, word.column};
}

std::string blank_comments(std::string_view text) {
  std::string out(text);
  std::size_t i = 0;
  while (i < out.size()) {
    if (out[i] == '/' && i + 1 < out.size() && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (out[i] == '/' && i + 1 < out.size() && out[i + 1] == '*') {
      out[i++] = ' ';
      out[i++] = ' ';
      while (i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/')) {
        if (out[i] != '\n') out[i] = ' ';
        ++i;
      }
      for (int k = 0; k < 2 && i < out.size(); ++k) out[i++] = ' ';
    } else {
      ++i;
    }
  }
  return out;
}

std::optional<Command> split_command(std::string_view line, int line_number) {
  std::size_t start = line.find_first_not_of(" \t\r\f\v");
  if (start == std::string_view::npos) return std::nullopt;
  std::size_t colon = line.find(':', start);
  std::size_t name_end = colon == std::string_view::npos ? line.size() : colon;
  Command command;
  bool space = false;
  for (std::size_t i = start; i < name_end; ++i) {
    if (std::isspace(static_cast<unsigned char>(line[i]))) {
      space = true;
      continue;
    }
    if (space && !command.name.empty()) command.name += ' ';
    space = false;
    command.name += static_cast<char>(std::tolower(static_cast<unsigned char>(line[i])));
  }
  command.name_word = Word{std::string(line.substr(start, name_end - start)), line_number, static_cast<int>(start) + 1};
  while (!command.name_word.text.empty() && std::isspace(static_cast<unsigned char>(command.name_word.text.back())))
    command.name_word.text.pop_back();
  std::size_t end = line.size();
  while (end > 0 && std::isspace(static_cast<unsigned char>(line[end - 1]))) --end;
  command.end = Word{"", line_number, static_cast<int>(end) + 1};
  if (colon != std::string_view::npos) {
    for (Word& w : split_words(line.substr(colon + 1), line_number)) {
      w.column += static_cast<int>(colon) + 1;
      command.arguments.push_back(std::move(w));
    }
  }
  return command;
}

}  // namespace sylva::io
