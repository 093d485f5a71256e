#include "lang/parallel_safety.h"

#include <cctype>

#include <map>
#include <optional>
#include <set>
#include <vector>
#include <utility>

namespace sylva::lang {
namespace {

using Names = std::set<std::string, std::less<>>;

// Words after which an identifier is an expression, not a declared name.
const Names kExpressionWords = {
    "return", "else", "case", "goto", "delete", "new", "throw", "sizeof", "typename", "do", "co_return",
    "co_yield", "co_await", "not", "and", "or", "xor", "bitand", "bitor", "compl", "not_eq", "and_eq", "or_eq",
    "xor_eq", "decltype", "alignof", "noexcept", "typeid", "using", "namespace", "operator", "template"};

// Words followed by `(` that call nothing.
const Names kNotCalls = {"if", "while", "for", "switch", "return", "sizeof", "alignof", "decltype", "noexcept",
                         "typeid", "catch", "static_assert", "alignas", "static_cast", "const_cast", "do", "else"};

// Words that make a body unsafe wherever they are.
const std::map<std::string, std::string, std::less<>> kUnsafeWords = {
    {"static", "declares a static variable"},
    {"thread_local", "declares a thread-local variable"},
    {"extern", "declares an external variable"},
    {"asm", "holds assembly"},
    {"reinterpret_cast", "reinterprets memory"},
    {"const_cast", "casts away const"},
    {"cout", "writes to the standard output"},
    {"cerr", "writes to the standard error"},
    {"clog", "writes to the standard error"},
    {"stdout", "writes to the standard output"},
    {"stderr", "writes to the standard error"},
    {"cin", "reads the standard input"},
    {"stdin", "reads the standard input"},
    {"errno", "reads or writes errno"},
};

// Functions of the runtime and the C++ library that only compute from their
// arguments (or read the control state, which no body changes in a parallel
// pass): math, vector operations, casts, constructors of the vector types.
const Names kPureFunctions = {
    "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh",
    "exp", "exp2", "expm1", "log", "log2", "log10", "log1p", "pow", "sqrt", "cbrt", "hypot", "fabs", "abs",
    "labs", "fmod", "remainder", "floor", "ceil", "round", "lround", "llround", "trunc", "rint", "lrint",
    "nearbyint", "fmin", "fmax", "min", "max", "clamp", "copysign", "isnan", "isinf", "isfinite", "signbit",
    "sign", "Normalize", "V2f", "V3f", "V2d", "V3d", "V2tf", "V3tf", "V2td", "V3td", "float", "double", "int",
    "long", "short", "char", "bool", "unsigned", "signed", "size_t", "StepNo", "CurrentGroup", "IsForward",
    "DerivationLength", "DecompositionMaxDepth", "InterpretationMaxDepth", "RingLsystem", "NumOfTables",
    "NumOfViews", "IgnoreEnvironment"};
// Namespaces whose pure functions (those above) may be named with them.
const Names kPureNamespaces = {"std::", "::std::", "::sylva::rt::cpfg::", "sylva::rt::cpfg::"};
// Methods of the runtime's vector types: those that read, and those that
// change the vector they are called on (allowed on the body's own).
const Names kReadingMethods = {"Length", "Normalized"};
const Names kChangingMethods = {"Set", "Normalize"};

bool is_operand_end(const Token& t) {
  if (t.kind == TokenKind::Identifier) return !kExpressionWords.count(t.text);
  return t.kind == TokenKind::Number || t.kind == TokenKind::String || t.kind == TokenKind::Character ||
         t.is_punct(")") || t.is_punct("]");
}

bool is_assignment(const Token& t) {
  static const Names ops = {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="};
  return t.kind == TokenKind::Punct && ops.count(t.text);
}

bool is_identifier(const std::string& text) {
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text[0]))) return false;
  for (char c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '$') return false;
  return true;
}

// The tokens of `code` as the lexer splits them: the cpfg front end carries
// the C++ it generates as one token.
Code split_tokens(const Code& code) {
  Code out;
  for (const Token& t : code) {
    if (t.kind != TokenKind::Identifier || is_identifier(t.text)) {
      out.push_back(t);
      continue;
    }
    TokenStream split = tokenize_preprocessed("# 1 \"lpfgall.h\" 1 3\n# 1 \"model\" 2\n" + t.text + "\n");
    for (Token& u : split.tokens) {
      if (u.kind == TokenKind::End) continue;
      u.file = t.file;
      u.line = t.line;
      out.push_back(std::move(u));
    }
  }
  return out;
}

