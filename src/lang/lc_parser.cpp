// The file-scope half of the L+C parser: the main loop over the token stream,
// module declarations, settings, ignore/consider, VerifyString, the axiom,
// control statements, groups and struct reading, and the entry point
// parse_lc(). Rules and their bodies are parsed in lc_rule_parser.cpp.
#include "lang/lc_parser.h"

#include <algorithm>
#include <climits>
#include <string>
#include <utility>
#include <vector>

#include "lang/lc_parser_impl.h"
#include "lang/literal_numbers.h"

namespace sylva::lang {
namespace detail {

LcParser::LcParser(const TokenStream& stream, const std::string& main_file) : stream_(stream), t_(stream.tokens) {
  model_.files = stream.files;
  model_.main_file = main_file;
  for (const ModuleDecl& m : predefined_modules()) declare(m);
}

Model LcParser::parse() {
  int depth = 0;
  bool statement_start = true;
  while (peek().kind != TokenKind::End) {
    const Token& tok = peek();
    if (tok.kind == TokenKind::Verbatim) {
      code_.push_back(tok);
      ++i_;
      continue;
    }
    if (depth == 0 && statement_start && parse_construct()) {
      statement_start = true;
      continue;
    }
    if (depth == 0 && statement_start && is_struct_definition()) {
      parse_struct();
      statement_start = true;
      continue;
    }
    if (depth == 0 && (tok.is_ident("produce") || tok.is_ident("nproduce")))
      fail(tok, "'" + tok.text + "' outside a production body");
    if (in_context_test_ahead()) fail(tok, in_context_misplaced(tok));
    if (is_open(tok)) ++depth;
    if (is_close(tok)) --depth;
    if (depth < 0) fail(tok, "unmatched '" + tok.text + "'");
    statement_start = depth == 0 && (tok.is_punct(";") || tok.is_punct("}"));
    code_.push_back(tok);
    ++i_;
  }
  flush_code();
  return std::move(model_);
}

// ---- L+C constructs at file scope ------------------------------------------
bool LcParser::parse_construct() {
  const Token& tok = peek();
  if (!tok.is_ident()) return false;
  const std::string& w = tok.text;
  if (w == "module" && peek(1).is_ident()) return parse_module_decl(), true;
  if (w == "derivation" && peek(1).is_ident("length") && followed_by_colon(2))
    return parse_setting(Setting::kDerivationLength, 3), true;
  if ((w == "axiom" || w == "Axiom") && followed_by_colon(1)) return parse_axiom(), true;
  if ((w == "ignore" || w == "consider") && followed_by_colon(1)) return parse_filter(), true;
  if (followed_by_colon(1) && !peek(2).is_punct(":")) {
    if (w == "production" || w == "productions") return switch_block(RuleKind::Production), true;
    if (w == "decomposition") return switch_block(RuleKind::Decomposition), true;
    if (w == "interpretation" || w == "homomorphism") return switch_block(RuleKind::Interpretation), true;
    if (w == "derivatives") return switch_block(RuleKind::Derivative), true;
    if (w == "events") return switch_block(RuleKind::Event), true;
  }
  if (w == "maximum" && peek(1).is_ident("depth") && followed_by_colon(2)) {
    if (block_ != RuleKind::Decomposition && block_ != RuleKind::Interpretation)
      fail(tok, "'maximum depth:' belongs in a decomposition: or interpretation: block");
    return parse_setting(block_ == RuleKind::Decomposition ? Setting::kDecompositionDepth
                                                           : Setting::kInterpretationDepth,
                         3),
           true;
  }
  if (w == "ring" && peek(1).is_ident("L") && peek(2).is_punct("-") && peek(3).is_ident("system") &&
      followed_by_colon(4))
    return parse_setting(Setting::kRing, 5), true;
  if (w == "group" && peek(1).kind == TokenKind::Number && followed_by_colon(2)) return open_group(false), true;
  if (w == "endgroup") {
    flush_code();
    ++i_;
    if (peek().is_punct(";")) ++i_;
    group_ = 0;
    gillespie_ = false;
    view_ = 0;
    return true;
  }
  if (w == "vgroup" && peek(1).kind == TokenKind::Number && followed_by_colon(2)) {
    // Interpretation rules of one view (7.3); the view names of the view
    // file's window: commands are defined as numbers.
    flush_code();
    view_ = whole_number(peek(1), "a view");
    i_ += 3;
    return true;
  }
  if (w == "vgroup") fail(peek(1), "expected a view (a number, or a name from a window: command of the view file) and ':' after 'vgroup'");
  if (w == "VerifyString" && followed_by_colon(1)) return parse_verify_string(), true;
  if (w == "ggroup" && peek(1).kind == TokenKind::Number) {
    if (!followed_by_colon(2)) fail(peek(2), "expected ':' after 'ggroup " + peek(1).text + "'");
    return open_group(true), true;
  }
  if (w == "ggroup" && followed_by_colon(2))
    fail(peek(1), "expected a group number after 'ggroup', found " + describe(peek(1)));
  if (followed_by_colon(1) && peek(2).is_punct("{")) {
    if (w == "Start") return parse_control(ControlStatement::kStart), true;
    if (w == "StartEach") return parse_control(ControlStatement::kStartEach), true;
    if (w == "EndEach") return parse_control(ControlStatement::kEndEach), true;
    if (w == "End") return parse_control(ControlStatement::kEnd), true;
  }
  if (find_module(w)) return parse_rule(), true;
  if (looks_like_rule()) require_module(tok);  // reports the undeclared module
  return false;
}

// `group N:` or `ggroup N:`; both kinds share one numbering (LPFG manual 7.2).
void LcParser::open_group(bool gillespie) {
  flush_code();
  const Token& number = peek(1);
  const int group = whole_number(number, "a group");
  const std::string name = std::to_string(group);
  if (gillespie && group == 0) fail(number, "group 0 is the main group and cannot be a Gillespie group");
  auto holds = [group](const std::vector<int>& list) {
    return std::find(list.begin(), list.end(), group) != list.end();
  };
  // model_.groups holds both kinds; a number is of one kind only.
  const bool known = holds(model_.groups), known_gillespie = holds(model_.gillespie_groups);
  if (gillespie && known && !known_gillespie)
    fail(number, "group " + name + " is already a regular group ('group " + name +
                     ":'); a Gillespie group needs a number of its own");
  if (!gillespie && known_gillespie)
    fail(number, "group " + name + " is already a Gillespie group ('ggroup " + name +
                     ":'); a regular group needs a number of its own");
  if (gillespie && !known_gillespie) model_.gillespie_groups.push_back(group);
  if (!known) model_.groups.push_back(group);
  group_ = group;
  gillespie_ = gillespie;
  i_ += 3;
}

// `Name(...) ... : {` with only pattern tokens before the colon: a rule whose
// first module was never declared.
bool LcParser::looks_like_rule() const {
  int parens = 0;
  for (std::size_t k = 0;; ++k) {
    const Token& t = peek(k);
    if (t.kind == TokenKind::End || t.kind == TokenKind::Verbatim) return false;
    if (t.is_punct("(")) ++parens;
    else if (t.is_punct(")")) --parens;
    else if (parens == 0 && t.is_punct(":")) return k > 0 && peek(k + 1).is_punct("{");
    else if (!(t.is_ident() || t.is_punct(",") || t.is_punct("<") || t.is_punct(">") ||
               t.is_punct("<<") || t.is_punct(">>")))
      return false;
  }
}

void LcParser::parse_module_decl() {
  flush_code();
  next();  // module
  const Token& name = expect_identifier("a module name");
  if (const ModuleDecl* existing = find_module(name.text)) {
    if (existing->at.kind == TokenKind::End) fail(name, "'" + name.text + "' is a predefined module and cannot be redeclared");
    fail(name, "module '" + name.text + "' is already declared");
  }
  ModuleDecl decl{name.text, {}, name, {}};
  if (peek().is_punct("(")) {
    next();
    while (!peek().is_punct(")")) {
      // A parameter type is one identifier (LPFG manual 2.3.2); a name after it is not allowed.
      std::string type;
      while (!peek().is_punct(",") && !peek().is_punct(")")) {
        const Token& part = next();
        if (part.kind == TokenKind::End || part.is_punct(";"))
          fail(part, "expected ')' to close the parameter list of module '" + name.text + "'");
        if (!type.empty()) type += ' ';
        type += part.text;
      }
      if (type.empty()) fail(peek(), "expected a parameter type");
      decl.param_types.push_back(type);
      if (peek().is_punct(",")) next();
    }
    next();  // )
  }
  expect_punct(";", "';' after the declaration of module '" + name.text + "'");
  if (model_.modules.size() >= 0xFFFF) fail(name, "too many modules");
  declare(decl);
  model_.items.emplace_back(decl);
}

Code LcParser::parse_expression_until_semicolon(const std::string& what) {
  Code expr;
  int depth = 0;
  while (depth > 0 || !peek().is_punct(";")) {
    const Token& tok = peek();
    if (tok.kind == TokenKind::End || tok.kind == TokenKind::Verbatim)
      fail(tok, "expected ';' after " + what);
    if (is_open(tok)) ++depth;
    if (is_close(tok)) --depth;
    expr.push_back(next());
  }
  if (expr.empty()) fail(peek(), "expected an expression after '" + what + ":'");
  next();  // ;
  return expr;
}

int LcParser::whole_number(const Token& number, const std::string& what) const {
  const std::optional<int> value = nonnegative_int(number.text);
  if (!value)
    fail(number, "expected " + what + " number from 0 to " + std::to_string(INT_MAX) + ", found " + number.text);
  return *value;
}

void LcParser::parse_setting(Setting::Kind kind, int keyword_tokens) {
  flush_code();
  Token at = peek();
  i_ += keyword_tokens;
  Code expr = parse_expression_until_semicolon(at.text);
  std::string text;
  for (const Token& t : expr) text += (t.space_before && !text.empty() ? " " : "") + t.text;
  if (const std::string error = setting_range_error(kind, text); !error.empty()) fail(expr.front(), error);
  model_.items.emplace_back(Setting{kind, std::move(expr), at});
}

void LcParser::switch_block(RuleKind kind) {
  flush_code();
  i_ += 2;
  block_ = kind;
}

void LcParser::parse_filter() {
  flush_code();
  const Token& keyword = next();
  next();  // :
  ContextFilter filter{keyword.text == "consider", {}, keyword};
  while (!peek().is_punct(";")) {
    const Token& name = peek();
    if (!name.is_ident()) fail(name, "expected a module name or ';' in '" + keyword.text + ":', found " + describe(name));
    require_module(name);
    filter.names.push_back(next().text);
  }
  next();  // ;
  if (filter.names.empty()) {
    filter_ = -1;
  } else {
    filter_ = static_cast<int>(model_.filters.size());
    model_.filters.push_back(std::move(filter));
  }
}

// VerifyString: A B [ C ]; (LPFG manual 10.4): module names; parameters
// may be written but are not compared.
// A second statement is an error: two would otherwise join into one
// expected string that neither of them states.
void LcParser::parse_verify_string() {
  flush_code();
  const Token& keyword = next();  // VerifyString
  if (model_.has_verify_string) {
    const SourceLocation& first = first_verify_string_;
    const SourceLocation here = stream_.location(keyword);
    fail(keyword, "only one VerifyString: per model; the first is at " +
                      (first.file == here.file ? std::string() : first.file + ":") + "line " +
                      std::to_string(first.line));
  }
  first_verify_string_ = stream_.location(keyword);
  next();  // :
  model_.has_verify_string = true;
  while (!peek().is_punct(";")) {
    const Token& tok = peek();
    if (tok.is_punct("[") || tok.is_punct("]")) {
      model_.verify_string.push_back(tok.is_punct("[") ? "SB" : "EB");
      next();
      continue;
    }
    if (!tok.is_ident()) fail(tok, "expected a module name or ';' in 'VerifyString:', found " + describe(tok));
    model_.verify_string.push_back(require_module(tok).name);
    next();
    if (peek().is_punct("(")) {
      next();
      parse_arguments();
    }
  }
  next();  // ;
}

void LcParser::parse_axiom() {
  flush_code();
  Axiom axiom;
  axiom.at = next();
  next();  // :
  axiom.modules = parse_module_calls("the axiom");
  model_.items.emplace_back(std::move(axiom));
}

void LcParser::parse_control(ControlStatement::Kind kind) {
  flush_code();
  ControlStatement statement{kind, {}, next()};
  next();  // :
  statement.body = parse_body(false);
  if (peek().is_punct(";")) next();
  model_.items.emplace_back(std::move(statement));
}

// ---- structs (so their parameters print field by field) ---------------------
bool LcParser::is_struct_definition() const {
  std::size_t k = 0;
  if (peek(k).is_ident("typedef")) ++k;
  if (!peek(k).is_ident("struct")) return false;
  ++k;
  if (peek(k).is_ident()) ++k;
  return peek(k).is_punct("{");
}

void LcParser::parse_struct() {
  Token at = peek();
  bool is_typedef = peek().is_ident("typedef");
  std::string name;
  while (!peek().is_punct("{")) {
    if (peek().is_ident() && !peek().is_ident("struct") && !peek().is_ident("typedef")) name = peek().text;
    code_.push_back(next());
  }
  // Members at depth 1, split at ';'.
  std::vector<std::string> fields;
  bool printable = true;
  Code member;
  int depth = 0;
  while (true) {
    const Token& tok = next();
    if (tok.kind == TokenKind::End) fail(at, "expected '}' to end the struct");
    code_.push_back(tok);
    int before = depth;
    if (is_open(tok)) ++depth;
    if (is_close(tok)) --depth;
    if (before == 0) continue;  // the struct's own '{'
    if (depth == 0) break;      // and its '}'
    if (before == 1 && tok.is_punct(";")) {
      add_fields(member, fields);
      member.clear();
    } else if (before == 1 && tok.is_punct(":") && member.size() == 1 &&
               (member[0].is_ident("private") || member[0].is_ident("protected") ||
                member[0].is_ident("public"))) {
      if (!member[0].is_ident("public")) printable = false;
      member.clear();
    } else if (before == 2 && depth == 1 && tok.is_punct("}")) {
      member.clear();  // the end of an inline method body
    } else {
      member.push_back(tok);
    }
  }
  if (is_typedef && peek().is_ident()) name = peek().text;
  // Copy the rest of the declaration up to ';'.
  while (!peek().is_punct(";") && peek().kind != TokenKind::End) code_.push_back(next());
  if (peek().is_punct(";")) code_.push_back(next());
  if (printable && !name.empty() && !fields.empty()) {
    flush_code();
    model_.items.emplace_back(StructFields{name, std::move(fields), at});
  }
}

// One member declaration `type a, b[3] = {...}`: adds the field names.
void LcParser::add_fields(const Code& member, std::vector<std::string>& fields) {
  if (member.empty()) return;
  const std::string& first = member[0].text;
  if (first == "static" || first == "typedef" || first == "using" || first == "enum" || first == "struct" ||
      first == "friend" || first == "template" || first == "class" || first == "union")
    return;
  for (const Token& t : member)
    if (t.is_punct("(")) return;  // a method or constructor
  std::string last_name;
  int depth = 0;
  bool in_initializer = false;
  for (const Token& t : member) {
    if (is_open(t)) ++depth;
    if (is_close(t)) --depth;
    if (depth > 0) continue;
    if (t.is_punct("=") || t.is_punct(":")) in_initializer = true;
    if (t.is_punct(",")) {
      if (!last_name.empty()) fields.push_back(last_name);
      last_name.clear();
      in_initializer = false;
      continue;
    }
    if (!in_initializer && t.is_ident()) last_name = t.text;
  }
  if (!last_name.empty()) fields.push_back(last_name);
}

}  // namespace detail

Model parse_lc(const TokenStream& tokens, const std::string& main_file) {
  return detail::LcParser(tokens, main_file).parse();
}

}  // namespace sylva::lang
