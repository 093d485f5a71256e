// For each kind of rule and each module id, the rules that could rewrite a
// module of that id, in file order: those whose strict predecessor starts
// with it (forward matching) or ends with it (backward matching).
#pragma once

#include <cstdint>
#include <vector>

#include "derive/context_matcher.h"
#include "sylva/abi.h"

namespace sylva::derive {

class RuleIndex {
 public:
  RuleIndex() = default;
  RuleIndex(const abi::ModelDescriptor& model);

  // Rules (as indices into the model's rule table) for module `id`.
  const std::vector<std::uint32_t>& forward(abi::RuleKind kind, ModuleId id) const {
    return forward_[static_cast<int>(kind)][id];
  }
  const std::vector<std::uint32_t>& backward(abi::RuleKind kind, ModuleId id) const {
    return backward_[static_cast<int>(kind)][id];
  }
  bool has_rules(abi::RuleKind kind) const { return count_[static_cast<int>(kind)] > 0; }

 private:
  std::vector<std::vector<std::uint32_t>> forward_[abi::kRuleKinds];
  std::vector<std::vector<std::uint32_t>> backward_[abi::kRuleKinds];
  std::size_t count_[abi::kRuleKinds] = {};
};

}  // namespace sylva::derive
