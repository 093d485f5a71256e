#include "lang/cpfg_expr.h"

#include <cctype>
#include <map>

namespace sylva::lang::cpfg {
namespace {

struct Tok {
  enum Kind { kNumber, kIdent, kString, kOp, kEnd } kind = kEnd;
  std::string text;
  Pos pos;
  std::size_t pos_index = 0;  // where it starts in the line
  std::size_t end = 0;
};

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A character no token of cpfg's expressions starts with: cpfg's lexer
// passes it by (flex echoes it). A macro continued with "\\" leaves a "\".
bool stray(const std::string& s, std::size_t i) {
  const char ch = s[i];
  if (ch == '|') return i + 1 >= s.size() || s[i + 1] != '|';
  if (ch == '.') return i + 1 >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i + 1]));
  return ch == '\\' || ch == '@' || ch == '#' || ch == '$' || ch == '\'' || ch == '~' || ch == '`';
}

Tok read_token(Cursor& c) {
  c.skip_space();
  while (c.at() < c.text().size() && stray(c.text(), c.at())) {
    c.set(c.at() + 1);
    c.skip_space();
  }
  Tok t;
  t.pos = c.pos();
  const std::size_t start = c.at();
  t.pos_index = start;
  const std::string& s = c.text();
  std::size_t i = start;
  if (i >= s.size()) {
    t.end = i;
    return t;
  }
  const char ch = s[i];
  if (std::isdigit(static_cast<unsigned char>(ch)) ||
      (ch == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
    t.kind = Tok::kNumber;
    while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
      std::size_t k = i + 1;
      if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
      if (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) {
        i = k;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
      }
    }
    if (i < s.size() && (s[i] == 'f' || s[i] == 'F')) ++i;  // 1.0f as in C
  } else if (ident_start(ch)) {
    t.kind = Tok::kIdent;
    while (i < s.size() && ident_char(s[i])) ++i;
  } else if (ch == '"') {
    t.kind = Tok::kString;
    ++i;
    while (i < s.size() && s[i] != '"') i += s[i] == '\\' ? 2 : 1;
    if (i >= s.size()) c.fail("unterminated string");
    ++i;
  } else {
    t.kind = Tok::kOp;
    static const char* ops[] = {"-->", "->", "~>", "&&", "||", "==", "!=", "<=", ">="};
    std::size_t len = 1;
    for (const char* op : ops)
      if (s.compare(i, std::char_traits<char>::length(op), op) == 0) {
        len = std::char_traits<char>::length(op);
        break;
      }
    i += len;
  }
  t.text = s.substr(start, i - start);
  t.end = i;
  return t;
}

Tok peek_token(Cursor& c) {
  const std::size_t at = c.at();
  Tok t = read_token(c);
  c.set(at);
  return t;
}

Tok next_token(Cursor& c) {
  c.skip_space();
  for (std::size_t i = c.at(); i < c.text().size() && (stray(c.text(), i) || c.text()[i] == ' ' || c.text()[i] == '\t'); ++i)
    if (stray(c.text(), i))
      c.warn_at(c.pos_at(i), std::string("'") + c.text()[i] + "' read past: it starts no part of an expression (as in cpfg)");
  Tok t = read_token(c);
  c.set(t.end);
  return t;
}

// Expressions and statements are read by recursion, a level for each
// parenthesis, unary operator, argument, index, conditional branch and block.
// Far deeper than any model nests, the nesting is an error where it gets too
// deep, before the machine stack runs out.
constexpr int kMaxNesting = 256;

class Nested {
 public:
  // At the next token, which opens the level.
  explicit Nested(Cursor& c) : c_(c) {
    if (c_.nesting() >= kMaxNesting)
      c_.fail_at(peek_token(c_).pos, "nested more than " + std::to_string(kMaxNesting) +
                                         " levels deep (parentheses, operators, arguments or blocks)");
    ++c_.nesting();
  }
  ~Nested() { --c_.nesting(); }
  Nested(const Nested&) = delete;
  Nested& operator=(const Nested&) = delete;

 private:
  Cursor& c_;
};

