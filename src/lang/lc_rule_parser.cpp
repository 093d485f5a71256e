// The rule half of the L+C parser: rules and their predecessors, bodies
// (produce, nproduce and propensity statements, in-body context tests), and
// the module lists and argument lists that bodies and the axiom contain.
#include <cstddef>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "lang/lc_parser_impl.h"

namespace sylva::lang::detail {

// ---- rules ------------------------------------------------------------------
void LcParser::parse_rule() {
  flush_code();
  Rule rule;
  rule.kind = block_;
  rule.group = group_;
  rule.view = view_;
  rule.filter = filter_;
  rule.at = peek();

  // Segments of modules separated by context operators, up to ':'.
  std::vector<std::vector<PatternModule>> segments(1);
  std::vector<Token> operators;
  while (!peek().is_punct(":")) {
    const Token& tok = peek();
    if (tok.is_punct("<") || tok.is_punct(">") || tok.is_punct("<<") || tok.is_punct(">>")) {
      if (segments.back().empty()) fail(tok, "expected a module before " + describe(tok));
      operators.push_back(next());
      segments.emplace_back();
      continue;
    }
    segments.back().push_back(parse_pattern_module());
  }
  if (segments.back().empty()) fail(peek(), "expected a module before ':'");
  next();  // :
  if (block_ == RuleKind::Event) rule.event_condition = parse_event_condition();

  const bool gillespie = gillespie_ && block_ == RuleKind::Production;
  for (const Token& op : operators)
    if (gillespie && (op.text == "<<" || op.text == ">>"))
      fail(op, "new context " + describe(op) + " cannot be used in a Gillespie group (LPFG manual 7.2)");
  std::size_t strict = 0;
  while (strict < operators.size() && (operators[strict].text == "<" || operators[strict].text == "<<")) ++strict;
  auto assign = [&](abi::PatternPart part, std::size_t segment, const Token& op) {
    if (!rule.parts[part].empty()) fail(op, "the predecessor has two " + describe(op) + " contexts");
    rule.parts[part] = std::move(segments[segment]);
  };
  for (std::size_t k = 0; k < operators.size(); ++k) {
    const Token& op = operators[k];
    if (k < strict) {
      assign(op.text == "<<" ? abi::kNewLeft : abi::kLeft, k, op);
    } else if (op.text == "<" || op.text == "<<") {
      fail(op, "left context " + describe(op) + " must come before the strict predecessor");
    } else {
      assign(op.text == ">>" ? abi::kNewRight : abi::kRight, k + 1, op);
    }
  }
  rule.parts[abi::kStrict] = std::move(segments[strict]);

  std::unordered_set<std::string> bound;
  for (const auto& part : rule.parts)
    for (const PatternModule& m : part)
      for (std::size_t f = 0; f < m.formals.size(); ++f)
        if (!bound.insert(m.formals[f]).second)
          fail(m.at, "parameter name '" + m.formals[f] + "' is bound twice in the predecessor");

  in_derivative_rule_ = block_ == RuleKind::Derivative;
  rule.body = parse_body(!in_derivative_rule_, gillespie);
  in_derivative_rule_ = false;
  if (peek().is_punct(";")) next();
  if (block_ == RuleKind::Derivative) resolve_rates(rule);
  if (block_ == RuleKind::Event) warn_of_equality(rule);
  model_.items.emplace_back(std::move(rule));
}

PatternModule LcParser::parse_pattern_module() {
  const Token& tok = peek();
  PatternModule m;
  m.at = tok;
  if (tok.is_punct("[") || tok.is_punct("]")) {
    m.name = tok.is_punct("[") ? "SB" : "EB";
    next();
    return m;
  }
  if (!tok.is_ident()) fail(tok, "expected a module in the predecessor, found " + describe(tok));
  const ModuleDecl& decl = require_module(tok);
  m.name = next().text;
  if (peek().is_punct("(")) {
    next();
    while (!peek().is_punct(")")) {
      m.formals.push_back(expect_identifier("a parameter name in the predecessor").text);
      if (peek().is_punct(",")) next();
      else if (!peek().is_punct(")")) fail(peek(), "expected ',' or ')' in the predecessor, found " + describe(peek()));
    }
    next();
  }
  if (m.formals.size() != decl.param_types.size())
    fail(m.at, arity_message(decl, m.formals.size(), "the predecessor names"));
  return m;
}

// ---- module lists (axiom, produce) ------------------------------------------
// Reads `A(x, y) B C(z)` up to and including the ';'.
std::vector<ModuleCall> LcParser::parse_module_calls(const std::string& where) {
  std::vector<ModuleCall> calls;
  // `produce(A B);` — lpfg accepts the list in parentheses too.
  bool parenthesized = peek().is_punct("(");
  if (parenthesized) next();
  while (true) {
    const Token& tok = peek();
    if (parenthesized && tok.is_punct(")")) {
      next();
      parenthesized = false;
      continue;
    }
    if (tok.is_punct(";") && !parenthesized) break;
    // lpfg accepts a produce statement that runs into the closing brace.
    if (tok.is_punct("}") && !parenthesized && !calls.empty()) return calls;
    calls.push_back(parse_module_call("a module in " + where, "is given"));
  }
  next();  // ;
  return calls;
}

// One module of a list: `[`, `]`, or a declared module with its arguments.
ModuleCall LcParser::parse_module_call(const std::string& expected, const char* arity_verb) {
  const Token& tok = peek();
  ModuleCall call;
  call.at = tok;
  if (tok.is_punct("[") || tok.is_punct("]")) {
    call.name = tok.is_punct("[") ? "SB" : "EB";
    next();
    return call;
  }
  if (!tok.is_ident()) fail(tok, "expected " + expected + ", found " + describe(tok));
  const ModuleDecl& decl = require_module(tok);
  call.name = next().text;
  if (peek().is_punct("(")) {
    next();
    call.args = parse_arguments();
  }
  if (call.args.size() != decl.param_types.size()) fail(call.at, arity_message(decl, call.args.size(), arity_verb));
  return call;
}

std::string LcParser::arity_message(const ModuleDecl& decl, std::size_t given, const char* verb) {
  return "module '" + decl.name + "' has " + std::to_string(decl.param_types.size()) + " parameter" +
         (decl.param_types.size() == 1 ? "" : "s") + " but " + verb + " " + std::to_string(given);
}

// After '(': arguments split at top-level commas, up to and including ')'.
std::vector<Code> LcParser::parse_arguments() {
  std::vector<Code> args;
  Code current;
  int depth = 0;
  while (true) {
    const Token& tok = peek();
    if (tok.kind == TokenKind::End || tok.kind == TokenKind::Verbatim || (depth == 0 && tok.is_punct(";")))
      fail(tok, "expected ')' to close the parameters, found " + describe(tok));
    if (depth == 0 && (tok.is_punct(",") || tok.is_punct(")"))) {
      bool closing = tok.is_punct(")");
      if (current.empty() && !(closing && args.empty())) fail(tok, "expected a parameter value before " + describe(tok));
      if (!current.empty()) args.push_back(std::move(current));
      current.clear();
      next();
      if (closing) return args;
      continue;
    }
    if (is_open(tok)) ++depth;
    if (is_close(tok)) --depth;
    current.push_back(next());
  }
}

// ---- bodies -----------------------------------------------------------------
// From '{' to its matching '}', cutting produce statements out.
// `gillespie`: a production of a Gillespie group, whose body offers
// reactions (`propensity p produce ...;`) instead of producing.
Body LcParser::parse_body(bool produce_allowed, bool gillespie) {
  Body body;
  BodyPart code;
  code.kind = BodyPart::kCode;
  // lpfg's translator turns a produce statement into a block of its own, so
  // one may stand for the whole body: "A(t) : produce A(t+dt);".
  if (peek().is_ident("produce") && produce_allowed && !gillespie) {
    BodyPart produce;
    produce.kind = BodyPart::kProduce;
    produce.at = next();
    produce.modules = parse_module_calls("a produce statement");
    body.push_back(std::move(produce));
    return body;
  }
  if (!peek().is_punct("{")) fail(peek(), "expected '{' or a produce statement to begin the body, found " + describe(peek()));
  const Token& opening = peek();
  int depth = 0;
  do {
    const Token& tok = peek();
    if (tok.kind == TokenKind::End)
      fail(opening, "expected '}' to end the body that begins here, found end of file");
    if (tok.is_ident("propensity") && (gillespie || propensity_statement_ahead())) {
      if (!gillespie) fail(tok, "'propensity' is only allowed in the productions of a Gillespie group ('ggroup N:')");
      if (!code.code.empty()) body.push_back(std::move(code));
      code = BodyPart{};
      body.push_back(parse_propensity());
      continue;
    }
    if (in_context_test_ahead()) {
      if (!produce_allowed) fail(tok, in_context_misplaced(tok));
      if (!code.code.empty()) body.push_back(std::move(code));
      code = BodyPart{};
      body.push_back(parse_in_context());
      continue;
    }
    if (in_derivative_rule_ && rate_statement_ahead()) {
      if (!code.code.empty()) body.push_back(std::move(code));
      code = BodyPart{};
      body.push_back(parse_rate());
      continue;
    }
    if (tok.is_ident("produce") || tok.is_ident("nproduce")) {
      if (in_derivative_rule_)
        fail(tok, "a derivative rule gives rates ('d(x) = ...;'), not a successor: productions at an instant "
                  "belong in an events: block");
      if (!produce_allowed) fail(tok, "'" + tok.text + "' is only allowed in a production or rule body");
      if (gillespie && tok.is_ident("produce"))
        fail(tok, "a production of a Gillespie group produces through its reactions: write "
                  "'propensity <expression> produce ...;'");
      if (!code.code.empty()) body.push_back(std::move(code));
      code = BodyPart{};
      BodyPart produce;
      produce.kind = tok.text == "produce" ? BodyPart::kProduce : BodyPart::kNProduce;
      produce.at = next();
      produce.modules = parse_module_calls("a produce statement");
      body.push_back(std::move(produce));
      continue;
    }
    if (tok.is_punct("{")) ++depth;
    if (tok.is_punct("}")) --depth;
    code.code.push_back(next());
  } while (depth > 0);
  if (!code.code.empty()) body.push_back(std::move(code));
  return body;
}

// `propensity <expression> produce <modules>;` (LPFG manual 7.2).
BodyPart LcParser::parse_propensity() {
  BodyPart part;
  part.kind = BodyPart::kPropensity;
  part.at = next();  // propensity
  int depth = 0;
  while (depth > 0 || !peek().is_ident("produce")) {
    const Token& tok = peek();
    if (tok.kind == TokenKind::End || tok.kind == TokenKind::Verbatim ||
        (depth == 0 && (tok.is_punct(";") || is_close(tok))))
      fail(tok, "expected 'produce' after the propensity, found " + describe(tok));
    if (is_open(tok)) ++depth;
    if (is_close(tok)) --depth;
    part.code.push_back(next());
  }
  if (part.code.empty()) fail(peek(), "expected an expression after 'propensity'");
  next();  // produce
  part.modules = parse_module_calls("a produce statement");
  return part;
}

// Whether the `propensity` here begins a propensity statement (a
// `produce` before the end of the statement) rather than naming a variable.
bool LcParser::propensity_statement_ahead() const {
  int depth = 0;
  for (std::size_t k = 1;; ++k) {
    const Token& t = peek(k);
    if (t.kind == TokenKind::End || t.kind == TokenKind::Verbatim) return false;
    if (depth == 0 && t.is_ident("produce")) return true;
    if (depth == 0 && (t.is_punct(";") || is_close(t))) return false;
    if (is_open(t)) ++depth;
    if (is_close(t)) --depth;
  }
}

// ---- in-body context tests (LPFG manual 3.3) --------------------------------
bool LcParser::in_context_test_ahead() const {
  const Token& tok = peek();
  return (tok.is_ident("InLeftContext") || tok.is_ident("InRightContext") || tok.is_ident("InNewLeftContext") ||
          tok.is_ident("InNewRightContext")) &&
         peek(1).is_punct("(");
}

std::string LcParser::in_context_misplaced(const Token& tok) {
  return "'" + tok.text + "' tests the context of a rule's predecessor: it is only allowed in the body of a "
         "production, decomposition or interpretation rule";
}

// `InLeftContext ( A(x) [ B(y, z) )`: modules as in a predecessor, each
// parameter a variable of the body to receive it.
BodyPart LcParser::parse_in_context() {
  BodyPart test;
  test.kind = BodyPart::kInContext;
  test.at = next();
  const std::string& w = test.at.text;
  test.context = w == "InLeftContext"    ? abi::kLeft
                 : w == "InRightContext" ? abi::kRight
                 : w == "InNewLeftContext" ? abi::kNewLeft
                                           : abi::kNewRight;
  next();  // (
  const std::string names = w + " names";
  while (!peek().is_punct(")"))
    test.modules.push_back(parse_module_call("a module or ')' in " + w + "(...)", names.c_str()));
  if (test.modules.empty()) fail(peek(), "expected the modules to look for in " + w + "(...)");
  next();  // )
  return test;
}

}  // namespace sylva::lang::detail