// Index of the token matching the bracket at `open` (searching forward), or
// code.size().
std::size_t matching_forward(const Code& code, std::size_t open) {
  const std::string o = code[open].text;
  const std::string c = o == "(" ? ")" : o == "[" ? "]" : "}";
  int depth = 0;
  for (std::size_t k = open; k < code.size(); ++k) {
    if (code[k].is_punct(o.c_str())) ++depth;
    else if (code[k].is_punct(c.c_str()) && --depth == 0) return k;
  }
  return code.size();
}

// Index of the opening bracket of the one closing at `close`, or nullopt.
std::optional<std::size_t> matching_backward(const Code& code, std::size_t close, const char* open,
                                             const char* closing) {
  int depth = 0;
  for (std::size_t k = close + 1; k-- > 0;) {
    if (code[k].is_punct(closing)) ++depth;
    else if (code[k].is_punct(open) && --depth == 0) return k;
  }
  return std::nullopt;
}

// A function the model defines: its parameter list and body (null body: one
// whose body the analysis does not find, e.g. a constructor with an
// initializer list).
struct Definition {
  Code params;
  Code body;
  bool opaque = false;
  // By parameter: a non-const reference or pointer, which the function may
  // write through; a call must pass the caller's own variable there.
  std::vector<bool> writable;
};

// The comma-separated parts of code[begin, end) at its top level, as ranges.
std::vector<std::pair<std::size_t, std::size_t>> split_top_level(const Code& code, std::size_t begin, std::size_t end) {
  std::vector<std::pair<std::size_t, std::size_t>> parts;
  int depth = 0;
  std::size_t from = begin;
  for (std::size_t k = begin; k <= end; ++k) {
    if (k < end) {
      const Token& t = code[k];
      if (t.is_punct("(") || t.is_punct("<") || t.is_punct("[") || t.is_punct("{")) ++depth;
      if (t.is_punct(")") || t.is_punct(">") || t.is_punct("]") || t.is_punct("}")) --depth;
      if (!(depth == 0 && t.is_punct(","))) continue;
    }
    if (k > from) parts.emplace_back(from, k);
    from = k + 1;
  }
  return parts;
}

class Analysis {
 public:
  explicit Analysis(const Model& model) {
    for (const Item& item : model.items)
      if (const Code* code = std::get_if<Code>(&item)) collect_definitions(*code);
    for (const Definition& d : definitions_["operator"]) {
      if (std::string why = function_reason(d); !why.empty()) {
        model_reason_ = "the model defines an operator that " + why;
        break;
      }
    }
  }

  RuleSafety rule_safety(const Rule& rule) {
    if (!model_reason_.empty()) return {model_reason_, false};
    Scopes scopes(1);
    for (const auto& part : rule.parts)
      for (const PatternModule& m : part)
        for (const std::string& formal : m.formals) scopes.back()[formal] = true;
    draws_ = false;
    std::string why = body_reason(rule.body, scopes);
    return {why, why.empty() && draws_};
  }

 private:
  // Names declared in each open block: true for the body's own variables.
  using Pending = std::map<std::string, bool, std::less<>>;
  using Scopes = std::vector<Pending>;

