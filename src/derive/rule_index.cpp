#include "derive/rule_index.h"

namespace sylva::derive {

RuleIndex::RuleIndex(const abi::ModelDescriptor& model) {
  for (int kind = 0; kind < abi::kRuleKinds; ++kind) {
    forward_[kind].resize(model.module_count);
    backward_[kind].resize(model.module_count);
  }
  for (std::uint32_t r = 0; r < model.rule_count; ++r) {
    const abi::Rule& rule = model.rules[r];
    const int kind = static_cast<int>(rule.kind);
    const int strict_begin = rule.part_length[abi::kNewLeft] + rule.part_length[abi::kLeft];
    const int strict_length = rule.part_length[abi::kStrict];
    if (strict_length == 0) continue;
    forward_[kind][rule.pattern[strict_begin]].push_back(r);
    backward_[kind][rule.pattern[strict_begin + strict_length - 1]].push_back(r);
    ++count_[kind];
  }
}

}  // namespace sylva::derive
