// From tokens to the syntax tree (gpu/lsystem_body_parser.h): the C++ type
// names, and a body's statements. The expressions are in
// lsystem_expression_parser.cpp.
#include "gpu/lsystem_body_parser.h"

#include <utility>

namespace sylva::gpu {

bool is_type_name(const std::string& s) {
  return s == "float" || s == "double" || s == "int" || s == "bool" || s == "V2d" || s == "V2f" || s == "V3d" ||
         s == "V3f" || s == "V2td" || s == "V2tf" || s == "V3td" || s == "V3tf" || s == "long" || s == "short" ||
         s == "unsigned" || s == "signed" || s == "char";
}

std::optional<Type> type_named(const std::string& s) {
  if (s == "float" || s == "double") return Type::kFloat;
  if (s == "int" || s == "long" || s == "short" || s == "signed") return Type::kInt;
  if (s == "bool") return Type::kBool;
  if (s == "V2d" || s == "V2f" || s == "V2td" || s == "V2tf") return Type::kVec2;
  if (s == "V3d" || s == "V3f" || s == "V3td" || s == "V3tf") return Type::kVec3;
  return std::nullopt;
}

const std::set<std::string>& random_functions() {
  static const std::set<std::string> names = {"ran", "Ran", "rand", "random", "drand48", "lrand48", "srand",
                                              "Uniform", "Gaussian", "Normal", "Bernoulli", "Poisson",
                                              "Exponential", "Binomial", "SeedRNG", "sran", "RandomNumber"};
  return names;
}

Stmt BodyParser::parse_body() {
  Stmt s = statement();
  if (at_ < toks_.size()) fail("'" + tok().text + "' after the end of the body");
  return s;
}

Stmt BodyParser::statement() {
  if (at_end()) fail("the body ends too early");
  if (toks_[at_].produce >= 0) {
    Stmt s;
    s.kind = Stmt::kProduce;
    s.produce = produce_index(toks_[at_].produce);
    ++at_;
    if (is_punct(";")) ++at_;
    return s;
  }
  if (is_punct("{")) {
    ++at_;
    scopes_.emplace_back();
    Stmt block;
    block.kind = Stmt::kBlock;
    while (!is_punct("}")) block.body.push_back(statement());
    ++at_;
    scopes_.pop_back();
    return block;
  }
  if (is_punct(";")) {
    ++at_;
    return Stmt{};
  }
  if (is_ident("if")) {
    ++at_;
    expect("(");
    Expr c = expression();
    expect(")");
    Stmt s;
    s.kind = Stmt::kIf;
    s.expr = to_bool(std::move(c));
    scopes_.emplace_back();
    s.body.push_back(statement());
    scopes_.pop_back();
    if (is_ident("else")) {
      ++at_;
      scopes_.emplace_back();
      s.body.push_back(statement());
      scopes_.pop_back();
    }
    return s;
  }
  if (is_ident("const") || (is_any_ident() && is_type_name(tok().text) && !is_punct("(", 1)))
    return declaration();
  if (is_punct("++") || is_punct("--")) {
    const char op = tok().text[0];
    ++at_;
    Stmt s = increment(op);
    expect(";");
    return s;
  }
  if (is_any_ident()) {
    const Token& name = tok();
    if (random_functions().count(name.text)) fail("stochastic: " + name.text + " draws random numbers");
    const int slot = lookup(name.text);
    if (slot < 0) {
      if (is_punct("(", 1)) fail("a call to " + name.text + " as a statement");
      fail("'" + name.text + "' is not a local variable or parameter of the production");
    }
    ++at_;
    int field = -1;
    if (is_punct(".")) {
      ++at_;
      const Token& member = next();
      if (member.is_ident("Normalize") && is_punct("(") && is_punct(")", 1)) {
        at_ += 2;
        expect(";");
        Stmt s;
        s.kind = Stmt::kAssign;
        s.slot = slot;
        Expr v = var(slot);
        Expr n;
        n.op = Expr::kNormalized;
        n.type = v.type;
        n.args.push_back(std::move(v));
        s.expr = std::move(n);
        return s;
      }
      field = field_index(member, p_.slot_types[slot]);
    }
    if (is_punct("++") || is_punct("--")) {
      if (field >= 0) fail("++ or -- on a vector's coordinate");
      const char op = tok().text[0];
      ++at_;
      Stmt s = increment_slot(op, slot);
      expect(";");
      return s;
    }
    Stmt s;
    s.kind = Stmt::kAssign;
    s.slot = slot;
    s.field = field;
    const Token& op = tok();
    if (is_punct("=")) s.op = '=';
    else if (is_punct("+=")) s.op = '+';
    else if (is_punct("-=")) s.op = '-';
    else if (is_punct("*=")) s.op = '*';
    else if (is_punct("/=")) s.op = '/';
    else fail("an assignment (= += -= *= /=) expected after '" + name.text + "'");
    ++at_;
    Expr value = expression();
    expect(";");
    const Type target = field >= 0 ? Type::kFloat : p_.slot_types[slot];
    Expr current = field >= 0 ? field_of(var(slot), field) : var(slot);
    if (s.op != '=') value = binary(s.op, std::move(current), std::move(value), op);
    s.expr = assign_convert(std::move(value), target, op);
    return s;
  }
  if (is_ident("return")) fail("'return' in a production body");
  if (is_ident("for") || is_ident("while") || is_ident("do")) fail("a loop ('" + tok().text + "')");
  if (is_ident("nproduce")) fail("'nproduce'");
  fail("'" + tok().text + "' begins a statement that is not translated");
}

Stmt BodyParser::increment(char op) {
  if (!is_any_ident()) fail("++ or -- of something other than a variable");
  const int slot = lookup(tok().text);
  if (slot < 0) fail("'" + tok().text + "' is not a local variable or parameter of the production");
  ++at_;
  return increment_slot(op, slot);
}
Stmt BodyParser::increment_slot(char op, int slot) {
  if (p_.slot_types[slot] != Type::kInt && p_.slot_types[slot] != Type::kFloat) fail("++ or -- of a non-number");
  Stmt s;
  s.kind = Stmt::kAssign;
  s.slot = slot;
  Expr one = literal(Type::kInt, 1);
  s.expr = assign_convert(binary(op == '+' ? '+' : '-', var(slot), one, here()), p_.slot_types[slot], here());
  return s;
}

Stmt BodyParser::declaration() {
  while (is_ident("const") || is_ident("static")) ++at_;
  std::string type_text;
  const Token& type_token = tok();
  while (is_any_ident() && is_type_name(tok().text)) type_text += (type_text.empty() ? "" : " ") + next().text;
  if (type_text.find("unsigned") != std::string::npos || type_text == "char")
    fail_at(type_token, "a variable of type '" + type_text + "'");
  std::optional<Type> t = type_named(type_text.substr(type_text.rfind(' ') + 1));
  if (type_text.rfind("long", 0) == 0 || type_text.rfind("short", 0) == 0 || type_text.rfind("signed", 0) == 0)
    t = Type::kInt;
  if (type_text == "long double") t = Type::kFloat;
  if (!t) fail_at(type_token, "a variable of type '" + type_text + "'");
  Stmt block;
  block.kind = Stmt::kBlock;  // several declarators: statements in the enclosing scope
  while (true) {
    if (!is_any_ident()) fail("a variable name expected");
    const Token& name = next();
    Stmt d;
    d.kind = Stmt::kDecl;
    if (is_punct("=")) {
      ++at_;
      d.expr = assign_convert(expression(), *t, name);
    } else if (is_punct("(") && is_vector(*t)) {
      d.expr = assign_convert(construct(*t, name), *t, name);
    } else {
      d.expr = literal(*t, 0);
    }
    d.slot = new_slot(name.text, *t);
    scopes_.back()[name.text] = d.slot;
    block.body.push_back(std::move(d));
    if (is_punct(",")) {
      ++at_;
      continue;
    }
    expect(";");
    break;
  }
  if (block.body.size() == 1) return std::move(block.body[0]);
  block.kind = Stmt::kBlock;
  // A block would scope the names: keep them as consecutive statements of a
  // block marked with slot -2 (written without braces).
  block.slot = -2;
  return block;
}

int BodyParser::produce_index(int cut) {
  // Each produce statement is parsed once, when met.
  if (static_cast<std::size_t>(cut) >= produced_index_.size()) produced_index_.resize(cut + 1, -1);
  if (produced_index_[cut] < 0) {
    std::vector<Produced> modules;
    // Parse the modules' arguments in the current scope.
    auto saved_toks = std::move(toks_);
    const std::size_t saved_at = at_;
    for (const lang::ModuleCall& call : produce_calls_[cut]) modules.push_back(produced_(call, *this));
    toks_ = std::move(saved_toks);
    at_ = saved_at;
    p_.produces.push_back(std::move(modules));
    produced_index_[cut] = static_cast<int>(p_.produces.size()) - 1;
  } else {
    fail("a produce statement met twice");
  }
  return produced_index_[cut];
}

}  // namespace sylva::gpu