std::string describe(const Tok& t) {
  if (t.kind == Tok::kEnd) return "the end of the line";
  return "'" + t.text + "'";
}

[[noreturn]] void expected(Cursor& c, const Tok& t, const std::string& what) {
  c.fail_at(t.pos, "expected " + what + ", found " + describe(t));
}

void expect_op(Cursor& c, const char* op) {
  Tok t = next_token(c);
  if (t.kind != Tok::kOp || t.text != op) expected(c, t, std::string("'") + op + "'");
}

std::string number_text(std::string n) {
  if (!n.empty() && (n.back() == 'f' || n.back() == 'F')) n.pop_back();
  if (n.find_first_of(".eE") == std::string::npos) n += ".0";
  if (n[0] == '.') n = "0" + n;
  if (n.back() == '.') n += "0";
  return n;
}

struct Function {
  const char* cpp;
  int min_args, max_args;
};

const std::map<std::string, Function>& functions() {
  static const std::map<std::string, Function> table = {
      {"sin", {"::sylva::rt::cpfg::sin", 1, 1}},
      {"cos", {"::sylva::rt::cpfg::cos", 1, 1}},
      {"tan", {"::sylva::rt::cpfg::tan", 1, 1}},
      {"asin", {"::sylva::rt::cpfg::asin", 1, 1}},
      {"acos", {"::sylva::rt::cpfg::acos", 1, 1}},
      {"atan", {"::sylva::rt::cpfg::atan", 1, 2}},
      {"atan2", {"::sylva::rt::cpfg::atan2", 2, 2}},
      {"exp", {"::std::exp", 1, 1}},
      {"log", {"::std::log", 1, 1}},
      {"sqrt", {"::std::sqrt", 1, 1}},
      {"fabs", {"::std::fabs", 1, 1}},
      {"floor", {"::std::floor", 1, 1}},
      {"ceil", {"::std::ceil", 1, 1}},
      {"trunc", {"::std::trunc", 1, 1}},
      {"sign", {"::sylva::rt::cpfg::sign", 1, 1}},
      {"ran", {"::sylva::rt::cpfg::ran", 1, 1}},
      {"nran", {"::sylva::rt::cpfg::nran", 2, 2}},
      {"srand", {"::sylva::rt::cpfg::srand", 1, 1}},
      {"func", {"::sylva::rt::cpfg::func", 2, 2}},
      {"pow", {"::sylva::rt::cpfg::pow", 2, 2}},
      {"bran", {"::sylva::rt::cpfg::bran", 2, 2}},
      {"biran", {"::sylva::rt::cpfg::biran", 2, 2}},
      {"fclose", {"::sylva::rt::cpfg::fclose", 1, 1}},
      {"fflush", {"::sylva::rt::cpfg::fflush", 1, 1}},
      {"curveX", {"::sylva::rt::cpfg::curve_x", 2, 2}},
      {"curveY", {"::sylva::rt::cpfg::curve_y", 2, 2}},
      {"curveZ", {"::sylva::rt::cpfg::curve_z", 2, 2}},
      {"curveGAL", {"::sylva::rt::cpfg::curve_length", 1, 1}},
      {"stop", {"::sylva::rt::cpfg::stop", 0, 1}},
      // The view volume (CPFG manual 5.6), with cpfg's dummy argument.
      {"vvXmin", {"::sylva::rt::cpfg::view_volume<0>", 1, 1}},
      {"vvXmax", {"::sylva::rt::cpfg::view_volume<1>", 1, 1}},
      {"vvYmin", {"::sylva::rt::cpfg::view_volume<2>", 1, 1}},
      {"vvYmax", {"::sylva::rt::cpfg::view_volume<3>", 1, 1}},
      {"vvZmin", {"::sylva::rt::cpfg::view_volume<4>", 1, 1}},
      {"vvZmax", {"::sylva::rt::cpfg::view_volume<5>", 1, 1}},
      {"vvScale", {"::sylva::rt::cpfg::view_volume<6>", 1, 1}},
  };
  return table;
}

std::string ternary(Cursor& c, Scope& scope);

