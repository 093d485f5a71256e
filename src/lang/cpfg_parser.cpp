#include "lang/cpfg_parser.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "lang/cpfg_expr.h"
#include "lang/cpfg_lines.h"
#include "lang/cpfg_random_code.h"
#include "lang/literal_numbers.h"

namespace sylva::lang {
namespace {
using cpfg::Cursor;
using cpfg::Line;
using cpfg::Pos;
using cpfg::Scope;

Token token_at(Pos p, std::string text = {}) {
  Token t;
  t.kind = TokenKind::Identifier;
  t.text = std::move(text);
  t.file = p.file;
  t.line = p.line;
  t.column = p.column;
  t.space_before = true;
  return t;
}

Code code_at(Pos p, const std::string& text) { return Code{token_at(p, text)}; }

// ---- symbols -------------------------------------------------------------------

// Multi-character turtle symbols (CPFG manual, section 6), longest first.
const char* const kAtSymbols[] = {"Di", "Dd", "bo", "bc", "PS", "PC", "PD", "Gs", "Ge", "Gc", "Gt", "Gr", "Tx",
                                  "Ts", "Td", "Tp", "Tf", "M",  "v",  "R",  "D",  "o",  "c",  "O",  "#",  "T",
                                  "L",  "S",  "s",  "b"};

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\0'; }

std::string mangle(const std::string& symbol, std::size_t params) {
  std::string name = "cpfg_";
  static const char* hex = "0123456789ABCDEF";
  for (char ch : symbol) {
    const unsigned char u = static_cast<unsigned char>(ch);
    if (std::isalnum(u)) name += ch;
    else name += std::string("x") + hex[u >> 4] + hex[u & 15];
  }
  return name + "_" + std::to_string(params);
}

class CpfgParser {
 public:
  // `split`: the multi-character turtle symbols (@o, ?P ...) to read as one
  // module a character, as cpfg's string holds them (see parse_cpfg).
  CpfgParser(const std::string& text, const std::string& main_file, std::set<std::string> split = {})
      : split_(std::move(split)) {
    model_.main_file = main_file;
    model_.cpfg = true;
    lines_ = cpfg::read_logical_lines(text, model_.files, main_file);
    model_.modules = predefined_modules();
    for (std::size_t k = 0; k < model_.modules.size(); ++k) module_index_[model_.modules[k].name] = k;
    model_.modules[module_index_.at("SB")].display_name = "[";
    model_.modules[module_index_.at("EB")].display_name = "]";
    model_.modules[module_index_.at("Cut")].display_name = "%";
  }

  Model parse() {
    collect_globals();
    for (const Line& line : lines_) statement(line);
    if (!seen_lsystem_) throw ModelError(SourceLocation{model_.main_file, 1, 1}, "expected 'Lsystem:' (a cpfg model)");
    if (!seen_end_) throw ModelError(SourceLocation{model_.main_file, 1, 1}, "expected 'endlsystem' at the end of the L-system");
    if (!seen_axiom_) throw ModelError(SourceLocation{model_.main_file, 1, 1}, "the L-system has no axiom");
    finish();
    return std::move(model_);
  }

  // The multi-character symbols of the model that hold a character some
  // production names as a module of its own (o(r) beside @o(0.2)): in cpfg
  // both are the same module o, so those symbols must be read split.
  std::set<std::string> symbols_to_split() const {
    std::set<std::string> split;
    for (const auto& [sym, names] : by_symbol_) {
      if (sym.size() < 2 || sym == "@L" || (sym[0] != '@' && sym[0] != '?' && sym[0] != '~')) continue;
      for (char ch : sym)
        if (lone_pattern_symbols_.count(ch)) split.insert(sym);
    }
    return split;
  }

 private:
  static Token verbatim(Pos p, const std::string& text) {
    Token t = token_at(p, text);
    t.kind = TokenKind::Verbatim;
    return t;
  }

  // The names an expression may use outside a production: the globals and arrays.
  Scope new_scope() {
    Scope scope;
    scope.globals = globals_;
    scope.arrays = arrays_;
    scope.warnings = &model_.warnings;
    return scope;
  }

