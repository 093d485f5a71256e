// From tokens to the syntax tree (gpu/lsystem_body_parser.h): expressions,
// typed, with C++'s conversions made explicit.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>
#include <span>
#include <utility>

#include "gpu/lsystem_body_parser.h"

namespace sylva::gpu {
namespace {

// The functions translated, with their GLSL names.
const std::map<std::string, std::string>& functions() {
  static const std::map<std::string, std::string> names = {
      {"fabs", "abs"}, {"abs", "abs"},     {"fabsf", "abs"},    {"sqrt", "sqrt"}, {"sqrtf", "sqrt"},
      {"min", "min"},  {"max", "max"},     {"fmin", "min"},     {"fmax", "max"},  {"floor", "floor"},
      {"ceil", "ceil"}, {"pow", "pow"},    {"exp", "exp"},      {"log", "log"},   {"sin", "sin"},
      {"cos", "cos"},  {"tan", "tan"},     {"atan2", "atan"},   {"Normalize", "normalize"}};
  return names;
}

}  // namespace

// An expression of the whole token list (a produce argument, a constant).
Expr BodyParser::whole_expression() {
  Expr e = expression();
  if (at_ < toks_.size()) fail("'" + tok().text + "' where the expression should end");
  return e;
}

Expr BodyParser::convert(Expr e, Type to) {
  if (e.type == to) return e;
  if (e.op == Expr::kLiteral && is_scalar(e.type) && is_scalar(to)) {
    Value v = e.literal;
    if (to == Type::kInt) v.c[0] = std::trunc(v.c[0]);
    if (to == Type::kBool) v.c[0] = v.c[0] != 0;
    e.literal = v;
    e.type = to;
    return e;
  }
  Expr c;
  c.op = Expr::kConvert;
  c.type = to;
  c.args.push_back(std::move(e));
  return c;
}

// Converts for an assignment to, or a parameter of, type `to` (C++'s implicit conversions).
Expr BodyParser::assign_convert(Expr e, Type to, const Token& at) const {
  if (e.type == to) return e;
  if (is_scalar(e.type) && is_scalar(to)) return convert(std::move(e), to);
  if (e.type == Type::kVec2 && to == Type::kVec3) return convert(std::move(e), to);
  fail_at(at, std::string("a ") + glsl_type(e.type) + " where a " + glsl_type(to) + " is expected");
}

// ---- expressions (C++ precedence)

Expr BodyParser::expression() { return ternary(); }

Expr BodyParser::ternary() {
  Expr c = logical_or();
  if (!is_punct("?")) return c;
  const Token& q = next();
  Expr a = expression();
  expect(":");
  Expr b = ternary();
  Expr t;
  t.op = Expr::kTernary;
  if (a.type != b.type) {
    if (is_scalar(a.type) && is_scalar(b.type)) {
      const Type common = (a.type == Type::kFloat || b.type == Type::kFloat) ? Type::kFloat : Type::kInt;
      a = convert(std::move(a), common);
      b = convert(std::move(b), common);
    } else {
      fail_at(q, "the two sides of ?: have different types");
    }
  }
  t.type = a.type;
  t.args.push_back(to_bool(std::move(c)));
  t.args.push_back(std::move(a));
  t.args.push_back(std::move(b));
  return t;
}

namespace {

// C's binary operators, loosest first, each with the code binary() takes.
struct BinaryOperator {
  const char* text;
  char code;
};
constexpr BinaryOperator kOr[] = {{"||", '|'}};
constexpr BinaryOperator kAnd[] = {{"&&", '&'}};
constexpr BinaryOperator kEquality[] = {{"==", 'e'}, {"!=", 'n'}};
constexpr BinaryOperator kRelational[] = {{"<", '<'}, {">", '>'}, {"<=", 'l'}, {">=", 'g'}};
constexpr BinaryOperator kAdditive[] = {{"+", '+'}, {"-", '-'}};
constexpr BinaryOperator kMultiplicative[] = {{"*", '*'}, {"/", '/'}, {"%", '%'}};
constexpr std::span<const BinaryOperator> kBinaryLevels[] = {kOr,       kAnd,      kEquality,
                                                             kRelational, kAdditive, kMultiplicative};

}  // namespace

Expr BodyParser::logical_or() { return binary_level(0); }

// Operands of the next tighter level joined, left to right, by this level's
// operators.
Expr BodyParser::binary_level(std::size_t level) {
  if (level == std::size(kBinaryLevels)) return unary();
  Expr l = binary_level(level + 1);
  while (true) {
    const BinaryOperator* found = nullptr;
    for (const BinaryOperator& op : kBinaryLevels[level])
      if (is_punct(op.text)) found = &op;
    if (!found) return l;
    const Token& op = next();
    l = binary(found->code, std::move(l), binary_level(level + 1), op);
  }
}

Expr BodyParser::unary() {
  if (is_punct("-")) {
    next();
    Expr e = unary();
    if (e.type == Type::kBool) e = convert(std::move(e), Type::kInt);
    if (e.op == Expr::kLiteral && is_scalar(e.type)) {
      e.literal.c[0] = -e.literal.c[0];
      return e;
    }
    Expr n;
    n.op = Expr::kNeg;
    n.type = e.type;
    n.args.push_back(std::move(e));
    return n;
  }
  if (is_punct("+")) {
    ++at_;
    return unary();
  }
  if (is_punct("!")) {
    ++at_;
    Expr n;
    n.op = Expr::kNot;
    n.type = Type::kBool;
    n.args.push_back(to_bool(unary()));
    return n;
  }
  // C-style casts: (double) x
  if (is_punct("(") && at_ + 2 < toks_.size() && toks_[at_ + 1].produce < 0 &&
      toks_[at_ + 1].token->is_ident() && is_type_name(toks_[at_ + 1].token->text) && is_punct(")", 2)) {
    const Token& type_token = *toks_[at_ + 1].token;
    at_ += 3;
    std::optional<Type> t = type_named(type_token.text);
    if (!t || is_vector(*t)) fail_at(type_token, "a cast to " + type_token.text);
    Expr e = unary();
    if (!is_scalar(e.type)) fail_at(type_token, "a cast of a vector");
    return convert(std::move(e), *t);
  }
  return postfix(primary());
}

Expr BodyParser::postfix(Expr e) {
  while (is_punct(".")) {
    ++at_;
    const Token& member = next();
    if (!is_vector(e.type)) fail_at(member, "'." + member.text + "' of a number");
    if (member.is_ident("Length") || member.is_ident("Normalized")) {
      expect("(");
      expect(")");
      Expr m;
      m.op = member.text == "Length" ? Expr::kLength : Expr::kNormalized;
      m.type = member.text == "Length" ? Type::kFloat : e.type;
      m.args.push_back(std::move(e));
      e = std::move(m);
      continue;
    }
    if (is_punct("(")) fail_at(member, "the member function " + member.text + " (Length and Normalized are translated)");
    e = field_of(std::move(e), field_index(member, e.type));
  }
  return e;
}

int BodyParser::field_index(const Token& member, Type t) const {
  if (!is_vector(t)) fail_at(member, "'." + member.text + "' of a number");
  if (member.is_ident("x")) return 0;
  if (member.is_ident("y")) return 1;
  if (member.is_ident("z") && t == Type::kVec3) return 2;
  fail_at(member, "the member '" + member.text + "'");
}

Expr BodyParser::field_of(Expr e, int field) {
  Expr f;
  f.op = Expr::kField;
  f.type = Type::kFloat;
  f.field = field;
  f.args.push_back(std::move(e));
  return f;
}

Expr BodyParser::literal(Type t, double v) {
  Expr e;
  e.op = Expr::kLiteral;
  e.type = t;
  for (int i = 0; i < width_of(t); ++i) e.literal.c[i] = v;
  return e;
}

Expr BodyParser::var(int slot) const {
  Expr e;
  e.op = Expr::kVar;
  e.slot = slot;
  e.type = p_.slot_types[slot];
  return e;
}

std::vector<Expr> BodyParser::arguments() {
  expect("(");
  std::vector<Expr> args;
  if (!is_punct(")")) {
    args.push_back(expression());
    while (is_punct(",")) {
      ++at_;
      args.push_back(expression());
    }
  }
  expect(")");
  return args;
}

Expr BodyParser::construct(Type t, const Token& at) {
  std::vector<Expr> args = arguments();
  if (args.size() == 1) {
    if (args[0].type == t) return std::move(args[0]);
    if (t == Type::kVec3 && args[0].type == Type::kVec2) return convert(std::move(args[0]), t);
    fail_at(at, "a vector made of a " + std::string(glsl_type(args[0].type)));
  }
  if (static_cast<int>(args.size()) != width_of(t))
    fail_at(at, "a vector of " + std::to_string(width_of(t)) + " coordinates made of " +
                    std::to_string(args.size()) + " numbers");
  Expr e;
  e.op = t == Type::kVec2 ? Expr::kVec2 : Expr::kVec3;
  e.type = t;
  for (Expr& a : args) {
    if (!is_scalar(a.type)) fail_at(at, "a vector's coordinate that is a vector");
    e.args.push_back(convert(std::move(a), Type::kFloat));
  }
  return e;
}

Expr BodyParser::primary() {
  if (at_end()) fail("an expression ends too early");
  if (toks_[at_].produce >= 0) fail("a produce statement inside an expression");
  const Token& t = next();
  if (t.kind == TokenKind::Number) return number(t);
  if (t.is_punct("(")) {
    Expr e = expression();
    expect(")");
    return e;
  }
  if (t.kind != TokenKind::Identifier) fail_at(t, "'" + t.text + "' in an expression");
  if (t.text == "true" || t.text == "false") return literal(Type::kBool, t.text == "true" ? 1 : 0);
  std::string name = t.text;
  const Token* name_token = &t;
  if (name == "std" && is_punct("::")) {
    ++at_;
    name_token = &next();
    name = name_token->text;
  }
  if (name == "static_cast") {
    expect("<");
    std::string type_text;
    while (is_any_ident()) type_text = next().text;
    expect(">");
    std::optional<Type> to = type_named(type_text);
    if (!to || is_vector(*to)) fail_at(t, "static_cast to " + type_text);
    expect("(");
    Expr e = expression();
    expect(")");
    if (!is_scalar(e.type)) fail_at(t, "a cast of a vector");
    return convert(std::move(e), *to);
  }
  if (random_functions().count(name)) fail_at(*name_token, "stochastic: " + name + " draws random numbers");
  if (std::optional<Type> ty = type_named(name); ty && is_punct("(")) {
    if (is_vector(*ty)) return construct(*ty, *name_token);
    expect("(");
    Expr e = expression();
    expect(")");
    if (!is_scalar(e.type)) fail_at(*name_token, "a cast of a vector");
    return convert(std::move(e), *ty);
  }
  if (is_punct("(")) return call(name, *name_token);
  if (const int slot = lookup(name); slot >= 0) return var(slot);
  if (auto c = constants_.find(name); c != constants_.end()) return c->second;
  fail_at(*name_token, "'" + name + "' is not a parameter, a local variable or a constant of the model");
}

Expr BodyParser::call(const std::string& name, const Token& at) {
  auto f = functions().find(name);
  if (f == functions().end())
    fail_at(at, "a call to " + name +
                    ", which is not translated to GLSL (fabs abs sqrt min max fmin fmax floor ceil pow exp log "
                    "sin cos tan atan2 Normalize, V2d V3d, .Length() .Normalized())");
  std::vector<Expr> args = arguments();
  const std::string& glsl = f->second;
  const std::size_t want = (glsl == "min" || glsl == "max" || glsl == "pow" || glsl == "atan") ? 2 : 1;
  if (args.size() != want) fail_at(at, name + " of " + std::to_string(args.size()) + " arguments");
  Expr e;
  e.op = Expr::kCall;
  e.call = glsl;
  if (glsl == "normalize") {
    if (!is_vector(args[0].type)) fail_at(at, "Normalize of a number");
    e.op = Expr::kNormalized;
    e.type = args[0].type;
    e.args.push_back(std::move(args[0]));
    return e;
  }
  for (const Expr& a : args)
    if (!is_scalar(a.type)) fail_at(at, name + " of a vector");
  // abs, min, max keep ints (C++ overloads); fabs and the others are in doubles.
  const bool ints = (name == "abs" || name == "min" || name == "max") &&
                    std::all_of(args.begin(), args.end(), [](const Expr& a) { return a.type != Type::kFloat; });
  e.type = ints ? Type::kInt : Type::kFloat;
  for (Expr& a : args) e.args.push_back(convert(std::move(a), e.type));
  return e;
}

Expr BodyParser::number(const Token& t) {
  std::string text = t.text;
  text.erase(std::remove(text.begin(), text.end(), '\''), text.end());
  const bool hex = text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
  bool floating = !hex && (text.find_first_of(".eE") != std::string::npos);
  while (!text.empty() && std::string("fFlLuU").find(text.back()) != std::string::npos) {
    if (text.back() == 'f' || text.back() == 'F') {
      if (hex) break;
      floating = true;
    }
    if (text.back() == 'u' || text.back() == 'U') fail_at(t, "an unsigned literal");
    text.pop_back();
  }
  double v = 0;
  if (floating) {
    auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || p != text.data() + text.size()) fail_at(t, "the number " + t.text);
    return literal(Type::kFloat, v);
  }
  long long i = 0;
  const int base = hex ? 16 : (text.size() > 1 && text[0] == '0') ? 8 : 10;
  const char* b = text.data() + (hex ? 2 : 0);
  auto [p, ec] = std::from_chars(b, text.data() + text.size(), i, base);
  if (ec != std::errc() || p != text.data() + text.size() || i > 0x7fffffffLL) fail_at(t, "the number " + t.text);
  return literal(Type::kInt, static_cast<double>(i));
}