std::string call(Cursor& c, Scope& scope, const Tok& name) {
  if (name.text == "printf") {
    expect_op(c, "(");
    Tok format = next_token(c);
    if (format.kind != Tok::kString) expected(c, format, "a format string");
    std::string text = "::std::printf(" + format.text;
    while (true) {
      Tok t = next_token(c);
      if (t.kind == Tok::kOp && t.text == ")") break;
      if (t.kind != Tok::kOp || t.text != ",") expected(c, t, "',' or ')'");
      text += ", (double)(" + ternary(c, scope) + ")";
    }
    return text + ")";
  }
  if (name.text == "fopen") {
    expect_op(c, "(");
    Tok file = next_token(c);
    if (file.kind != Tok::kString) expected(c, file, "a file name in quotes");
    expect_op(c, ",");
    Tok mode = next_token(c);
    if (mode.kind != Tok::kString) expected(c, mode, "\"r\" or \"w\"");
    expect_op(c, ")");
    return "::sylva::rt::cpfg::fopen(" + file.text + ", " + mode.text + ")";
  }
  if (name.text == "fprintf" || name.text == "fscan" || name.text == "fscanf") {
    // fprintf(file, "format", values...) and fscan(file, "format", &var, ...):
    // every cpfg variable is a number, so formats hold %f and %g only.
    const bool scan = name.text != "fprintf";
    expect_op(c, "(");
    std::string file = ternary(c, scope);
    expect_op(c, ",");
    Tok format = next_token(c);
    if (format.kind != Tok::kString) expected(c, format, "a format string");
    std::vector<std::string> values;
    while (true) {
      Tok t = next_token(c);
      if (t.kind == Tok::kOp && t.text == ")") break;
      if (t.kind != Tok::kOp || t.text != ",") expected(c, t, "',' or ')'");
      if (!scan) {
        values.push_back("(double)(" + ternary(c, scope) + ")");
        continue;
      }
      expect_op(c, "&");
      Tok var = next_token(c);
      if (var.kind != Tok::kIdent) expected(c, var, "a variable to read into");
      if (!scope.formals.count(var.text) && !scope.locals.count(var.text) && !scope.globals.count(var.text)) {
        if (scope.control_block) scope.globals.insert(var.text);
        else scope.locals.insert(var.text);
      }
      values.push_back(variable(var.text));
    }
    if (!scan) {
      std::string text = "::sylva::rt::cpfg::fprintf((double)(" + file + "), " + format.text;
      for (const std::string& v : values) text += ", " + v;
      return text + ")";
    }
    // Read into floats (what %f and %g store), then copy into the variables.
    const std::string n = std::to_string(values.size() ? values.size() : 1);
    std::string text = "[&]() -> double { float sylva_in[" + n +
                       "] = {}; double sylva_read = ::sylva::rt::cpfg::fscan((double)(" + file + "), " + format.text;
    for (std::size_t k = 0; k < values.size(); ++k) text += ", &sylva_in[" + std::to_string(k) + "]";
    text += ");";
    for (std::size_t k = 0; k < values.size(); ++k)
      text += " if (sylva_read > " + std::to_string(k) + ") " + values[k] + " = sylva_in[" + std::to_string(k) + "];";
    return text + " return sylva_read; }()";
  }
  auto it = functions().find(name.text);
  if (it == functions().end()) {
    static const std::set<std::string> later = {"inblob"};
    if (later.count(name.text)) c.fail_at(name.pos, "the cpfg function " + name.text + " is not supported yet");
    c.fail_at(name.pos, "unknown function '" + name.text + "'");
  }
  expect_op(c, "(");
  std::vector<std::string> args;
  if (peek_token(c).text != ")") {
    args.push_back(ternary(c, scope));
    while (peek_token(c).text == ",") {
      next_token(c);
      args.push_back(ternary(c, scope));
    }
  }
  expect_op(c, ")");
  const int n = static_cast<int>(args.size());
  if (n < it->second.min_args || n > it->second.max_args)
    c.fail_at(name.pos, name.text + " takes " + std::to_string(it->second.min_args) +
                            (it->second.max_args != it->second.min_args ? " or " + std::to_string(it->second.max_args) : "") +
                            " argument(s), not " + std::to_string(n));
  std::string text = it->second.cpp;
  text += "(";
  for (int k = 0; k < n; ++k) text += (k ? ", " : "") + std::string("(double)(") + args[k] + ")";
  return text + ")";
}

