// Tokens of preprocessed C++ as the L+C front end sees them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "support/diagnostic.h"

namespace sylva::lang {

enum class TokenKind : std::uint8_t {
  Identifier,
  Number,
  String,     // "..." (any prefix)
  Character,  // '...'
  Punct,      // operators and punctuation
  Verbatim,   // raw lines copied to the output untouched (system headers, pragmas)
  End,
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;
  int file = 0;  // index into TokenStream::files
  int line = 0;
  int column = 0;
  bool space_before = false;

  bool is(TokenKind k, const char* t) const { return kind == k && text == t; }
  bool is_punct(const char* t) const { return is(TokenKind::Punct, t); }
  bool is_ident(const char* t) const { return is(TokenKind::Identifier, t); }
  bool is_ident() const { return kind == TokenKind::Identifier; }
};

// Brackets of any kind, for code taken as it stands up to a delimiter
// outside them.
inline bool is_open(const Token& t) { return t.is_punct("(") || t.is_punct("[") || t.is_punct("{"); }
inline bool is_close(const Token& t) { return t.is_punct(")") || t.is_punct("]") || t.is_punct("}"); }

struct TokenStream {
  std::vector<std::string> files;
  std::vector<Token> tokens;  // ends with an End token
  // Every file the preprocessor read, for the compiled-model cache.
  std::vector<std::string> dependencies;

  SourceLocation location(const Token& t) const { return {files[t.file], t.line, t.column}; }
};

// Splits the output of the C preprocessor into tokens. Text before the
// inclusion of lpfgall.h and text of system headers stays as Verbatim tokens:
// only the model's own code after lpfgall.h is L+C. `lpfgall_seen` tells
// whether lpfgall.h was included at all.
TokenStream tokenize_preprocessed(const std::string& text, bool* lpfgall_seen = nullptr);

}  // namespace sylva::lang
