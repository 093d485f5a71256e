#include "hand_built_model.h"

#include <cstdio>
#include <cstring>

#include "lstring/module_types.h"

namespace sylva::test {
namespace {

// "p1,p2,..." as %g, for a module of N float parameters.
template <int N>
void format_floats(const unsigned char* params, abi::TextSink* out) {
  for (int k = 0; k < N; ++k) {
    float value;
    std::memcpy(&value, params + k * sizeof(float), sizeof value);
    char text[32];
    std::snprintf(text, sizeof text, "%s%g", k ? "," : "", static_cast<double>(value));
    out->write(text);
  }
}

using Formatter = void (*)(const unsigned char*, abi::TextSink*);
constexpr Formatter kFormatters[] = {&format_floats<0>, &format_floats<1>, &format_floats<2>, &format_floats<3>};

}  // namespace

void write_modules(abi::ModuleBuffer* out, std::initializer_list<Written> modules) {
  for (const Written& m : modules) {
    const std::size_t param_size = m.params.size() * sizeof(float);
    out->reserve_more(abi::encoded_module_size(m.id, param_size));
    unsigned char* at = out->data + out->size;
    abi::put_encoded_module(at, m.id, m.params.data(), param_size);
    out->size = static_cast<std::size_t>(at - out->data);
  }
}

void produce(abi::RuleCall* call, std::initializer_list<Written> modules) {
  write_modules(call->out, modules);
  call->produced = true;
}

float param(const unsigned char* const* params, int module, int k) {
  float value;
  std::memcpy(&value, params[module] + k * sizeof(float), sizeof value);
  return value;
}

HandBuiltModel::HandBuiltModel() {
  std::size_t count = 0;
  const abi::ModuleType* predefined = predefined_module_types(&count);
  modules_.assign(predefined, predefined + count);
}

abi::ModuleId HandBuiltModel::module(const std::string& name, int float_params) {
  const std::string& kept = names_.emplace_back(name);
  abi::ModuleType type{};  // fields not set here keep their zero defaults
  type.name = kept.c_str();
  type.param_size = static_cast<std::uint32_t>(float_params * sizeof(float));
  type.format_params = kFormatters[float_params];
  type.param_count = static_cast<std::uint32_t>(float_params);
  modules_.push_back(type);
  return static_cast<abi::ModuleId>(modules_.size() - 1);
}

void HandBuiltModel::rule(abi::RuleKind kind, const Pattern& pattern, RuleBody body, int group) {
  RuleEntry entry{kind, group, current_filter_, {}, {}, body};
  const std::vector<abi::ModuleId>* parts[] = {&pattern.new_left, &pattern.left, &pattern.strict, &pattern.right,
                                               &pattern.new_right};
  for (int p = 0; p < abi::kPatternParts; ++p) {
    entry.pattern.insert(entry.pattern.end(), parts[p]->begin(), parts[p]->end());
    entry.part_length[p] = static_cast<std::uint16_t>(parts[p]->size());
  }
  rule_entries_.push_back(std::move(entry));
}

void HandBuiltModel::filter(bool consider, std::vector<abi::ModuleId> ids) {
  if (ids.empty()) {
    current_filter_ = -1;
    return;
  }
  const std::vector<abi::ModuleId>& kept = filter_ids_.emplace_back(std::move(ids));
  filters_.push_back(abi::ContextFilter{consider, kept.data(), static_cast<std::uint32_t>(kept.size())});
  current_filter_ = static_cast<int>(filters_.size() - 1);
}

const abi::ModelDescriptor& HandBuiltModel::descriptor() {
  rules_.clear();
  for (const RuleEntry& e : rule_entries_) {
    abi::Rule r{};
    r.kind = e.kind;
    r.group = e.group;
    r.filter = e.filter;
    r.pattern = e.pattern.data();
    std::memcpy(r.part_length, e.part_length, sizeof r.part_length);
    r.body = e.body;
    r.file = "hand-built";
    r.line = static_cast<int>(rules_.size() + 1);
    rules_.push_back(r);
  }
  std::size_t predefined = 0;
  predefined_module_types(&predefined);
  descriptor_ = abi::ModelDescriptor{};  // fields not set here keep their zero defaults
  descriptor_.abi_version = abi::kAbiVersion;
  descriptor_.source_file = "hand-built";
  descriptor_.modules = modules_.data();
  descriptor_.module_count = static_cast<std::uint32_t>(modules_.size());
  descriptor_.predefined_count = static_cast<std::uint32_t>(predefined);
  descriptor_.rules = rules_.data();
  descriptor_.rule_count = static_cast<std::uint32_t>(rules_.size());
  descriptor_.filters = filters_.data();
  descriptor_.filter_count = static_cast<std::uint32_t>(filters_.size());
  descriptor_.control = &control_;
  descriptor_.axiom = axiom_;
  descriptor_.derivation_length = derivation_length_;
  descriptor_.decomposition_depth = decomposition_depth_;
  descriptor_.call_module = abi::kNoModule;
  descriptor_.return_module = abi::kNoModule;
  descriptor_.verify_length = -1;  // no VerifyString:
  return descriptor_;
}

}  // namespace sylva::test
