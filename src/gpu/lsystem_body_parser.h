// From a production's tokens to the syntax tree (gpu/lsystem_tree.h): a
// recursive-descent parser of the C++ a production body may hold, typed as
// GLSL types. Its statements are in lsystem_body_parser.cpp, its
// expressions in lsystem_expression_parser.cpp. Private to src/gpu.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "gpu/lsystem_tree.h"
#include "lang/model_ir.h"
#include "lang/token.h"

namespace sylva::gpu {

using lang::Token;
using lang::TokenKind;

struct Unsupported {
  const Token* at;
  std::string what;
};

// A token of a body, or a produce statement cut out of it.
struct Tok {
  const Token* token;
  int produce = -1;
};

// The C++ type names (of declarations and casts), and the GLSL type of those translated.
bool is_type_name(const std::string& s);
std::optional<Type> type_named(const std::string& s);
// The functions that draw random numbers: a production calling one is stochastic.
const std::set<std::string>& random_functions();

class BodyParser {
 public:
  BodyParser(std::vector<Tok> toks, Production& production, const std::map<std::string, Expr>& constants,
             const std::vector<std::vector<lang::ModuleCall>>& produce_calls,
             const std::function<Produced(const lang::ModuleCall&, BodyParser&)>& produced)
      : toks_(std::move(toks)), p_(production), constants_(constants), produce_calls_(produce_calls),
        produced_(produced) {}

  // Scopes of names: the formals first.
  void declare_formal(const std::string& name, int slot) { scopes_.back()[name] = slot; }
  int new_slot(const std::string& name, Type t) {
    p_.slot_types.push_back(t);
    p_.slot_names.push_back(name);
    return static_cast<int>(p_.slot_types.size()) - 1;
  }

  Stmt parse_body();

  // An expression of the whole token list (a produce argument, a constant).
  Expr whole_expression();

  void reset(std::vector<Tok> toks) {
    toks_ = std::move(toks);
    at_ = 0;
  }

  [[noreturn]] void fail(const std::string& what) const { throw Unsupported{&here(), what}; }
  [[noreturn]] void fail_at(const Token& t, const std::string& what) const { throw Unsupported{&t, what}; }

  static Expr convert(Expr e, Type to);
  // Converts for an assignment to, or a parameter of, type `to` (C++'s implicit conversions).
  Expr assign_convert(Expr e, Type to, const Token& at) const;

  // ---- expressions (C++ precedence)
  Expr expression();
  static Expr literal(Type t, double v);
  Expr to_bool(Expr e) const;
  // The usual arithmetic conversions and the vectors' operators.
  Expr binary(char op, Expr a, Expr b, const Token& at) const;

 private:
  const Token& here() const { return at_ < toks_.size() ? *toks_[at_].token : *toks_.back().token; }
  const Token& tok() const { return here(); }
  bool at_end() const { return at_ >= toks_.size(); }
  bool is_punct(const char* p, std::size_t ahead = 0) const {
    return at_ + ahead < toks_.size() && toks_[at_ + ahead].produce < 0 && toks_[at_ + ahead].token->is_punct(p);
  }
  bool is_ident(const char* p, std::size_t ahead = 0) const {
    return at_ + ahead < toks_.size() && toks_[at_ + ahead].produce < 0 && toks_[at_ + ahead].token->is_ident(p);
  }
  bool is_any_ident(std::size_t ahead = 0) const {
    return at_ + ahead < toks_.size() && toks_[at_ + ahead].produce < 0 && toks_[at_ + ahead].token->is_ident();
  }
  const Token& next() {
    if (at_end()) fail("the body ends too early");
    return *toks_[at_++].token;
  }
  void expect(const char* p) {
    if (!is_punct(p)) fail(std::string("expected '") + p + "', found " + (at_end() ? "the end" : "'" + tok().text + "'"));
    ++at_;
  }

  int lookup(const std::string& name) const {
    for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s)
      if (auto f = s->find(name); f != s->end()) return f->second;
    return -1;
  }

  // ---- statements (lsystem_body_parser.cpp)
  Stmt statement();
  Stmt increment(char op);
  Stmt increment_slot(char op, int slot);
  Stmt declaration();
  int produce_index(int cut);

  // ---- expressions (lsystem_expression_parser.cpp)
  Expr ternary();
  Expr logical_or();
  Expr binary_level(std::size_t level);
  Expr unary();
  Expr postfix(Expr e);
  int field_index(const Token& member, Type t) const;
  static Expr field_of(Expr e, int field);
  Expr var(int slot) const;
  std::vector<Expr> arguments();  // ( expression, ... )
  Expr construct(Type t, const Token& at);
  Expr primary();
  Expr call(const std::string& name, const Token& at);
  Expr number(const Token& t);

  std::vector<Tok> toks_;
  std::size_t at_ = 0;
  Production& p_;
  const std::map<std::string, Expr>& constants_;
  const std::vector<std::vector<lang::ModuleCall>>& produce_calls_;
  const std::function<Produced(const lang::ModuleCall&, BodyParser&)>& produced_;
  std::vector<std::map<std::string, int>> scopes_{1};
  std::vector<int> produced_index_;
};

}  // namespace sylva::gpu