std::string array_index(Cursor& c, Scope& scope) {
  // name[i,j] or name[i][j]
  std::string text;
  while (peek_token(c).text == "[") {
    next_token(c);
    text += "[(int)(" + ternary(c, scope) + ")]";
    while (peek_token(c).text == ",") {
      next_token(c);
      text += "[(int)(" + ternary(c, scope) + ")]";
    }
    expect_op(c, "]");
  }
  return text;
}

std::string primary(Cursor& c, Scope& scope) {
  Tok t = next_token(c);
  if (t.kind == Tok::kNumber) return number_text(t.text);
  if (t.kind == Tok::kOp && t.text == "(") {
    std::string inner = ternary(c, scope);
    expect_op(c, ")");
    return "(" + inner + ")";
  }
  if (t.kind == Tok::kIdent) {
    if (peek_token(c).text == "(") return call(c, scope, t);
    if (scope.arrays.count(t.text)) {
      if (peek_token(c).text != "[") c.fail_at(t.pos, "array " + t.text + " needs an index");
      return variable(t.text) + array_index(c, scope);
    }
    if (scope.formals.count(t.text) || scope.locals.count(t.text) || scope.globals.count(t.text))
      return variable(t.text);
    // cpfg warns ("Identifier ... not previously defined") and reads a new
    // variable of value 0.
    if (scope.warnings) {
      const SourceLocation at = c.location(t.pos);
      scope.warnings->push_back(at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                                ": warning: unknown variable '" + t.text + "' read as 0 (as cpfg does)");
    }
    scope.locals.insert(t.text);
    return variable(t.text);
  }
  expected(c, t, "an expression");
}

std::string unary(Cursor& c, Scope& scope) {
  Tok t = peek_token(c);
  if (t.kind == Tok::kOp && (t.text == "-" || t.text == "+" || t.text == "!")) {
    const Nested operand(c);
    next_token(c);
    return "(" + t.text + unary(c, scope) + ")";
  }
  return primary(c, scope);
}

// ^ is exponentiation, tighter than * and /, left-associative.
std::string power(Cursor& c, Scope& scope) {
  std::string left = unary(c, scope);
  while (peek_token(c).text == "^") {
    next_token(c);
    left = "::sylva::rt::cpfg::pow(" + left + ", " + unary(c, scope) + ")";
  }
  return left;
}

std::string product(Cursor& c, Scope& scope) {
  std::string left = power(c, scope);
  while (true) {
    Tok t = peek_token(c);
    if (t.kind != Tok::kOp || (t.text != "*" && t.text != "/" && t.text != "%")) return left;
    next_token(c);
    std::string right = power(c, scope);
    left = t.text == "%" ? "::std::fmod(" + left + ", " + right + ")" : "(" + left + " " + t.text + " " + right + ")";
  }
}

std::string binary_level(Cursor& c, Scope& scope, int level) {
  // 0: ||, 1: &&, 2: == !=, 3: < <= > >=, 4: + -
  static const std::vector<std::vector<std::string>> ops = {
      {"||"}, {"&&"}, {"==", "!="}, {"<", "<=", ">", ">="}, {"+", "-"}};
  auto next = [&]() { return level == 4 ? product(c, scope) : binary_level(c, scope, level + 1); };
  std::string left = next();
  while (true) {
    Tok t = peek_token(c);
    bool match = false;
    for (const std::string& op : ops[static_cast<std::size_t>(level)]) match = match || (t.kind == Tok::kOp && t.text == op);
    if (!match) return left;
    next_token(c);
    left = "(" + left + " " + t.text + " " + next() + ")";
  }
}