  // Names assigned (or read by fscan) in Start/End blocks are global (CPFG manual 4.1).
  void collect_globals() {
    for (const Line& line : lines_) {
      Cursor c(line, model_.files, &model_.warnings);
      std::string key;
      if (!keyword(c, &key) || (key != "start" && key != "starteach" && key != "endeach" && key != "end")) continue;
      const std::string& s = line.text;
      for (std::size_t i = 0; i < s.size(); ++i) {
        if (!(std::isalpha(static_cast<unsigned char>(s[i])) || s[i] == '_') ||
            (i > 0 && (std::isalnum(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == '_')))
          continue;
        std::size_t e = i;
        while (e < s.size() && (std::isalnum(static_cast<unsigned char>(s[e])) || s[e] == '_')) ++e;
        std::size_t k = e;
        while (k < s.size() && s[k] == ' ') ++k;
        std::size_t before = i;
        while (before > 0 && s[before - 1] == ' ') --before;
        // Assigned (name = ...) or read into by fscan (&name).
        const bool assigned = k < s.size() && s[k] == '=' && (k + 1 >= s.size() || s[k + 1] != '=');
        const bool scanned = before > 0 && s[before - 1] == '&' && (before < 2 || s[before - 2] != '&');
        if (assigned || scanned) globals_.insert(s.substr(i, e - i));
        i = e;
      }
    }
  }

  // Reads "word word:" at the start of a line; the key is lower case without spaces.
  static bool keyword(Cursor& c, std::string* key) {
    const std::size_t start = c.at();
    c.skip_space();
    std::string k;
    while (true) {
      while (std::isalpha(static_cast<unsigned char>(c.peek()))) k += static_cast<char>(std::tolower(static_cast<unsigned char>(c.get())));
      if (c.peek() == ' ' && std::isalpha(static_cast<unsigned char>(c.peek(1))) && !k.empty()) {
        // "derivation length:", "maximum depth:", "ring lsystem"
        const std::size_t save = c.at();
        c.get();
        std::string rest;
        std::size_t j = c.at();
        while (std::isalpha(static_cast<unsigned char>(c.text()[j < c.text().size() ? j : 0])) && j < c.text().size())
          rest += static_cast<char>(std::tolower(static_cast<unsigned char>(c.text()[j++])));
        if (k + rest == "derivationlength" || k + rest == "maximumdepth" || k + rest == "ringlsystem" ||
            k + rest == "homomorphismno") {
          continue;
        }
        c.set(save);
      }
      break;
    }
    c.skip_space();
    static const std::set<std::string> colon_words = {"lsystem", "derivationlength", "axiom", "ignore", "consider",
                                                      "seed", "define", "start", "starteach", "endeach", "end",
                                                      "maximumdepth", "decomposition", "homomorphism"};
    if (c.peek() == ':' && colon_words.count(k)) {
      c.get();
      *key = k;
      return true;
    }
    if ((k == "endlsystem" || k == "ringlsystem" || k == "decomposition" || k == "homomorphism" ||
         k == "endhomomorphism" || k == "enddecomposition") &&
        (c.done())) {
      *key = k;
      return true;
    }
    c.set(start);
    return false;
  }

  void statement(const Line& line) {
    Cursor c(line, model_.files, &model_.warnings);
    const Pos at = c.pos();
    std::string key;
    const bool has_key = keyword(c, &key);
    if (seen_end_ && !(has_key && key == "lsystem"))
      c.fail_at(at, "expected 'Lsystem:' (a sub-L-system) after 'endlsystem'");
    if (!has_key) {
      if (!seen_lsystem_) c.fail_at(at, "expected 'Lsystem:' before the L-system");
      production(c, at);
      return;
    }
    if (key != "lsystem" && !seen_lsystem_) c.fail_at(at, "expected 'Lsystem:' before the L-system");
    if (key == "lsystem") {
      if (seen_lsystem_ && !seen_end_) c.fail_at(at, "expected 'endlsystem' before the next 'Lsystem:'");
      // The label is optional (0); it names the L-system for ?(label,s) calls.
      c.skip_space();
      const Pos lp = c.pos();
      std::string digits;
      while (std::isdigit(static_cast<unsigned char>(c.peek()))) digits += c.get();
      c.skip_space();
      if (!c.done()) c.fail_at(lp, "expected an integer label after 'Lsystem:'");
      const std::optional<int> read = digits.empty() ? 0 : nonnegative_int(digits);
      if (!read) c.fail_at(lp, "the L-system label " + digits + " is too large (at most " + std::to_string(INT_MAX) + ")");
      const int label = *read;
      for (const Block& b : blocks_)
        if (b.label == label) c.fail_at(lp, "a second L-system with label " + std::to_string(label));
      Block block;
      block.label = label;
      blocks_.push_back(block);
      seen_lsystem_ = true;
      seen_end_ = false;
      section_ = kProductions;
      return;
    }
    const bool main_block = blocks_.size() == 1;
    if (key == "endlsystem") {
      seen_end_ = true;
      return;
    }
    // Only the main L-system's axiom, derivation length and depths are used;
    // a sub-L-system's are read and dropped (CPFG manual 7.2).
    if (!main_block && (key == "derivationlength" || key == "maximumdepth" || key == "ringlsystem")) {
      Scope scope = new_scope();
      if (key != "ringlsystem") cpfg::expression(c, scope);
      globals_.insert(scope.locals.begin(), scope.locals.end());
      return;
    }
    if (!main_block && key == "axiom") {
      if (module_string(c, nullptr, "the axiom").empty()) c.fail_at(at, "the axiom cannot be empty");
      return;
    }
    if (key == "derivationlength") {
      setting(c, at, Setting::kDerivationLength);
    } else if (key == "maximumdepth") {
      if (section_ == kProductions) c.fail_at(at, "'maximum depth:' belongs after 'decomposition' or 'homomorphism'");
      setting(c, at, section_ == kDecomposition ? Setting::kDecompositionDepth : Setting::kInterpretationDepth);
    } else if (key == "ringlsystem") {
      model_.items.push_back(Setting{Setting::kRing, code_at(at, "1"), token_at(at)});
    } else if (key == "axiom") {
      Axiom axiom;
      axiom.at = token_at(at);
      axiom.modules = module_string(c, nullptr, "the axiom");
      if (axiom.modules.empty()) c.fail_at(at, "the axiom cannot be empty");
      seen_axiom_ = true;
      model_.items.push_back(std::move(axiom));
    } else if (key == "ignore" || key == "consider") {
      Block& block = blocks_.back();
      if (!block.filter_chars.empty()) c.fail_at(at, "only one ignore: or consider: statement is supported");
      block.filter_consider = key == "consider";
      block.filter_at = token_at(at);
      // Characters, as cpfg's ignore table has them.
      while (!c.done()) block.filter_chars.insert(c.get());
    } else if (key == "seed") {
      if (section_ == kDecomposition) c.fail_at(at, "seed: cannot be used in a decomposition (CPFG manual 4.4)");
      if (section_ == kHomomorphism && blocks_.back().homomorphism_rules)
        c.fail_at(at, "a homomorphism's seed: comes before its productions");
      // An expression, taken as an integer.
      Scope scope = new_scope();
      c.skip_space();
      const std::size_t first = c.at();
      if (const std::string error = range_error("the seed", c.text().substr(first), true); !error.empty())
        c.fail_at(c.pos_at(first), error);
      const std::string seed = "static_cast<long>(static_cast<int>(" + cpfg::expression(c, scope) + "))";
      if (!c.done()) c.fail("expected the end of the seed: statement");
      globals_.insert(scope.locals.begin(), scope.locals.end());
      if (section_ == kHomomorphism) {
        // The homomorphism's own stream for ran() and its kin.
        blocks_.back().homomorphism_seed = seed;
      } else {
        // The L-system's productions are chosen at random; the seed matters
        // only as cpfg's window seeds (cpfg_random_code.cpp).
        blocks_.back().stochastic = true;
        blocks_.back().production_seed = seed;
      }
    } else if (key == "define") {
      define(c);
    } else if (key == "start" || key == "starteach" || key == "endeach" || key == "end") {
      Scope scope = new_scope();
      scope.control_block = true;
      c.expect("{", "'{' to begin the block");
      // Each block in braces of its own: several (one per L-system) run in turn.
      std::string body = "{ " + cpfg::statements(c, scope) + "} ";
      globals_.insert(scope.locals.begin(), scope.locals.end());  // unknown names read as 0
      c.accept(";");
      if (!c.done()) c.fail("expected the end of the line after the block");
      ControlStatement::Kind kind = key == "start"       ? ControlStatement::kStart
                                    : key == "starteach" ? ControlStatement::kStartEach
                                    : key == "endeach"   ? ControlStatement::kEndEach
                                                         : ControlStatement::kEnd;
      control_[kind] += body;
      control_at_[kind] = at;
    } else if (key == "decomposition") {
      if (section_ == kHomomorphism) c.fail_at(at, "decomposition: must come before homomorphism:");
      section_ = kDecomposition;
    } else if (key == "homomorphism") {
      section_ = kHomomorphism;
    } else if (key == "endhomomorphism" || key == "enddecomposition") {
      // tolerated
    }
  }

  void setting(Cursor& c, Pos at, Setting::Kind kind) {
    Scope scope = new_scope();
    c.skip_space();
    const std::size_t first = c.at();
    const std::string written = c.text().substr(first);
    if (const std::string error = setting_range_error(kind, written); !error.empty()) c.fail_at(c.pos_at(first), error);
    std::string e = cpfg::expression(c, scope);
    if (!c.done()) c.fail("expected the end of the statement");
    globals_.insert(scope.locals.begin(), scope.locals.end());  // unknown names read as 0
    model_.items.push_back(Setting{kind, code_at(at, "(" + e + ")"), token_at(at)});
  }

  void define(Cursor& c) {
    c.expect("{", "'{' after 'define:'");
    std::string text;
    while (!c.accept("}")) {
      c.skip_space();
      std::string word;
      while (std::isalpha(static_cast<unsigned char>(c.peek()))) word += c.get();
      if (word != "array") c.fail("expected 'array name[size]' in define:");
      c.skip_space();
      std::string name;
      while (std::isalnum(static_cast<unsigned char>(c.peek())) || c.peek() == '_') name += c.get();
      if (name.empty()) c.fail("expected an array name");
      c.expect("[", "'[' and the array's dimensions");
      std::string dims;
      do {
        c.skip_space();
        std::string n;
        while (std::isdigit(static_cast<unsigned char>(c.peek()))) n += c.get();
        if (n.empty()) c.fail("expected an integer dimension");
        dims += "[" + n + "]";
      } while (c.accept(","));
      c.expect("]", "']'");
      text += "[[maybe_unused]] double " + cpfg::variable(name) + dims;
      if (c.accept("=")) {
        c.expect("{", "'{' and the array's values");
        Scope scope;
        scope.warnings = &model_.warnings;
        text += " = {";
        do text += "(" + cpfg::expression(c, scope) + "),";
        while (c.accept(","));
        c.expect("}", "'}' after the values");
        text += "}";
      }
      text += ";\n";
      c.expect(";", "';' after the array");
      arrays_.insert(name);
    }
    model_.items.push_back(Code{verbatim(c.pos(), "namespace {\n" + text + "}\n")});
  }

  // ---- modules ---------------------------------------------------------------

  // One cpfg symbol: a character, or a multi-character turtle symbol.
  std::string symbol(Cursor& c) {
    std::string s = joined_symbol(c);
    // A symbol read split: its first character now, the rest as symbols of their own.
    if (s.size() > 1 && split_.count(s)) {
      c.set(c.at() - (s.size() - 1));
      s.resize(1);
    }
    return s;
  }

  std::string joined_symbol(Cursor& c) {
    c.skip_space();
    const Pos p = c.pos();
    char ch = c.get();
    if (ch == '\0') c.fail_at(p, "expected a symbol");
    if (ch == '*' ) c.fail_at(p, "'*' is not a symbol (it stands for an empty successor or condition)");
    if (ch == '(' || ch == ')') c.fail_at(p, std::string("expected a symbol, found '") + ch + "'");
    std::string s(1, ch);
    if (ch == '@') {
      for (const char* tail : kAtSymbols)
        if (c.starts_with(tail)) {
          s += tail;
          c.set(c.at() + std::char_traits<char>::length(tail));
          return s;
        }
      if (!is_separator(c.peek())) s += c.get();
    } else if (ch == '?') {
      // ?( is a sub-L-system call ?(label,scale); ?P ?H ?L ?U are queries.
      if (std::isalpha(static_cast<unsigned char>(c.peek()))) s += c.get();
    } else if (ch == '~') {
      // ~id: the view file's surface id (CPFG manual 6.7.1), one character.
      if (is_separator(c.peek()) || c.peek() == '(' || c.peek() == ')')
        c.fail_at(p, "expected a surface id after '~'");
      s += c.get();
    }
    return s;
  }

  std::string module_name(const std::string& sym, std::size_t params, Pos at, Cursor& c) {
    if (sym == "[" || sym == "]" || sym == "%") {
      if (params) c.fail_at(at, "'" + sym + "' takes no parameters");
      return sym == "[" ? "SB" : sym == "]" ? "EB" : "Cut";
    }
    std::string name = mangle(sym, params);
    if (!module_index_.count(name)) {
      ModuleDecl decl{name, std::vector<std::string>(params, "float"), token_at(at), sym};
      module_index_[name] = model_.modules.size();
      model_.modules.push_back(decl);
      by_symbol_[sym].push_back(name);
    }
    return name;
  }

  // @L("format", p1, ...): a const char* (the literal, kept by the compiled
  // model) and `params - 1` floats.
  std::string label_module(std::size_t params, Pos at) {
    const std::string name = mangle("@L", params);
    if (!module_index_.count(name)) {
      std::vector<std::string> types(params, "float");
      types[0] = "const char*";
      module_index_[name] = model_.modules.size();
      model_.modules.push_back(ModuleDecl{name, types, token_at(at), "@L"});
      by_symbol_["@L"].push_back(name);
    }
    return name;
  }

  // A "..." literal (the cursor at its quote), returned as written.
  static std::string string_literal(Cursor& c) {
    const Pos start = c.pos();
    std::string text(1, c.get());
    while (true) {
      const char ch = c.get();
      if (ch == '\0') c.fail_at(start, "unterminated string");
      text += ch;
      if (ch == '"') return text;
      if (ch == '\\') {
        const char next = c.get();
        if (next == '\0') c.fail_at(start, "unterminated string");
        text += next;
      }
    }
  }

  // Modules up to the end of the line or a stop token (":" after a successor).
  std::vector<ModuleCall> module_string(Cursor& c, Scope* scope, const char* what) {
    std::vector<ModuleCall> calls;
    Scope constants = new_scope();
    Scope& s = scope ? *scope : constants;
    while (!c.done()) {
      if (c.peek() == ':') break;
      const Pos p = c.pos();
      if (c.peek() == '*' && calls.empty()) {
        c.get();
        if (!c.done() && c.peek() != ':') c.fail("expected the end of the successor after '*'");
        break;
      }
      std::string sym = symbol(c);
      std::vector<Code> args;
      bool label = false;  // @L("format", p1, ...): a string, then floats
      if (c.peek() == '(') {
        c.get();
        do {
          c.skip_space();
          const Pos ap = c.pos();
          if (c.peek() == '"') {
            if (sym != "@L" || !args.empty())
              c.fail_at(ap, "string parameters (" + sym + "(\"...\")) are supported only as the first of @L");
            // The literal as written is a C string literal: the compiled model keeps it.
            args.push_back(code_at(ap, string_literal(c)));
            label = true;
            continue;
          }
          const std::string e = cpfg::expression(c, s);
          if (sym == "?" && args.empty()) {
            // A constant label is checked once every L-system is known.
            char* end = nullptr;
            const double label = std::strtod(e.c_str(), &end);
            if (!e.empty() && *end == '\0') calls_.push_back({label, ap});
          }
          args.push_back(code_at(ap, "static_cast<float>(" + e + ")"));
        } while (c.accept(","));
        c.expect(")", std::string("',' or ')' in the parameters of ") + sym + " in " + what);
      }
      // A bare @L is a module without parameters: nothing to print.
      if (sym == "@L" && !label && !args.empty())
        c.fail_at(p, "@L takes a string first: @L(\"label\") or @L(\"format\",p1,...)");
      ModuleCall call;
      call.name = label ? label_module(args.size(), p) : module_name(sym, args.size(), p, c);
      call.args = std::move(args);
      call.at = token_at(p);
      calls.push_back(std::move(call));
    }
    // Unknown names in the axiom read as 0, as new globals.
    if (!scope) globals_.insert(constants.locals.begin(), constants.locals.end());
    return calls;
  }

  bool at_arrow(Cursor& c) {
    c.skip_space();
    return c.starts_with("-->") || c.starts_with("->");
  }

  // Pattern modules up to '<', '>', ':' or the arrow.
  std::vector<PatternModule> pattern(Cursor& c, Scope& scope, bool right_context) {
    std::vector<PatternModule> modules;
    while (true) {
      c.skip_space();
      const char ch = c.peek();
      if (ch == '\0') c.fail("expected '-->' after the predecessor");
      if (ch == '<' || ch == '>' || ch == ':' || at_arrow(c)) break;
      const Pos p = c.pos();
      if (ch == '=') {
        // cpfg's "=": the rest of the branch, before its ']'.
        c.get();
        c.skip_space();
        if (!right_context || c.peek() != ']') c.fail_at(p, "'=' is supported only before ']' in a right context");
        continue;
      }
      std::string sym = symbol(c);
      if (sym.size() == 1) lone_pattern_symbols_.insert(sym[0]);
      if (sym == "@L" && c.peek() == '(') c.fail_at(p, "@L(...) in a predecessor is not supported yet");
      std::vector<std::string> formals;
      if (c.peek() == '(') {
        c.get();
        do {
          c.skip_space();
          std::string name;
          const Pos fp = c.pos();
          while (std::isalnum(static_cast<unsigned char>(c.peek())) || c.peek() == '_') name += c.get();
          if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])))
            c.fail_at(fp, "expected a formal parameter name in the predecessor");
          scope.formals.insert(name);
          formals.push_back(cpfg::variable(name));
        } while (c.accept(","));
        c.expect(")", "',' or ')' after the formal parameters");
      }
      PatternModule m;
      m.name = module_name(sym, formals.size(), p, c);
      m.formals = std::move(formals);
      m.at = token_at(p);
      modules.push_back(std::move(m));
    }
    return modules;
  }

  void production(Cursor& c, Pos at) {
    if (!seen_axiom_ && section_ == kProductions && blocks_.size() == 1)
      c.fail_at(at, "expected 'Axiom:' before the productions");
    Rule rule;
    rule.kind = section_ == kProductions   ? abi::RuleKind::Production
                : section_ == kDecomposition ? abi::RuleKind::Decomposition
                                             : abi::RuleKind::Interpretation;
    rule.at = token_at(at);
    Scope scope = new_scope();
    // A context written `*` is no context (cpfg reads `*` among symbols as "nothing").
    if (c.accept("*")) {
      if (!c.accept("<")) c.fail("expected '<' after '*' (an empty left context)");
    } else {
      std::vector<PatternModule> first = pattern(c, scope, false);
      if (c.accept("<")) rule.parts[abi::kLeft] = std::move(first);
      else rule.parts[abi::kStrict] = std::move(first);
    }
    if (rule.parts[abi::kStrict].empty()) rule.parts[abi::kStrict] = pattern(c, scope, false);
    if (rule.parts[abi::kStrict].empty())
      c.fail_at(at, "expected a strict predecessor (a production: predecessor --> successor)");
    if (c.accept(">")) {
      if (c.accept("*")) {
        c.skip_space();
        if (c.peek() != ':' && !at_arrow(c)) c.fail("expected ':' or '-->' after '*' (an empty right context)");
      } else {
        rule.parts[abi::kRight] = pattern(c, scope, true);
      }
    }
    if (c.peek() == '<' || c.peek() == '>') c.fail("expected ':' or '-->'");

    std::string before, condition = "true", after;
    if (c.accept(":")) {
      if (c.accept("{")) before = cpfg::statements(c, scope);
      c.skip_space();
      if (c.accept("*")) {
      } else if (!c.starts_with("{") && !at_arrow(c)) {
        condition = cpfg::expression(c, scope);
      }
      if (c.accept("{")) after = cpfg::statements(c, scope);
    }
    c.skip_space();
    if (!c.accept("-->") && !c.accept("->")) c.fail("expected '-->' between the predecessor and the successor");
    std::vector<ModuleCall> successor = module_string(c, &scope, "the successor");
    // The probability: an expression, evaluated once the predecessor matched.
    std::string probability = "1.0";
    if (c.accept(":")) {
      c.skip_space();
      const Pos p = c.pos();
      probability = cpfg::expression(c, scope);
      if (!blocks_.back().stochastic)
        warn(p, "probability ignored: the L-system has no seed:, so its productions are not chosen at random");
      else if (rule.kind != abi::RuleKind::Production)
        warn(p, "probability ignored: cpfg applies the first decomposition or homomorphism production that matches");
    }
    if (!c.done()) c.fail("expected the end of the production");

    // Stochastic productions (CPFG manual 4.5), as cpfg chooses: the
    // derivation first probes which productions apply, each evaluating its
    // probability; the module's draw times their total, less each one's
    // probability in turn, picks the first to take it to 0 or below.
    const bool stochastic = rule.kind == abi::RuleKind::Production && blocks_.back().stochastic;
    const std::string number = std::to_string(rules_.size());
    std::string text;
    if (stochastic) text += "if (!::sylva::rt::cpfg::probing && sylva_cpfg_chosen != " + number + ") return; ";
    else if (rule.kind == abi::RuleKind::Production) text += "if (::sylva::rt::cpfg::probing) return; ";
    if (rule.kind == abi::RuleKind::Interpretation && !blocks_.back().homomorphism_seed.empty())
      text += "::sylva::rt::cpfg::StreamSwap sylva_own_stream(::sylva::rt::cpfg::random.stream, "
              "sylva_cpfg_homomorphism_stream[" + std::to_string(blocks_.size() - 1) + "]); ";
    if (rule.kind == abi::RuleKind::Interpretation) blocks_.back().homomorphism_rules = true;
    // cpfg keeps every variable in one table: what a production's statements
    // assign keeps its value into the next module's production (a loop that
    // does not run leaves the last module's value).
    globals_.insert(scope.locals.begin(), scope.locals.end());
    text += before;
    if (condition != "true") text += "if (!(" + condition + ")) return; ";
    if (stochastic)
      text += "if (::sylva::rt::cpfg::probing) { sylva_cpfg_applies(" + number + ", static_cast<float>(" + probability +
              ")); return; } ";
    text += after;
    if (!text.empty()) rule.body.push_back(BodyPart{BodyPart::kCode, code_at(at, text), {}, token_at(at)});
    rule.body.push_back(BodyPart{BodyPart::kProduce, {}, std::move(successor), token_at(at)});
    rules_.push_back(model_.items.size());
    rule_blocks_.push_back(blocks_.size() - 1);
    model_.items.push_back(std::move(rule));
  }

  void finish() {
    // ignore: / consider: name characters. A module type is named when
    // every character of its symbol is (@o by @ and o). Each L-system has its own.
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
      const Block& block = blocks_[b];
      if (block.filter_chars.empty()) continue;
      ContextFilter filter;
      filter.consider = block.filter_consider;
      filter.at = block.filter_at;
      if (block.filter_chars.count('[')) filter.names.push_back("SB");
      if (block.filter_chars.count(']')) filter.names.push_back("EB");
      if (block.filter_chars.count('%')) filter.names.push_back("Cut");
      for (const auto& [sym, names] : by_symbol_) {
        const bool named = std::all_of(sym.begin(), sym.end(), [&](char ch) { return block.filter_chars.count(ch) > 0; });
        if (named) filter.names.insert(filter.names.end(), names.begin(), names.end());
      }
      const int index = static_cast<int>(model_.filters.size());
      model_.filters.push_back(filter);
      for (std::size_t r = 0; r < rules_.size(); ++r)
        if (rule_blocks_[r] == b) std::get<Rule>(model_.items[rules_[r]]).filter = index;
    }
    // Sub-L-systems (CPFG manual 7.2): rules carry their L-system's label.
    const std::string call = mangle("?", 2), ret = mangle("$", 0);
    if (blocks_.size() > 1 || module_index_.count(call)) {
      for (const auto& [label, at] : calls_) {
        const bool known = std::any_of(blocks_.begin(), blocks_.end(), [&label = label](const Block& b) { return b.label == label; });
        if (!known) {
          std::ostringstream text;
          text << "?(" << label << ",...) calls L-system " << label << ", but no 'Lsystem: " << label
               << "' is defined";
          throw ModelError(SourceLocation{model_.files[static_cast<std::size_t>(at.file)], at.line, at.column},
                           text.str());
        }
      }
      model_.cpfg_sub_lsystems = true;
      model_.main_lsystem = blocks_.front().label;
      for (const Block& b : blocks_) model_.lsystem_labels.push_back(b.label);
      if (module_index_.count(call)) model_.call_module = call;
      if (module_index_.count(ret)) model_.return_module = ret;
      for (std::size_t r = 0; r < rules_.size(); ++r)
        std::get<Rule>(model_.items[rules_[r]]).group = blocks_[rule_blocks_[r]].label;
    }
    random_streams();
    // Globals, declared before everything that uses them.
    std::string globals = "namespace {\n";
    for (const std::string& g : globals_) globals += "[[maybe_unused]] double " + cpfg::variable(g) + " = 0;\n";
    globals += "}\n";
    model_.items.insert(model_.items.begin(), Code{verbatim(lines_.front().pos.front(), globals)});
    for (auto& [kind, body] : control_) {
      ControlStatement statement;
      statement.kind = static_cast<ControlStatement::Kind>(kind);
      statement.at = token_at(control_at_[kind]);
      statement.body.push_back(BodyPart{BodyPart::kCode, code_at(control_at_[kind], "{ " + body + "}"), {}, statement.at});
      model_.items.push_back(std::move(statement));
    }
  }

  // The random streams' code, and their start in the Start statement.
  void random_streams() {
    const Pos first = lines_.front().pos.front();
    std::vector<cpfg::LsystemRandomness> lsystems;
    for (const Block& b : blocks_) lsystems.push_back(cpfg::LsystemRandomness{b.label, b.stochastic, b.production_seed, b.homomorphism_seed});
    const cpfg::RandomCode code = cpfg::random_code(lsystems, rules_.size());
    model_.items.insert(model_.items.begin(), Code{verbatim(first, code.declarations)});
    model_.cpfg_stochastic = code.chooses;
    control_[ControlStatement::kStart] = code.start + control_[ControlStatement::kStart];
    if (!control_at_.count(ControlStatement::kStart)) control_at_[ControlStatement::kStart] = first;
    if (!code.restarts_streams) return;
    // The engine asks for the interpretation depth once at the start of
    // every interpretation pass: the homomorphisms' streams restart there.
    bool has_depth = false;
    for (Item& item : model_.items) {
      Setting* setting = std::get_if<Setting>(&item);
      if (!setting || setting->kind != Setting::kInterpretationDepth) continue;
      setting->expression.front().text = "(sylva_cpfg_restart_streams(), " + setting->expression.front().text + ")";
      has_depth = true;
    }
    if (!has_depth)
      model_.items.push_back(
          Setting{Setting::kInterpretationDepth, code_at(first, "(sylva_cpfg_restart_streams(), 1)"), token_at(first)});
  }

  void warn(Pos p, const std::string& text) {
    model_.warnings.push_back(model_.files[static_cast<std::size_t>(p.file)] + ":" + std::to_string(p.line) + ":" +
                              std::to_string(p.column) + ": warning: " + text);
  }

  enum Section { kProductions, kDecomposition, kHomomorphism };

  Model model_;
  std::vector<Line> lines_;
  std::set<std::string> split_;          // symbols read a character a module
  std::set<char> lone_pattern_symbols_;  // one-character symbols in predecessors and contexts
  std::map<std::string, std::size_t> module_index_;
  std::map<std::string, std::vector<std::string>> by_symbol_;
  std::set<std::string> globals_, arrays_;
  // One per Lsystem: ... endlsystem; the first is the main L-system.
  struct Block {
    int label = 0;
    std::set<char> filter_chars;
    bool filter_consider = false;
    Token filter_at;
    // A seed: statement makes the L-system's productions stochastic.
    bool stochastic = false;
    std::string homomorphism_seed;  // C++ of the homomorphism's seed:; empty without one
    std::string production_seed;    // C++ of the L-system's seed:; empty without one
    bool homomorphism_rules = false;
  };
  std::vector<Block> blocks_;
  std::vector<std::pair<double, Pos>> calls_;  // ?(label,s) with a constant label
  std::vector<std::size_t> rules_;
  std::vector<std::size_t> rule_blocks_;  // the block of each of rules_
  std::map<int, std::string> control_;
  std::map<int, Pos> control_at_;
  Section section_ = kProductions;
  bool seen_lsystem_ = false, seen_end_ = false, seen_axiom_ = false;
};

}  // namespace

Model parse_cpfg(const std::string& preprocessed, const std::string& main_file) {
  // cpfg's string is one module a character; the turtle reads @o, ?P and
  // their kin from the characters that follow @, ? or ~. Sylva keeps such a
  // symbol as one module, unless a production names one of its characters on
  // its own: then the model is read again with those symbols split.
  CpfgParser joined(preprocessed, main_file);
  Model model = joined.parse();
  std::set<std::string> split = joined.symbols_to_split();
  if (split.empty()) return model;
  return CpfgParser(preprocessed, main_file, std::move(split)).parse();
}

}  // namespace sylva::lang