Expr BodyParser::to_bool(Expr e) const {
  if (is_vector(e.type)) fail("a vector where a condition is expected");
  return convert(std::move(e), Type::kBool);
}

// The usual arithmetic conversions and the vectors' operators.
Expr BodyParser::binary(char op, Expr a, Expr b, const Token& at) const {
  Expr e;
  auto arith = [&](Expr::Op o) {
    if (is_vector(a.type) || is_vector(b.type)) {
      if (a.type != b.type) fail_at(at, std::string("'") + at.text + "' of a " + glsl_type(a.type) + " and a " + glsl_type(b.type));
      e.type = a.type;
    } else {
      e.type = (a.type == Type::kFloat || b.type == Type::kFloat) ? Type::kFloat : Type::kInt;
      a = convert(std::move(a), e.type);
      b = convert(std::move(b), e.type);
    }
    e.op = o;
  };
  switch (op) {
    case '+': arith(Expr::kAdd); break;
    case '-': arith(Expr::kSub); break;
    case '*':
      if (is_vector(a.type) && is_vector(b.type)) {
        if (a.type != b.type) fail_at(at, "the dot product of vectors of different sizes");
        e.op = Expr::kDot;
        e.type = Type::kFloat;
      } else if (is_vector(a.type) || is_vector(b.type)) {
        if (is_vector(b.type)) std::swap(a, b);
        b = convert(std::move(b), Type::kFloat);
        e.op = Expr::kScale;
        e.type = a.type;
      } else {
        arith(Expr::kMul);
      }
      break;
    case '/':
      if (is_vector(a.type)) {
        if (is_vector(b.type)) fail_at(at, "a vector divided by a vector");
        b = convert(std::move(b), Type::kFloat);
        e.op = Expr::kDivScale;
        e.type = a.type;
      } else if (is_vector(b.type)) {
        fail_at(at, "a number divided by a vector");
      } else {
        arith(Expr::kDiv);
      }
      break;
    case '%':
      if (a.type == Type::kVec3 && b.type == Type::kVec3) {
        e.op = Expr::kCross;
        e.type = Type::kVec3;
      } else if (is_scalar(a.type) && is_scalar(b.type) && a.type != Type::kFloat && b.type != Type::kFloat) {
        arith(Expr::kMod);
      } else {
        fail_at(at, std::string("'%' of a ") + glsl_type(a.type) + " and a " + glsl_type(b.type));
      }
      break;
    case '<': case '>': case 'l': case 'g': case 'e': case 'n': {
      if (is_vector(a.type) || is_vector(b.type)) fail_at(at, "a comparison of vectors");
      const Type common = (a.type == Type::kFloat || b.type == Type::kFloat) ? Type::kFloat
                          : (a.type == Type::kBool && b.type == Type::kBool && (op == 'e' || op == 'n'))
                              ? Type::kBool
                              : Type::kInt;
      a = convert(std::move(a), common);
      b = convert(std::move(b), common);
      e.type = Type::kBool;
      e.op = op == '<' ? Expr::kLess : op == '>' ? Expr::kGreater : op == 'l' ? Expr::kLessEqual
           : op == 'g' ? Expr::kGreaterEqual : op == 'e' ? Expr::kEqual : Expr::kNotEqual;
      break;
    }
    case '&': case '|':
      a = to_bool(std::move(a));
      b = to_bool(std::move(b));
      e.type = Type::kBool;
      e.op = op == '&' ? Expr::kAnd : Expr::kOr;
      break;
    default: fail_at(at, std::string("the operator ") + at.text);
  }
  e.args.push_back(std::move(a));
  e.args.push_back(std::move(b));
  return e;
}

}  // namespace sylva::gpu
