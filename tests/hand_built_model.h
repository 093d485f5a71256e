// A model descriptor built by hand, for running the engine without the
// translator or a C++ compiler: module types with float parameters, rules
// whose bodies are plain C++ functions, and an axiom function. Every field of
// the descriptor this builder does not set keeps its zero default, so fields
// added to the ABI later need no change here.
#pragma once

#include <cstdint>
#include <deque>
#include <initializer_list>
#include <string>
#include <vector>

#include "sylva/abi.h"
#include "sylva/predefined_ids.h"

namespace sylva::test {

// One module to write: its id and its float parameters.
struct Written {
  abi::ModuleId id;
  std::vector<float> params = {};
};

// Appends modules to a buffer (an axiom's or a rule's successor).
void write_modules(abi::ModuleBuffer* out, std::initializer_list<Written> modules);
// A body's `produce`: appends the successor and marks the rule as applied.
void produce(abi::RuleCall* call, std::initializer_list<Written> modules);
// The k-th float parameter of the i-th module of the rule's pattern.
float param(const unsigned char* const* params, int module, int k = 0);

using RuleBody = void (*)(abi::RuleCall*, const unsigned char* const*);

// A rule's pattern, part by part (abi::PatternPart order).
struct Pattern {
  std::vector<abi::ModuleId> new_left = {}, left = {}, strict = {}, right = {}, new_right = {};
};

class HandBuiltModel {
 public:
  // The predefined modules come first, with the engine's own ids (SB, EB ...).
  HandBuiltModel();
  HandBuiltModel(const HandBuiltModel&) = delete;
  HandBuiltModel& operator=(const HandBuiltModel&) = delete;

  // A module type with `float_params` float parameters; returns its id.
  abi::ModuleId module(const std::string& name, int float_params = 0);

  void rule(abi::RuleKind kind, const Pattern& pattern, RuleBody body, int group = 0);
  void production(const Pattern& pattern, RuleBody body) { rule(abi::RuleKind::Production, pattern, body); }
  // An ignore: (consider = false) or consider: statement in force for the
  // rules added after it; an empty list ends it.
  void filter(bool consider, std::vector<abi::ModuleId> ids);

  void set_axiom(void (*axiom)(abi::ModuleBuffer*)) { axiom_ = axiom; }
  void set_decomposition_depth(int (*depth)()) { decomposition_depth_ = depth; }
  void set_derivation_length(int (*length)()) { derivation_length_ = length; }

  abi::ControlState& control() { return control_; }
  // The descriptor of everything added so far (rebuilt on each call).
  const abi::ModelDescriptor& descriptor();

 private:
  struct RuleEntry {
    abi::RuleKind kind;
    int group;
    int filter;
    std::vector<abi::ModuleId> pattern;
    std::uint16_t part_length[abi::kPatternParts];
    RuleBody body;
  };

  std::deque<std::string> names_;  // the module types' names, kept in place
  std::vector<abi::ModuleType> modules_;
  std::vector<RuleEntry> rule_entries_;
  std::vector<abi::Rule> rules_;
  std::deque<std::vector<abi::ModuleId>> filter_ids_;
  std::vector<abi::ContextFilter> filters_;
  int current_filter_ = -1;
  void (*axiom_)(abi::ModuleBuffer*) = nullptr;
  int (*decomposition_depth_)() = nullptr;
  int (*derivation_length_)() = nullptr;
  abi::ControlState control_;
  abi::ModelDescriptor descriptor_{};
};

}  // namespace sylva::test
