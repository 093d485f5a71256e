// The differential L-system half of the L+C parser (docs/continuous-time.md):
// the conditions of events, the rates `d(x) = ...;` of derivative rules and
// the parameters they are for.
#include <algorithm>
#include <cstddef>
#include <string>
#include <unordered_set>

#include "lang/lc_parser_impl.h"

namespace sylva::lang::detail {

// `when ( condition )` after the ':' of an event.
Code LcParser::parse_event_condition() {
  if (!peek().is_ident("when") || !peek(1).is_punct("("))
    fail(peek(), "expected 'when (condition)' after ':' in an event, found " + describe(peek()));
  next();
  const Token& opening = next();
  Code condition;
  int depth = 0;
  while (depth > 0 || !peek().is_punct(")")) {
    const Token& tok = peek();
    if (tok.kind == TokenKind::End || tok.kind == TokenKind::Verbatim || (depth == 0 && tok.is_punct(";")))
      fail(opening, "expected ')' to close the condition that begins here, found " + describe(tok));
    if (is_open(tok)) ++depth;
    if (is_close(tok)) --depth;
    condition.push_back(next());
  }
  if (condition.empty()) fail(peek(), "expected a condition in 'when ( )'");
  next();  // )
  return condition;
}

// A continuously changing value passes a threshold between two instants the
// integrator looks at; it is equal to it at neither, and the event would
// never fire. Warned where `==` compares a float or double parameter.
void LcParser::warn_of_equality(const Rule& rule) {
  std::unordered_set<std::string> continuous;
  for (const auto& part : rule.parts)
    for (const PatternModule& m : part)
      if (const ModuleDecl* decl = find_module(m.name))
        for (std::size_t i = 0; i < m.formals.size() && i < decl->param_types.size(); ++i)
          if (decl->param_types[i] == "float" || decl->param_types[i] == "double") continuous.insert(m.formals[i]);
  const Code& c = rule.event_condition;
  // The operands of each `==` outside brackets: up to the `&&` or `||` around it.
  auto joins = [](const Token& t) { return t.is_punct("&&") || t.is_punct("||"); };
  int depth = 0;
  std::size_t clause = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (is_open(c[k])) ++depth;
    if (is_close(c[k])) --depth;
    if (depth != 0) continue;
    if (joins(c[k])) clause = k + 1;
    if (!c[k].is_punct("==")) continue;
    std::size_t end = k;
    for (int d = 0; end < c.size() && (d != 0 || !joins(c[end])); ++end) d += is_open(c[end]) - is_close(c[end]);
    const bool reads_continuous = std::any_of(c.begin() + static_cast<std::ptrdiff_t>(clause),
                                              c.begin() + static_cast<std::ptrdiff_t>(end),
                                              [&](const Token& t) { return t.is_ident() && continuous.count(t.text); });
    if (!reads_continuous) continue;
    const SourceLocation at = stream_.location(c[k]);
    model_.warnings.push_back(at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                              ": warning: '==' on a parameter that changes continuously: it equals the value only "
                              "at an instant the integration does not land on, so the event may never fire; "
                              "write '>=' or '<=' (docs/continuous-time.md)");
  }
}

// `d(x) = ` begins a rate statement in a derivative rule's body.
bool LcParser::rate_statement_ahead() const {
  return peek().is_ident("d") && peek(1).is_punct("(") && peek(2).is_ident() && peek(3).is_punct(")") &&
         peek(4).is_punct("=");
}

// `d(x) = expression;`
BodyPart LcParser::parse_rate() {
  BodyPart rate;
  rate.kind = BodyPart::kRate;
  rate.at = next();  // d
  next();            // (
  rate.rate_of = next().text;
  next();  // )
  next();  // =
  int depth = 0;
  while (depth > 0 || !peek().is_punct(";")) {
    const Token& tok = peek();
    if (tok.kind == TokenKind::End || tok.kind == TokenKind::Verbatim || (depth == 0 && is_close(tok)))
      fail(tok, "expected ';' to end 'd(" + rate.rate_of + ") = ...', found " + describe(tok));
    if (is_open(tok)) ++depth;
    if (is_close(tok)) --depth;
    rate.code.push_back(next());
  }
  if (rate.code.empty()) fail(peek(), "expected the rate of '" + rate.rate_of + "' after 'd(" + rate.rate_of + ") ='");
  next();  // ;
  return rate;
}

// The equations of a derivative rule are for the parameters of its one
// strict predecessor module.
void LcParser::resolve_rates(Rule& rule) {
  const std::vector<PatternModule>& strict = rule.parts[abi::kStrict];
  if (strict.size() != 1)
    fail(strict.size() > 1 ? strict[1].at : rule.at,
         "a derivative rule gives the rates of one module: its strict predecessor must be a single module");
  const PatternModule& m = strict.front();
  for (BodyPart& part : rule.body) {
    if (part.kind != BodyPart::kRate) continue;
    const auto formal = std::find(m.formals.begin(), m.formals.end(), part.rate_of);
    if (formal == m.formals.end())
      fail(part.at, "an equation for '" + part.rate_of + "', which is not a parameter of " + m.name +
                        ", the module this derivative rule is for");
    part.rate_index = static_cast<int>(formal - m.formals.begin());
  }
}

}  // namespace sylva::lang::detail