  void collect_definitions(const Code& written) {
    const Code code = split_tokens(written);
    for (std::size_t k = 0; k + 1 < code.size(); ++k) {
      const Token& t = code[k];
      if ((t.is_ident("struct") || t.is_ident("class") || t.is_ident("union")) && code[k + 1].is_ident())
        types_.insert(code[k + 1].text);
      if (t.is_ident("typedef") || t.is_ident("using")) {
        std::size_t end = k;
        while (end < code.size() && !code[end].is_punct(";")) ++end;
        if (t.is_ident("using") && code[k + 1].is_ident() && k + 2 < code.size() && code[k + 2].is_punct("="))
          types_.insert(code[k + 1].text);
        else if (t.is_ident("typedef") && end > 0 && end < code.size() && code[end - 1].is_ident())
          types_.insert(code[end - 1].text);
      }
      // name ( params ) [const noexcept ...] { body }   or   operator@ ( params ) { body }
      std::string name;
      std::size_t open = 0;
      if (t.is_ident("operator")) {
        name = "operator";
        open = k + 1;
        if (k + 3 < code.size() && code[k + 1].is_punct("(") && code[k + 2].is_punct(")")) open = k + 3;  // operator()
        while (open < code.size() && !code[open].is_punct("(")) ++open;
      } else if (t.is_ident() && code[k + 1].is_punct("(") && !kNotCalls.count(t.text)) {
        name = t.text;
        open = k + 1;
      } else {
        continue;
      }
      if (open >= code.size()) continue;
      const std::size_t close = matching_forward(code, open);
      std::size_t at = close + 1;
      while (at < code.size() && code[at].is_ident() &&
             (code[at].text == "const" || code[at].text == "noexcept" || code[at].text == "override" ||
              code[at].text == "final"))
        ++at;
      if (at >= code.size()) continue;
      Definition d;
      d.params.assign(code.begin() + static_cast<std::ptrdiff_t>(open + 1),
                      code.begin() + static_cast<std::ptrdiff_t>(close));
      d.writable = writable_params(d.params);
      if (code[at].is_punct("{")) {
        const std::size_t end = matching_forward(code, at);
        d.body.assign(code.begin() + static_cast<std::ptrdiff_t>(at), code.begin() + static_cast<std::ptrdiff_t>(end));
      } else if (code[at].is_punct(":") || code[at].is_punct("->")) {
        d.opaque = true;  // an initializer list or a trailing return type
      } else {
        continue;  // a declaration or a call
      }
      definitions_[name].push_back(std::move(d));
    }
  }

  // Why a function the model defines is unsafe to call, or empty.
  std::string function_reason(const Definition& d) {
    if (d.opaque) return "has a form the analysis does not follow";
    Scopes scopes(1);
    // Parameters are the function's own: what it writes through a reference
    // or pointer, the caller must own (checked at each call).
    for (const auto& [begin, end] : split_top_level(d.params, 0, d.params.size())) {
      std::string name;
      for (std::size_t j = begin; j < end && !d.params[j].is_punct("="); ++j)
        if (d.params[j].is_ident()) name = d.params[j].text;
      if (!name.empty()) scopes.back()[name] = true;
    }
    Body body{BodyPart{BodyPart::kCode, d.body, {}, {}, abi::kLeft}};
    return body_reason(body, scopes);
  }

  static std::vector<bool> writable_params(const Code& params) {
    std::vector<bool> writable;
    for (const auto& [begin, end] : split_top_level(params, 0, params.size())) {
      bool is_const = false, indirect = false;
      for (std::size_t j = begin; j < end && !params[j].is_punct("="); ++j) {
        if (params[j].is_ident("const")) is_const = true;
        if (params[j].is_punct("&") || params[j].is_punct("*") || params[j].is_punct("&&")) indirect = true;
      }
      writable.push_back(indirect && !is_const);
    }
    return writable;
  }

  // Why the arguments of a call of the model's function `name`, between the
  // parentheses at `open`, hand it something not the caller's own to write.
  std::string arguments_reason(const std::string& name, const Code& code, std::size_t open, const Scopes& scopes,
                               const Pending& pending) {
    const auto d = definitions_.find(name);
    if (d == definitions_.end()) return "";
    const auto args = split_top_level(code, open + 1, matching_forward(code, open));
    for (std::size_t i = 0; i < args.size(); ++i) {
      bool writable = false;
      for (const Definition& def : d->second) writable |= i < def.writable.size() && def.writable[i];
      if (!writable) continue;
      auto [begin, end] = args[i];
      if (code[begin].is_punct("&")) ++begin;
      std::size_t k = begin + 1;
      while (k < end && (code[k].is_punct(".") || code[k].is_ident() || code[k].is_punct("[")))
        k = code[k].is_punct("[") ? matching_forward(code, k) + 1 : k + 1;
      if (begin >= end || !code[begin].is_ident() || k != end || !owned(scopes, pending, code[begin].text))
        return "passes `" + name + "` something not its own to write";
    }
    return "";
  }