std::string ternary(Cursor& c, Scope& scope) {
  const Nested nested(c);
  std::string cond = binary_level(c, scope, 0);
  if (peek_token(c).text != "?") return cond;
  next_token(c);
  std::string a = ternary(c, scope);
  expect_op(c, ":");
  std::string b = ternary(c, scope);
  return "((" + cond + ") ? (double)(" + a + ") : (double)(" + b + "))";
}

std::string block(Cursor& c, Scope& scope) {
  expect_op(c, "{");
  return "{ " + statements(c, scope) + " }";
}

std::string statement(Cursor& c, Scope& scope) {
  const Nested nested(c);
  Tok t = next_token(c);
  if (t.kind == Tok::kIdent && t.text == "if") {
    expect_op(c, "(");
    std::string cond = ternary(c, scope);
    expect_op(c, ")");
    std::string text = "if (" + cond + ") " + block(c, scope);
    if (peek_token(c).text == "else") {
      next_token(c);
      if (peek_token(c).text == "if") text += " else { " + statement(c, scope) + " }";
      else text += " else " + block(c, scope);
    }
    return text;
  }
  if (t.kind == Tok::kIdent && t.text == "while") {
    expect_op(c, "(");
    std::string cond = ternary(c, scope);
    expect_op(c, ")");
    return "while (" + cond + ") " + block(c, scope);
  }
  if (t.kind == Tok::kIdent && t.text == "do") {
    std::string body = block(c, scope);
    Tok w = next_token(c);
    if (w.text != "while") expected(c, w, "'while'");
    expect_op(c, "(");
    std::string cond = ternary(c, scope);
    expect_op(c, ")");
    if (peek_token(c).text == ";") next_token(c);
    return "do " + body + " while (" + cond + ");";
  }
  // An assignment (name = e; or name[i] = e;), or else an expression whose
  // value is dropped (cpfg's "procedure": f(x); and also x - y;).
  Tok after = peek_token(c);
  bool assignment = t.kind == Tok::kIdent && after.kind == Tok::kOp && after.text == "=";
  if (t.kind == Tok::kIdent && after.text == "[" && scope.arrays.count(t.text)) {
    const std::size_t index_at = c.at();
    Scope probe = scope;
    probe.warnings = nullptr;
    array_index(c, probe);
    assignment = peek_token(c).text == "=";
    c.set(index_at);
  }
  if (!assignment) {
    c.set(t.pos_index);
    std::string value = ternary(c, scope);
    Tok semi = next_token(c);
    if (semi.kind != Tok::kOp || semi.text != ";") expected(c, semi, "';' after the statement");
    return "(void)(" + value + ");";
  }
  std::string target;
  if (after.text == "[") {
    target = variable(t.text) + array_index(c, scope);
  } else {
    if (scope.arrays.count(t.text)) c.fail_at(t.pos, "array " + t.text + " needs an index");
    if (!scope.formals.count(t.text) && !scope.locals.count(t.text) && !scope.globals.count(t.text)) {
      if (scope.control_block) scope.globals.insert(t.text);
      else scope.locals.insert(t.text);
    }
    target = variable(t.text);
  }
  Tok eq = next_token(c);
  if (eq.kind != Tok::kOp || eq.text != "=") expected(c, eq, "'=' (an assignment)");
  std::string value = ternary(c, scope);
  Tok semi = next_token(c);
  if (semi.kind != Tok::kOp || semi.text != ";") expected(c, semi, "';' after the assignment");
  return target + " = " + value + ";";
}

}  // namespace

void Cursor::fail(const std::string& message) const {
  Cursor copy = *this;
  copy.skip_space();
  std::string found = copy.peek() ? std::string("'") + copy.peek() + "'" : "the end of the line";
  throw ModelError(copy.location(), message + ", found " + found);
}

std::string expression(Cursor& c, Scope& scope) { return ternary(c, scope); }

std::string statements(Cursor& c, Scope& scope) {
  std::string text;
  while (true) {
    Tok t = peek_token(c);
    if (t.kind == Tok::kOp && t.text == "}") {
      next_token(c);
      return text;
    }
    if (t.kind == Tok::kEnd) expected(c, t, "'}'");
    text += statement(c, scope) + " ";
  }
}

}  // namespace sylva::lang::cpfg
