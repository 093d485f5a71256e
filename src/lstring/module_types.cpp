#include "lstring/module_types.h"

#include <cstring>

#include "lstring/param_text.h"
#include "lstring/param_values.h"

namespace sylva {

ModuleTypes::ModuleTypes(std::vector<Type> types) : types_(std::move(types)) {
  for (std::size_t k = 0; k < types_.size(); ++k) {
    const auto id = static_cast<ModuleId>(k);
    encoded_sizes_.push_back(static_cast<std::uint32_t>(abi::encoded_module_size(id, types_[k].param_size)));
    by_name_.emplace(types_[k].name, id);
  }
  classify_params_text();
}

void ModuleTypes::set_cpfg(bool cpfg) {
  cpfg_ = cpfg;
  classify_params_text();
}

void ModuleTypes::classify_params_text() {
  const NumberStyle style = cpfg_ ? NumberStyle::kCpfg : NumberStyle::kExact;
  params_text_from_table_.assign(types_.size(), false);
  for (std::size_t k = 0; k < types_.size(); ++k) {
    const Type& type = types_[k];
    const bool described = type.params != nullptr || type.param_size == 0;
    params_text_from_table_[k] = described && params_text_from_table(params(static_cast<ModuleId>(k)), style);
  }
}

ModuleTypes ModuleTypes::from_model(const abi::ModelDescriptor& model) {
  std::size_t predefined_count = 0;
  const abi::ModuleType* predefined = predefined_module_types(&predefined_count);
  std::vector<Type> types;
  for (std::uint32_t k = 0; k < model.module_count; ++k) {
    const abi::ModuleType& type = model.modules[k];
    auto format = type.format_params;
    auto parse = type.parse_params;
    auto params = type.params;
    const bool engine_supplies = k < model.predefined_count && k < predefined_count;
    if (!format && engine_supplies) format = predefined[k].format_params;
    if (!parse && engine_supplies && !(model.flags & abi::kModelCpfg)) parse = predefined[k].parse_params;
    if (!params && engine_supplies) params = predefined[k].params;
    types.push_back(Type{type.name, type.param_size, format, type.param_count, parse, params});
  }
  ModuleTypes result(std::move(types));
  result.set_cpfg((model.flags & abi::kModelCpfg) != 0);
  return result;
}

std::optional<ModuleId> ModuleTypes::find(std::string_view name) const {
  auto it = by_name_.find(std::string(name));
  if (it == by_name_.end()) return std::nullopt;
  return it->second;
}

std::span<const abi::ParamField> ModuleTypes::params(ModuleId id) const {
  const Type& type = types_[id];
  if (!type.params) return {};
  return {type.params, type.param_count};
}

namespace {

void append_numbers(const abi::ParamType& type, const unsigned char* at, std::vector<double>& out) {
  using abi::ParamKind;
  switch (type.kind) {
    case ParamKind::kFloat: out.push_back(load_param<float>(at)); break;
    case ParamKind::kDouble: out.push_back(load_param<double>(at)); break;
    case ParamKind::kLongDouble: out.push_back(static_cast<double>(load_param<long double>(at))); break;
    case ParamKind::kBool: out.push_back(load_param<bool>(at) ? 1 : 0); break;
    case ParamKind::kSigned:
    case ParamKind::kUnsigned:
      out.push_back(with_integer(type, at, [](auto v) { return static_cast<double>(v); }));
      break;
    case ParamKind::kEnum: append_numbers(*type.element, at, out); break;
    case ParamKind::kVector:
    case ParamKind::kArray:
      for (std::uint32_t k = 0; k < type.count; ++k) append_numbers(*type.element, at + k * type.element->size, out);
      break;
    case ParamKind::kStruct:
      for (std::uint32_t k = 0; k < type.field_count; ++k)
        if (const abi::ParamField& field = type.fields[k]; field.type) append_numbers(*field.type, at + field.offset, out);
      break;
    case ParamKind::kText:
    case ParamKind::kOther: break;
  }
}

}  // namespace

std::vector<double> ModuleTypes::numbers(ModuleId id, const unsigned char* params) const {
  std::vector<double> out;
  for (const abi::ParamField& param : this->params(id)) append_numbers(*param.type, params + param.offset, out);
  return out;
}

void ModuleTypes::format_params(ModuleId id, const unsigned char* params, std::string& out) const {
  if (params_text_from_table_[id]) {
    append_params_text(this->params(id), params, cpfg_ ? NumberStyle::kCpfg : NumberStyle::kExact, out);
    return;
  }
  const Type& type = types_[id];
  if (!type.format_params) return;
  abi::TextSink sink{&out, [](void* self, const char* text, std::size_t n) {
                       static_cast<std::string*>(self)->append(text, n);
                     }};
  type.format_params(params, &sink);
}

bool ModuleTypes::can_read_params(ModuleId id) const {
  return types_[id].parse_params || (!cpfg_ && params_text_from_table_[id]);
}

bool ModuleTypes::read_params(ModuleId id, abi::TextSource* in, unsigned char* params) const {
  if (types_[id].parse_params) return types_[id].parse_params(in, params);
  return can_read_params(id) && read_params_text(this->params(id), in, params);
}

}  // namespace sylva