  // Why calling `name` (as written, with its qualification) is unsafe, or empty.
  std::string call_reason(const std::string& qualifier, const std::string& name) {
    if (qualifier.empty() || qualifier == "::") {
      if (auto d = definitions_.find(name); d != definitions_.end()) {
        if (auto known = verdicts_.find(name); known != verdicts_.end()) {
          draws_ |= known->second.draws;
          return known->second.reason;
        }
        verdicts_[name] = {};  // a recursive call is judged by the rest of the function
        const bool drew = std::exchange(draws_, false);
        std::string why;
        for (const Definition& def : d->second)
          if (why = function_reason(def); !why.empty()) break;
        if (!why.empty()) why = "calls `" + name + "`, which " + why;
        verdicts_[name] = {why, draws_};
        draws_ |= drew;
        return why;
      }
      if (name == "ran") {
        draws_ = true;  // safe where ran() is keyed by the module (RuleSafety::draws_random)
        return "";
      }
      if (kPureFunctions.count(name) || types_.count(name)) return "";
    } else if (kPureNamespaces.count(qualifier) && kPureFunctions.count(name)) {
      return "";
    }
    return "calls `" + qualifier + name + "`, which is not known to be pure";
  }

  // Whether `name` is the body's own variable: `pending` holds those
  // declared in the parentheses before a block or statement.
  static bool owned(const Scopes& scopes, const Pending& pending, const std::string& name) {
    if (auto it = pending.find(name); it != pending.end()) return it->second;
    for (std::size_t s = scopes.size(); s-- > 0;)
      if (auto it = scopes[s].find(name); it != scopes[s].end()) return it->second;
    return false;
  }

  // The variable an lvalue ending at `end` belongs to (a.b[i].c: a), or
  // nullopt for one the analysis does not follow (*p, p->x, f().x, ::g).
  static std::optional<std::string> root_before(const Code& code, std::size_t end) {
    std::size_t k = end;
    for (;;) {
      if (code[k].is_punct("]")) {
        auto open = matching_backward(code, k, "[", "]");
        if (!open || *open == 0) return std::nullopt;
        k = *open - 1;
        continue;
      }
      if (!code[k].is_ident()) return std::nullopt;
      if (k >= 2 && code[k - 1].is_punct(".")) {
        k -= 2;
        continue;
      }
      if (k >= 1 && (code[k - 1].is_punct("::") || code[k - 1].is_punct("->") || code[k - 1].is_punct("*")) &&
          !(k >= 2 && code[k - 1].is_punct("*") && is_operand_end(code[k - 2])))
        return std::nullopt;
      return code[k].text;
    }
  }
  static std::optional<std::string> root_after(const Code& code, std::size_t begin) {
    if (begin >= code.size() || !code[begin].is_ident()) return std::nullopt;
    for (std::size_t k = begin + 1; k < code.size(); ++k) {
      if (code[k].is_punct("->")) return std::nullopt;
      if (code[k].is_punct(".") || code[k].is_ident()) continue;
      if (code[k].is_punct("[")) {
        k = matching_forward(code, k);
        continue;
      }
      break;
    }
    return code[begin].text;
  }

