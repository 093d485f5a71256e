#include "io/string_reader.h"

#include <cctype>
#include <vector>

#include "support/diagnostic.h"
#include "support/whole_file.h"

namespace sylva::io {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

class StringReader {
 public:
  StringReader(const std::string& text, const ModuleTypes& types, const std::string& path)
      : text_(text), types_(types), path_(path) {}

  ModuleString read() {
    if (types_.cpfg())
      throw ModelError(SourceLocation{path_, 0, 0},
                       "a cpfg model's string cannot be read back (saved strings are read for L+C models)");
    ModuleString string;
    std::vector<unsigned char> params;
    skip_space();
    while (at_ < text_.size()) {
      const std::size_t name_at = at_;
      while (at_ < text_.size() && !is_space(text_[at_]) && text_[at_] != '(') ++at_;
      const std::string name = text_.substr(name_at, at_ - name_at);
      if (name.empty()) fail(name_at, "expected a module name, found '('");
      const std::optional<ModuleId> id = types_.find(name);
      if (!id) fail(name_at, "unknown module '" + name + "' (the model declares no module of that name)");
      const ModuleTypes::Type& type = types_[*id];
      params.assign(type.param_size, 0);
      if (at_ < text_.size() && text_[at_] == '(') {
        read_params(*id, name_at, params.data());
      } else if (type.param_count > 0) {
        fail(name_at, count_message(type, 0));
      }
      string.append_module(*id, params.data(), type.param_size);
      if (at_ < text_.size() && !is_space(text_[at_]))
        fail(at_, "expected a space between modules, found '" + std::string(1, text_[at_]) + "'");
      skip_space();
    }
    return string;
  }

 private:
  void skip_space() {
    while (at_ < text_.size() && is_space(text_[at_])) ++at_;
  }

  static std::string count_message(const ModuleTypes::Type& type, std::size_t given) {
    return "module '" + type.name + "' has " + std::to_string(type.param_count) + " parameter" +
           (type.param_count == 1 ? "" : "s") + " but the saved string gives " +
           (given == 0 ? std::string("none") : std::to_string(given));
  }

  // At '(': the parameters up to the matching ')', counted first so that a
  // wrong number of them is said as such.
  void read_params(ModuleId id, std::size_t name_at, unsigned char* params) {
    const ModuleTypes::Type& type = types_[id];
    const std::size_t open = at_;
    std::size_t given = 0, close = open + 1;
    int depth = 0;
    bool empty = true;
    for (; close < text_.size(); ++close) {
      const char c = text_[close];
      if (c == '"') {  // quoted text: skip to its end
        for (++close; close < text_.size() && text_[close] != '"'; ++close)
          if (text_[close] == '\\') ++close;
        continue;
      }
      if (c == '(' || c == '[' || c == '{') ++depth;
      if (c == ']' || c == '}') --depth;
      if (c == ')' && depth-- == 0) break;
      if (c == ',' && depth == 0) ++given;
      if (!is_space(c)) empty = false;
    }
    if (close >= text_.size()) fail(open, "expected ')' to close the parameters of '" + type.name + "'");
    if (!empty) ++given;
    if (given != type.param_count) fail(name_at, count_message(type, given));
    if (given > 0) {
      if (!types_.can_read_params(id)) fail(name_at, "the parameters of module '" + type.name + "' cannot be read back");
      abi::TextSource in{text_.data() + open + 1, text_.data() + close};
      if (!types_.read_params(id, &in, params))
        fail(static_cast<std::size_t>(in.at - text_.data()),
             "expected " + std::string(in.expected ? in.expected : "a parameter value") + " in the parameters of '" +
                 type.name + "'");
      while (in.at < in.end && is_space(*in.at)) ++in.at;
      if (in.at != in.end)
        fail(static_cast<std::size_t>(in.at - text_.data()),
             "expected ')' after the parameters of '" + type.name + "', found '" + std::string(1, *in.at) + "'");
    }
    at_ = close + 1;
  }

  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    int line = 1, column = 1;
    for (std::size_t k = 0; k < offset && k < text_.size(); ++k) {
      if (text_[k] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw ModelError(SourceLocation{path_, line, column}, message);
  }

  const std::string& text_;
  const ModuleTypes& types_;
  const std::string& path_;
  std::size_t at_ = 0;
};

}  // namespace

ModuleString parse_string(const std::string& text, const ModuleTypes& types, const std::string& path) {
  return StringReader(text, types, path).read();
}

namespace {

[[noreturn]] void cannot_read(const std::string& path, const std::string& why) {
  throw ModelError(SourceLocation{path, 0, 0}, "cannot read the saved string: " + why);
}

// The file's text; a folder or a failed read is an error rather than an
// empty string.
std::string read_text(const std::string& path) {
  WholeFile file = read_whole_file(path);
  switch (file.failure) {
    case WholeFile::Failure::None: return std::move(file.bytes);
    case WholeFile::Failure::IsFolder: cannot_read(path, "it is a directory, not a file");
    case WholeFile::Failure::CannotOpen: cannot_read(path, "no such file");
    case WholeFile::Failure::CannotRead: break;
  }
  cannot_read(path, "the file could not be read");
}

}  // namespace

ModuleString read_string_file(const std::string& path, const ModuleTypes& types) {
  const std::string text = read_text(path);
  // OutputString writes even a string of no modules as a line ("\n"), so a
  // file without a single byte was not written by it.
  if (text.empty()) cannot_read(path, "the file is empty (a saved string, even one of no modules, is a line)");
  return parse_string(text, types, path);
}

}  // namespace sylva::io
