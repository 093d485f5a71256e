#include "lang/lc_parser.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace sylva::lang {
namespace {

using abi::RuleKind;

bool is_open(const Token& t) { return t.is_punct("(") || t.is_punct("[") || t.is_punct("{"); }
bool is_close(const Token& t) { return t.is_punct(")") || t.is_punct("]") || t.is_punct("}"); }

class LcParser {
 public:
  LcParser(const TokenStream& stream, const std::string& main_file) : stream_(stream), t_(stream.tokens) {
    model_.files = stream.files;
    model_.main_file = main_file;
    for (const ModuleDecl& m : predefined_modules()) declare(m);
  }

  Model parse() {
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

 private:
  // ---- token access ---------------------------------------------------------
  const Token& peek(std::size_t ahead = 0) const {
    std::size_t k = std::min(i_ + ahead, t_.size() - 1);
    return t_[k];
  }
  const Token& next() {
    const Token& tok = peek();
    if (tok.kind != TokenKind::End) ++i_;
    return tok;
  }
  [[noreturn]] void fail(const Token& at, const std::string& message) const {
    SourceLocation where = stream_.location(at);
    // The end of the file has no column of its own: point just past the last token.
    if (at.kind == TokenKind::End && t_.size() >= 2 && t_[t_.size() - 2].kind != TokenKind::Verbatim) {
      const Token& last = t_[t_.size() - 2];
      where = stream_.location(last);
      where.column += static_cast<int>(last.text.size());
    }
    throw ModelError(where, message);
  }
  static std::string describe(const Token& t) {
    if (t.kind == TokenKind::End) return "end of file";
    if (t.kind == TokenKind::Verbatim) return "a preprocessor line";
    return "'" + t.text + "'";
  }
  const Token& expect_punct(const char* p, const std::string& what) {
    if (!peek().is_punct(p)) fail(peek(), "expected " + what + " before " + describe(peek()));
    return next();
  }
  const Token& expect_identifier(const std::string& what) {
    if (!peek().is_ident()) fail(peek(), "expected " + what + ", found " + describe(peek()));
    return next();
  }

  void flush_code() {
    if (!code_.empty()) model_.items.emplace_back(std::move(code_));
    code_.clear();
  }

  void declare(const ModuleDecl& decl) {
    module_index_[decl.name] = static_cast<int>(model_.modules.size());
    model_.modules.push_back(decl);
  }
  const ModuleDecl* find_module(const std::string& name) const {
    auto it = module_index_.find(name);
    return it == module_index_.end() ? nullptr : &model_.modules[it->second];
  }
  const ModuleDecl& require_module(const Token& name) const {
    const ModuleDecl* m = find_module(name.text);
    if (!m) fail(name, "undeclared module '" + name.text + "' (declare it with 'module " + name.text + "(...);')");
    return *m;
  }

  // ---- L+C constructs at file scope ------------------------------------------
  bool followed_by_colon(std::size_t ahead) const { return peek(ahead).is_punct(":"); }

  bool parse_construct() {
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
    }
    if (w == "maximum" && peek(1).is_ident("depth") && followed_by_colon(2)) {
      if (block_ == RuleKind::Production) fail(tok, "'maximum depth:' belongs in a decomposition: or interpretation: block");
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
      view_ = std::stoi(peek(1).text, nullptr, 0);
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
  void open_group(bool gillespie) {
    flush_code();
    const Token& number = peek(1);
    const int group = std::stoi(number.text, nullptr, 0);
    const std::string name = std::to_string(group);
    if (gillespie && group == 0) fail(number, "group 0 is the main group and cannot be a Gillespie group");
    if (gillespie && regular_groups_.count(group))
      fail(number, "group " + name + " is already a regular group ('group " + name +
                       ":'); a Gillespie group needs a number of its own");
    if (!gillespie && gillespie_groups_.count(group))
      fail(number, "group " + name + " is already a Gillespie group ('ggroup " + name +
                       ":'); a regular group needs a number of its own");
    (gillespie ? gillespie_groups_ : regular_groups_).insert(group);
    if (gillespie && std::find(model_.gillespie_groups.begin(), model_.gillespie_groups.end(), group) ==
                         model_.gillespie_groups.end())
      model_.gillespie_groups.push_back(group);
    if (std::find(model_.groups.begin(), model_.groups.end(), group) == model_.groups.end())
      model_.groups.push_back(group);
    group_ = group;
    gillespie_ = gillespie;
    i_ += 3;
  }

  // `Name(...) ... : {` with only pattern tokens before the colon: a rule whose
  // first module was never declared.
  bool looks_like_rule() const {
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

  void parse_module_decl() {
    flush_code();
    next();  // module
    const Token& name = expect_identifier("a module name");
    if (const ModuleDecl* existing = find_module(name.text)) {
      if (existing->at.kind == TokenKind::End) fail(name, "'" + name.text + "' is a predefined module and cannot be redeclared");
      fail(name, "module '" + name.text + "' is already declared");
    }
    ModuleDecl decl{name.text, {}, name};
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

  Code parse_expression_until_semicolon(const std::string& what) {
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

  void parse_setting(Setting::Kind kind, int keyword_tokens) {
    flush_code();
    Token at = peek();
    i_ += keyword_tokens;
    Code expr = parse_expression_until_semicolon(at.text);
    model_.items.emplace_back(Setting{kind, std::move(expr), at});
  }

  void switch_block(RuleKind kind) {
    flush_code();
    i_ += 2;
    block_ = kind;
  }

  void parse_filter() {
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
  void parse_verify_string() {
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

  void parse_axiom() {
    flush_code();
    Axiom axiom;
    axiom.at = next();
    next();  // :
    axiom.modules = parse_module_calls("the axiom");
    model_.items.emplace_back(std::move(axiom));
  }

  void parse_control(ControlStatement::Kind kind) {
    flush_code();
    ControlStatement statement{kind, {}, next()};
    next();  // :
    statement.body = parse_body(false);
    if (peek().is_punct(";")) next();
    model_.items.emplace_back(std::move(statement));
  }

  // ---- module lists (axiom, produce) ------------------------------------------
  // Reads `A(x, y) B C(z)` up to and including the ';'.
  std::vector<ModuleCall> parse_module_calls(const std::string& where) {
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
      ModuleCall call;
      call.at = tok;
      if (tok.is_punct("[") || tok.is_punct("]")) {
        call.name = tok.is_punct("[") ? "SB" : "EB";
        next();
        calls.push_back(std::move(call));
        continue;
      }
      if (!tok.is_ident()) fail(tok, "expected a module in " + where + ", found " + describe(tok));
      const ModuleDecl& decl = require_module(tok);
      call.name = next().text;
      if (peek().is_punct("(")) {
        next();
        call.args = parse_arguments();
      }
      if (call.args.size() != decl.param_types.size())
        fail(call.at, arity_message(decl, call.args.size(), "is given"));
      calls.push_back(std::move(call));
    }
    next();  // ;
    return calls;
  }

  // ---- in-body context tests (LPFG manual 3.3) --------------------------------
  bool in_context_test_ahead() const {
    const Token& tok = peek();
    return (tok.is_ident("InLeftContext") || tok.is_ident("InRightContext") || tok.is_ident("InNewLeftContext") ||
            tok.is_ident("InNewRightContext")) &&
           peek(1).is_punct("(");
  }
  static std::string in_context_misplaced(const Token& tok) {
    return "'" + tok.text + "' tests the context of a rule's predecessor: it is only allowed in the body of a "
           "production, decomposition or interpretation rule";
  }

  // `InLeftContext ( A(x) [ B(y, z) )`: modules as in a predecessor, each
  // parameter a variable of the body to receive it.
  BodyPart parse_in_context() {
    BodyPart test;
    test.kind = BodyPart::kInContext;
    test.at = next();
    const std::string& w = test.at.text;
    test.context = w == "InLeftContext"    ? abi::kLeft
                   : w == "InRightContext" ? abi::kRight
                   : w == "InNewLeftContext" ? abi::kNewLeft
                                             : abi::kNewRight;
    next();  // (
    while (!peek().is_punct(")")) {
      const Token& tok = peek();
      ModuleCall m;
      m.at = tok;
      if (tok.is_punct("[") || tok.is_punct("]")) {
        m.name = tok.is_punct("[") ? "SB" : "EB";
        next();
        test.modules.push_back(std::move(m));
        continue;
      }
      if (!tok.is_ident()) fail(tok, "expected a module or ')' in " + w + "(...), found " + describe(tok));
      const ModuleDecl& decl = require_module(tok);
      m.name = next().text;
      if (peek().is_punct("(")) {
        next();
        m.args = parse_arguments();
      }
      if (m.args.size() != decl.param_types.size())
        fail(m.at, arity_message(decl, m.args.size(), std::string(w + " names").c_str()));
      test.modules.push_back(std::move(m));
    }
    if (test.modules.empty()) fail(peek(), "expected the modules to look for in " + w + "(...)");
    next();  // )
    return test;
  }

  static std::string arity_message(const ModuleDecl& decl, std::size_t given, const char* verb) {
    return "module '" + decl.name + "' has " + std::to_string(decl.param_types.size()) + " parameter" +
           (decl.param_types.size() == 1 ? "" : "s") + " but " + verb + " " + std::to_string(given);
  }

  // After '(': arguments split at top-level commas, up to and including ')'.
  std::vector<Code> parse_arguments() {
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
  Body parse_body(bool produce_allowed, bool gillespie = false) {
    Body body;
    BodyPart code;
    code.kind = BodyPart::kCode;
    if (!peek().is_punct("{")) fail(peek(), "expected '{' to begin the body, found " + describe(peek()));
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
      if (tok.is_ident("produce") || tok.is_ident("nproduce")) {
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
  BodyPart parse_propensity() {
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
  bool propensity_statement_ahead() const {
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

  // ---- rules ------------------------------------------------------------------
  void parse_rule() {
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

    rule.body = parse_body(true, gillespie);
    if (peek().is_punct(";")) next();
    model_.items.emplace_back(std::move(rule));
  }

  PatternModule parse_pattern_module() {
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

  // ---- structs (so their parameters print field by field) ---------------------
  bool is_struct_definition() const {
    std::size_t k = 0;
    if (peek(k).is_ident("typedef")) ++k;
    if (!peek(k).is_ident("struct")) return false;
    ++k;
    if (peek(k).is_ident()) ++k;
    return peek(k).is_punct("{");
  }

  void parse_struct() {
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
  static void add_fields(const Code& member, std::vector<std::string>& fields) {
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

  const TokenStream& stream_;
  const std::vector<Token>& t_;
  std::size_t i_ = 0;
  Model model_;
  Code code_;
  std::unordered_map<std::string, int> module_index_;
  RuleKind block_ = RuleKind::Production;
  int group_ = 0;
  bool gillespie_ = false;  // group_ is a Gillespie group
  std::unordered_set<int> regular_groups_{0}, gillespie_groups_;
  int view_ = 0;
  int filter_ = -1;
  SourceLocation first_verify_string_;
};

}  // namespace

Model parse_lc(const TokenStream& tokens, const std::string& main_file) {
  return LcParser(tokens, main_file).parse();
}

}  // namespace sylva::lang