  // Why the tokens of `code` are unsafe, or empty. `scopes` and `pending`
  // carry the body's variables from one part of a body to the next.
  std::string code_reason(const Code& written, Scopes& scopes, Pending& pending) {
    const Code code = split_tokens(written);
    auto where = [&](std::size_t k) { return code[k].line > 0 ? " (line " + std::to_string(code[k].line) + ")" : ""; };
    auto starts_expression = [](const Token& t) { return t.is_ident() && !kExpressionWords.count(t.text); };
    std::size_t declared_at = code.size();  // the name just declared, whose `=` initializes
    int nesting = 0;             // brackets open
    int declaration_nesting = -1;  // where a declaration goes on after a comma; -1: none
    for (std::size_t k = 0; k < code.size(); ++k) {
      const Token& t = code[k];
      const Token* prev = k > 0 ? &code[k - 1] : nullptr;
      const Token* next = k + 1 < code.size() ? &code[k + 1] : nullptr;
      if (t.is_punct("(") || t.is_punct("[") || t.is_punct("{")) ++nesting;
      if ((t.is_punct(")") || t.is_punct("]") || t.is_punct("}")) && --nesting < declaration_nesting)
        declaration_nesting = -1;
      if (t.is_punct(";")) declaration_nesting = -1;
      if (t.is_ident()) {
        if (auto bad = kUnsafeWords.find(t.text); bad != kUnsafeWords.end()) return bad->second + where(k);
        // A declared name follows a type (an identifier that starts no
        // expression), or a comma in a declaration (T a = 1, b;); `T& x`
        // and `T* x` declare names that are not the body's own.
        const bool after_comma = declaration_nesting == nesting && prev && prev->is_punct(",");
        const bool after_type = (prev && starts_expression(*prev)) || after_comma;
        if (after_type || (prev && (prev->is_punct("&") || prev->is_punct("*")) && k >= 2 &&
                           ((starts_expression(code[k - 2]) && starts_statement(code, k - 2)) ||
                            (declaration_nesting == nesting && code[k - 2].is_punct(","))))) {
          (paren_depth(code, k) > 0 ? pending : scopes.back())[t.text] = after_type;
          declared_at = k;
          declaration_nesting = nesting;
        }
        if (!next || !next->is_punct("(") || kNotCalls.count(t.text) || after_type) continue;
        if (prev && prev->is_punct("->")) return "calls `" + t.text + "` through a pointer" + where(k);
        if (prev && prev->is_punct(".")) {
          if (definitions_.count(t.text)) {
            if (std::string why = call_reason("", t.text); !why.empty()) return why + where(k);
            if (std::string why = arguments_reason(t.text, code, k + 1, scopes, pending); !why.empty())
              return why + where(k);
            continue;
          }
          if (kReadingMethods.count(t.text)) continue;
          auto root = k >= 2 ? root_before(code, k - 2) : std::nullopt;
          if (kChangingMethods.count(t.text) && root && owned(scopes, pending, *root)) continue;
          return "calls `" + t.text + "` on something not its own" + where(k);
        }
        std::string qualifier;
        std::size_t first = k;
        for (; first >= 2 && code[first - 1].is_punct("::") && code[first - 2].is_ident(); first -= 2)
          qualifier = code[first - 2].text + "::" + qualifier;
        if (first >= 1 && code[first - 1].is_punct("::")) qualifier = "::" + qualifier;
        if (std::string why = call_reason(qualifier, t.text); !why.empty()) return why + where(k);
        if (qualifier.empty())
          if (std::string why = arguments_reason(t.text, code, k + 1, scopes, pending); !why.empty())
            return why + where(k);
        continue;
      }
      if (t.kind == TokenKind::Verbatim) return "holds code the analysis does not read" + where(k);
      if (t.kind != TokenKind::Punct) continue;
      if (t.text == "{") {
        scopes.push_back(std::move(pending));
        pending.clear();
      } else if (t.text == "}") {
        if (scopes.size() > 1) scopes.pop_back();
      } else if (t.text == ";" && !pending.empty() && paren_depth(code, k) == 0) {
        pending.clear();
      } else if (t.text == "(" && prev && !prev->is_ident()) {
        if (std::string why = indirect_call_reason(code, k); !why.empty()) return why + where(k);
      } else if (is_assignment(t)) {
        if (declared_at + 1 == k || (t.text == "=" && prev && prev->is_punct("["))) continue;  // T x = ...; [=]
        auto root = k > 0 ? root_before(code, k - 1) : std::nullopt;
        if (!root) return "assigns through an expression it cannot follow" + where(k);
        if (!owned(scopes, pending, *root)) return "assigns `" + *root + "`, which is not its own" + where(k);
      } else if (t.text == "++" || t.text == "--") {
        const bool postfix = prev && is_operand_end(*prev);
        auto root = postfix ? root_before(code, k - 1) : root_after(code, k + 1);
        if (!root) return "changes something through an expression it cannot follow" + where(k);
        if (!owned(scopes, pending, *root)) return "changes `" + *root + "`, which is not its own" + where(k);
      } else if (t.text == "&" && !(prev && is_operand_end(*prev))) {
        if ((prev && prev->is_punct("[")) || (next && next->is_punct("]"))) continue;  // a lambda's [&]
        auto root = root_after(code, k + 1);
        if (!root || !owned(scopes, pending, *root))
          return "takes the address of something not its own" + where(k);
      }
    }
    return "";
  }

