// The Model IR: what a front end (L+C or cpfg) makes of a model, and what the
// C++ generator turns into a compiled model.
//
// A model is a sequence of items in source order. C++ the front end does not
// interpret is carried as Code (tokens with their positions) so that errors
// from the C++ compiler point at the user's file.
#pragma once

#include <array>
#include <string>
#include <variant>
#include <vector>

#include "lang/token.h"
#include "sylva/abi.h"

namespace sylva::lang {

// A run of C++ tokens kept with their source positions.
using Code = std::vector<Token>;

struct ModuleDecl {
  std::string name;
  std::vector<std::string> param_types;  // as written: "float", "CellData"
  Token at;
  // The name strings print (empty: `name`); cpfg symbols such as "+" or "?E"
  // have a C++-safe `name` and their own symbol here.
  std::string display_name;
};

// `Name(arg, ...)` in an axiom or a produce statement.
struct ModuleCall {
  std::string name;
  std::vector<Code> args;
  Token at;
};

// One module of a predecessor pattern, with the names bound to its parameters.
struct PatternModule {
  std::string name;
  std::vector<std::string> formals;
  Token at;
};

// A body is C++ with produce statements cut out of it.
struct BodyPart {
  // kPropensity: `propensity <code> produce <modules>;`, a reaction offered
  // by a production of a Gillespie group.
  // kInContext: `InLeftContext(A(x) B(y))` and its kin (LPFG manual 3.3),
  // an expression testing context; `modules` is the pattern, each argument
  // the variable its parameter is copied into.
  // kRate: `d(x) = <code>;` in a derivative rule, the rate of the strict
  // predecessor's parameter number `rate_index` (named `rate_of`).
  enum Kind { kCode, kProduce, kNProduce, kPropensity, kInContext, kRate } kind = kCode;
  Code code;                        // kCode; kPropensity: the propensity; kRate: the rate
  std::vector<ModuleCall> modules;  // kProduce, kNProduce, kPropensity, kInContext
  Token at;
  abi::PatternPart context = abi::kLeft;  // kInContext: which context it tests
  std::string rate_of = {};               // kRate
  int rate_index = -1;                    // kRate
};
using Body = std::vector<BodyPart>;

struct Rule {
  abi::RuleKind kind = abi::RuleKind::Production;
  int group = 0;
  int view = 0;  // vgroup (LPFG manual 7.3)
  int filter = -1;
  std::array<std::vector<PatternModule>, abi::kPatternParts> parts;
  Body body;
  Token at;
  // An event (RuleKind::Event): `when (condition)`, the instant it becomes true.
  Code event_condition;
};

struct Axiom {
  std::vector<ModuleCall> modules;
  Token at;
};

// derivation length:, maximum depth:, ring L-system: — an expression
// evaluated once the model has started.
struct Setting {
  enum Kind { kDerivationLength, kDecompositionDepth, kInterpretationDepth, kRing } kind;
  Code expression;
  Token at;
};

struct ControlStatement {
  enum Kind { kStart, kStartEach, kEndEach, kEnd } kind;
  Body body;
  Token at;
};

struct ContextFilter {
  bool consider = false;
  std::vector<std::string> names;
  Token at;
};

// A struct of the model, so module parameters of that type print field by field.
struct StructFields {
  std::string name;
  std::vector<std::string> fields;
  Token at;
};

using Item = std::variant<Code, ModuleDecl, Rule, Axiom, Setting, ControlStatement, StructFields>;

struct Model {
  std::vector<std::string> files;  // file names referred to by tokens
  std::string main_file;
  std::vector<Item> items;
  std::vector<ContextFilter> filters;  // referred to by Rule::filter
  // Modules the generator must know: the predefined ones, then the model's.
  std::vector<ModuleDecl> modules;
  // A cpfg model: formal parameters are doubles, parameters print as cpfg
  // prints them, the descriptor says so (abi::kModelCpfg).
  bool cpfg = false;
  // cpfg's stochastic draw: the model defines sylva_cpfg_before_module.
  bool cpfg_stochastic = false;
  // cpfg sub-L-systems (abi::kModelSubLsystems): Rule::group is the label of
  // a rule's L-system; `?(label,s)` and `$` are the modules named here.
  bool cpfg_sub_lsystems = false;
  int main_lsystem = 0;
  std::vector<int> lsystem_labels;
  std::string call_module, return_module;  // empty: the model has none
  // VerifyString: (LPFG manual 10.4): the module names the derived string
  // must have.
  bool has_verify_string = false;
  std::vector<std::string> verify_string;
  // The numbers of the Gillespie groups (ggroup N:, LPFG manual 7.2).
  std::vector<int> gillespie_groups;
  // The numbers of every group the model defines (group N: and ggroup N:).
  std::vector<int> groups;
  // What the reference program reads past with a warning, as
  // "file:line:column: warning: text", for the user to see.
  std::vector<std::string> warnings;
};

// The predefined modules of lpfgall.h, in id order.
const std::vector<ModuleDecl>& predefined_modules();

}  // namespace sylva::lang
