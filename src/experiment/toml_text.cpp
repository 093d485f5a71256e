#include "experiment/toml_text.h"

#include <cstdint>
#include <cstdio>

#include "support/diagnostic.h"

namespace sylva::experiment {
namespace {

bool is_ascii(unsigned char byte) { return byte < 0x80; }
bool continues_a_character(unsigned char byte) { return (byte & 0xC0) == 0x80; }

// The code point of the UTF-8 sequence at `at`, and its length; a length of
// 0 when it is not well formed (toml++ then says so itself).
std::uint32_t decode(const std::string& text, std::size_t at, std::size_t& length) {
  const auto lead = static_cast<unsigned char>(text[at]);
  length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 0;
  if (length == 0 || at + length > text.size()) return length = 0;
  std::uint32_t code = lead & (0x7F >> length);
  for (std::size_t k = 1; k < length; ++k) {
    const auto byte = static_cast<unsigned char>(text[at + k]);
    if (!continues_a_character(byte)) return length = 0;
    code = code << 6 | (byte & 0x3F);
  }
  return code;
}

std::string escape(std::uint32_t code) {
  char escaped[11];
  if (code <= 0xFFFF) std::snprintf(escaped, sizeof escaped, "\\u%04X", static_cast<unsigned>(code));
  else std::snprintf(escaped, sizeof escaped, "\\U%08X", static_cast<unsigned>(code));
  return escaped;
}

}  // namespace

std::string toml_text_for_parser(const std::string& text, const std::string& path) {
  enum class Inside { Nothing, Comment, BasicString, MultiLineBasicString, LiteralString, MultiLineLiteralString };
  Inside inside = Inside::Nothing;
  std::string out;
  out.reserve(text.size());
  int line = 1, column = 1;
  auto fail = [&](const std::string& message) { throw ModelError({path, line, column}, message); };
  auto quotes_at = [&](std::size_t at, char quote) {
    std::size_t n = 0;
    while (at + n < text.size() && text[at + n] == quote) ++n;
    return n;
  };
  for (std::size_t at = 0; at < text.size();) {
    const auto byte = static_cast<unsigned char>(text[at]);
    std::size_t taken = 1;  // bytes of the text passed on as they are
    switch (inside) {
      case Inside::Nothing:
        if (byte == '#') inside = Inside::Comment;
        else if (byte == '"' || byte == '\'') {
          const bool multi_line = quotes_at(at, static_cast<char>(byte)) >= 3;
          taken = multi_line ? 3 : 1;
          inside = byte == '"' ? (multi_line ? Inside::MultiLineBasicString : Inside::BasicString)
                               : (multi_line ? Inside::MultiLineLiteralString : Inside::LiteralString);
        } else if (!is_ascii(byte)) {
          fail("expected a key, a value or a comment; TOML allows characters outside ASCII only in strings and "
               "comments");
        }
        break;
      case Inside::Comment:
        if (byte == '\n') inside = Inside::Nothing;
        break;
      case Inside::BasicString:
      case Inside::LiteralString: {
        const char quote = inside == Inside::BasicString ? '"' : '\'';
        if (byte == '\\' && inside == Inside::BasicString && at + 1 < text.size() && text[at + 1] != '\n') taken = 2;
        else if (byte == static_cast<unsigned char>(quote) || byte == '\n') inside = Inside::Nothing;
        break;
      }
      case Inside::MultiLineBasicString:
      case Inside::MultiLineLiteralString: {
        const char quote = inside == Inside::MultiLineBasicString ? '"' : '\'';
        if (byte == static_cast<unsigned char>(quote)) {
          taken = quotes_at(at, quote);  // three close it; up to two more belong to the string
          if (taken >= 3) inside = Inside::Nothing;
        } else if (inside == Inside::MultiLineBasicString && byte == '\\' && at + 1 < text.size()) {
          if (!is_ascii(static_cast<unsigned char>(text[at + 1]))) {
            ++column;
            fail("expected an escape sequence after '\\'");
          }
          taken = text[at + 1] == '\n' ? 1 : 2;
        } else if (inside == Inside::MultiLineBasicString && !is_ascii(byte)) {
          std::size_t length = 0;
          const std::uint32_t code = decode(text, at, length);
          if (length > 0) {
            out += escape(code);
            at += length;
            ++column;
            continue;
          }
        }
        break;
      }
    }
    for (std::size_t k = 0; k < taken; ++k) {
      const auto passed = static_cast<unsigned char>(text[at + k]);
      if (passed == '\n') {
        ++line;
        column = 1;
      } else if (!continues_a_character(passed)) {
        ++column;
      }
    }
    out.append(text, at, taken);
    at += taken;
  }
  return out;
}

}  // namespace sylva::experiment