  // A `(` after something other than a name: f<T>(...) calls f, (T)(x)
  // casts, [](...) begins a lambda; (*p)(...) and a[i](...) call what the
  // analysis cannot name. `>` not closing a template's arguments compares.
  std::string indirect_call_reason(const Code& code, std::size_t k) {
    const Token& prev = code[k - 1];
    if (prev.is_punct(">")) {
      auto open = matching_backward(code, k - 1, "<", ">");
      if (!open || *open == 0 || !code[*open - 1].is_ident()) return "";
      for (std::size_t j = *open + 1; j + 1 < k; ++j)
        if (!(code[j].is_ident() || code[j].kind == TokenKind::Number || code[j].is_punct("::") ||
              code[j].is_punct(",") || code[j].is_punct("*") || code[j].is_punct("&") || code[j].is_punct("<") ||
              code[j].is_punct(">")))
          return "";
      const std::string& name = code[*open - 1].text;
      if (name == "static_cast" || name == "dynamic_cast") return "";
      return call_reason("", name);
    }
    if (prev.is_punct(")")) {
      auto open = matching_backward(code, k - 1, "(", ")");
      if (open && *open > 0 && code[*open - 1].is_ident() && kNotCalls.count(code[*open - 1].text)) return "";
      if (open && *open + 2 == k - 1 && code[*open + 1].is_ident() &&
          (kPureFunctions.count(code[*open + 1].text) || types_.count(code[*open + 1].text)))
        return "";  // (float)(x)
      return "calls a function through an expression";
    }
    if (prev.is_punct("]")) {
      auto open = matching_backward(code, k - 1, "[", "]");
      if (open && (*open == 0 || !is_operand_end(code[*open - 1]))) return "";  // a lambda
      return "calls a function through an expression";
    }
    return "";
  }

  // Whether the type name at `k` may begin a declaration (T* x), rather
  // than end an operand (a * x).
  static bool starts_statement(const Code& code, std::size_t k) {
    if (k == 0) return true;
    const Token& before = code[k - 1];
    static const Names punctuation = {";", "{", "}", "(", ")", ",", "::", ">"};
    static const Names words = {"const", "volatile", "constexpr", "unsigned", "signed", "struct", "class"};
    return (before.kind == TokenKind::Punct && punctuation.count(before.text)) ||
           (before.is_ident() && words.count(before.text));
  }

  static int paren_depth(const Code& code, std::size_t k) {
    int depth = 0;
    for (std::size_t j = k; j-- > 0;) {
      if (code[j].is_punct("{") || code[j].is_punct("}")) break;
      if (code[j].is_punct(")")) --depth;
      if (code[j].is_punct("(")) ++depth;
    }
    return depth > 0 ? depth : 0;
  }

  std::string body_reason(const Body& body, Scopes& scopes) {
    Pending pending;
    for (const BodyPart& part : body) {
      std::string why;
      switch (part.kind) {
        case BodyPart::kCode:
        case BodyPart::kPropensity:
        case BodyPart::kRate:
          why = code_reason(part.code, scopes, pending);
          break;
        case BodyPart::kProduce:
        case BodyPart::kNProduce:
          for (const ModuleCall& m : part.modules)
            for (const Code& arg : m.args)
              if (why = code_reason(arg, scopes, pending); !why.empty()) break;
          break;
        case BodyPart::kInContext:
          if (part.context == abi::kNewLeft || part.context == abi::kNewRight)
            return "reads the new string as context (line " + std::to_string(part.at.line) + ")";
          // Each argument receives a parameter: it must be the body's own.
          for (const ModuleCall& m : part.modules)
            for (const Code& arg : m.args)
              if (arg.size() != 1 || !arg[0].is_ident() || !owned(scopes, pending, arg[0].text))
                return "copies context into something not its own (line " + std::to_string(part.at.line) + ")";
          break;
      }
      if (!why.empty()) return why;
    }
    return "";
  }

  Names types_;
  std::map<std::string, std::vector<Definition>, std::less<>> definitions_;
  struct Verdict {
    std::string reason;
    bool draws = false;
  };
  std::map<std::string, Verdict, std::less<>> verdicts_;
  bool draws_ = false;  // the body analysed calls ran()
  std::string model_reason_;
};

}  // namespace

std::vector<RuleSafety> rule_safety(const Model& model) {
  Analysis analysis(model);
  std::vector<RuleSafety> verdicts;
  for (const Item& item : model.items)
    if (const Rule* rule = std::get_if<Rule>(&item)) verdicts.push_back(analysis.rule_safety(*rule));
  return verdicts;
}

}  // namespace sylva::lang
