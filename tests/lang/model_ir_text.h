// Front ends run on source text held in the test, and short renderings of
// the Model IR's pieces to compare with what is worked out from that text.
#pragma once

#include <string>
#include <vector>

#include "lang/cpfg_parser.h"
#include "lang/lc_parser.h"
#include "lang/model_ir.h"
#include "support/diagnostic.h"

namespace sylva::test {

// L+C text as the C preprocessor hands it over: lpfgall.h included first
// (only what follows it is L+C), then the model's lines from line 1 of model.l.
inline lang::Model parse_lc_text(const std::string& source) {
  return lang::parse_lc(lang::tokenize_preprocessed("# 1 \"lpfgall.h\" 1 3\n# 1 \"model.l\" 2\n" + source), "model.l");
}

// A cpfg L-system file's text; plant.l is not on disk, so line continuations
// (a leading tab) are read from the text itself.
inline lang::Model parse_cpfg_text(const std::string& source) { return lang::parse_cpfg(source, "plant.l"); }

// The error a parse stops with ("file:line:column: error: ..."), or "no error".
template <class Parse>
std::string parse_error(Parse parse, const std::string& source) {
  try {
    parse(source);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

// Tokens joined by single spaces.
inline std::string text(const lang::Code& code) {
  std::string out;
  for (const lang::Token& t : code) out += (out.empty() ? "" : " ") + t.text;
  return out;
}

// "A(x + 1, 2) B" for a module list.
inline std::string text(const std::vector<lang::ModuleCall>& calls) {
  std::string out;
  for (const lang::ModuleCall& call : calls) {
    out += (out.empty() ? "" : " ") + call.name;
    if (call.args.empty()) continue;
    out += "(";
    for (std::size_t k = 0; k < call.args.size(); ++k) out += (k ? ", " : "") + text(call.args[k]);
    out += ")";
  }
  return out;
}

// "A(x) B(y, z)" for a part of a predecessor.
inline std::string text(const std::vector<lang::PatternModule>& part) {
  std::string out;
  for (const lang::PatternModule& m : part) {
    out += (out.empty() ? "" : " ") + m.name;
    if (m.formals.empty()) continue;
    out += "(";
    for (std::size_t k = 0; k < m.formals.size(); ++k) out += (k ? ", " : "") + m.formals[k];
    out += ")";
  }
  return out;
}

// A body part by part: code as its tokens, "produce A(x)", "nproduce B",
// "propensity <code> produce <modules>", "InLeftContext(A(x))", "d(x) = <code>", joined by " | ".
inline std::string text(const lang::Body& body) {
  static const char* contexts[] = {"InNewLeftContext", "InLeftContext", "", "InRightContext", "InNewRightContext"};
  auto modules = [](const lang::BodyPart& part) { return part.modules.empty() ? "" : " " + text(part.modules); };
  std::string out;
  for (const lang::BodyPart& part : body) {
    std::string piece;
    switch (part.kind) {
      case lang::BodyPart::kCode: piece = text(part.code); break;
      case lang::BodyPart::kProduce: piece = "produce" + modules(part); break;
      case lang::BodyPart::kNProduce: piece = "nproduce" + modules(part); break;
      case lang::BodyPart::kPropensity:
        piece = "propensity " + text(part.code) + " produce" + modules(part);
        break;
      case lang::BodyPart::kInContext: piece = std::string(contexts[part.context]) + "(" + text(part.modules) + ")"; break;
      case lang::BodyPart::kRate: piece = "d(" + part.rate_of + ") = " + text(part.code); break;
    }
    out += (out.empty() ? "" : " | ") + piece;
  }
  return out;
}

// The items of one kind, in source order.
template <class T>
std::vector<const T*> items_of(const lang::Model& model) {
  std::vector<const T*> found;
  for (const lang::Item& item : model.items)
    if (const T* x = std::get_if<T>(&item)) found.push_back(x);
  return found;
}

// "line:column" of a token.
inline std::string at(const lang::Token& t) { return std::to_string(t.line) + ":" + std::to_string(t.column); }

}  // namespace sylva::test
