// Internal to the L+C front end (not part of lc_parser.h): the LcParser class
// shared by lc_parser.cpp (file-scope constructs, groups, structs) and
// lc_rule_parser.cpp (rules, bodies, module lists), with its token access,
// error reporting and module lookup helpers.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include "lang/model_ir.h"
#include "lang/token.h"

namespace sylva::lang::detail {

using abi::RuleKind;

class LcParser {
 public:
  LcParser(const TokenStream& stream, const std::string& main_file);

  Model parse();

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

  // ---- L+C constructs at file scope (lc_parser.cpp) ---------------------------
  bool followed_by_colon(std::size_t ahead) const { return peek(ahead).is_punct(":"); }
  bool parse_construct();
  void open_group(bool gillespie);
  bool looks_like_rule() const;
  void parse_module_decl();
  Code parse_expression_until_semicolon(const std::string& what);
  void parse_setting(Setting::Kind kind, int keyword_tokens);
  // A group's or a view's number; `what` names it ("a group").
  int whole_number(const Token& number, const std::string& what) const;
  void switch_block(RuleKind kind);
  void parse_filter();
  void parse_verify_string();
  void parse_axiom();
  void parse_control(ControlStatement::Kind kind);

  // ---- structs, so their parameters print field by field (lc_parser.cpp) ------
  bool is_struct_definition() const;
  void parse_struct();
  static void add_fields(const Code& member, std::vector<std::string>& fields);

  // ---- rules (lc_rule_parser.cpp) ---------------------------------------------
  void parse_rule();
  PatternModule parse_pattern_module();

  // ---- module lists (axiom, produce) (lc_rule_parser.cpp) ----------------------
  std::vector<ModuleCall> parse_module_calls(const std::string& where);
  ModuleCall parse_module_call(const std::string& expected, const char* arity_verb);
  static std::string arity_message(const ModuleDecl& decl, std::size_t given, const char* verb);
  std::vector<Code> parse_arguments();

  // ---- bodies (lc_rule_parser.cpp) --------------------------------------------
  Body parse_body(bool produce_allowed, bool gillespie = false);
  BodyPart parse_propensity();
  bool propensity_statement_ahead() const;

  // ---- in-body context tests, LPFG manual 3.3 (lc_rule_parser.cpp) -------------
  bool in_context_test_ahead() const;
  static std::string in_context_misplaced(const Token& tok);
  BodyPart parse_in_context();
  Code parse_event_condition();
  void warn_of_equality(const Rule& rule);
  bool rate_statement_ahead() const;
  BodyPart parse_rate();
  void resolve_rates(Rule& rule);

  const TokenStream& stream_;
  const std::vector<Token>& t_;
  std::size_t i_ = 0;
  Model model_;
  Code code_;
  std::unordered_map<std::string, int> module_index_;
  RuleKind block_ = RuleKind::Production;
  bool in_derivative_rule_ = false;  // its body's `d(x) = ...;` are rates
  int group_ = 0;
  bool gillespie_ = false;  // group_ is a Gillespie group
  int view_ = 0;
  int filter_ = -1;
  SourceLocation first_verify_string_;
};

}  // namespace sylva::lang::detail
