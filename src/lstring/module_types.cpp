#include "lstring/module_types.h"

namespace sylva {

ModuleTypes::ModuleTypes(std::vector<Type> types) : types_(std::move(types)) {
  for (std::size_t k = 0; k < types_.size(); ++k) {
    encoded_sizes_.push_back(types_[k].param_size + static_cast<std::uint32_t>(abi::kModuleOverhead));
    by_name_.emplace(types_[k].name, static_cast<ModuleId>(k));
  }
}

ModuleTypes ModuleTypes::from_model(const abi::ModelDescriptor& model) {
  std::size_t predefined_count = 0;
  const abi::ModuleType* predefined = predefined_module_types(&predefined_count);
  std::vector<Type> types;
  for (std::uint32_t k = 0; k < model.module_count; ++k) {
    auto format = model.modules[k].format_params;
    auto parse = model.modules[k].parse_params;
    const bool engine_supplies = k < model.predefined_count && k < predefined_count;
    if (!format && engine_supplies) format = predefined[k].format_params;
    if (!parse && engine_supplies && !(model.flags & abi::kModelCpfg)) parse = predefined[k].parse_params;
    types.push_back(Type{model.modules[k].name, model.modules[k].param_size, format, model.modules[k].param_count, parse});
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

void ModuleTypes::format_params(ModuleId id, const unsigned char* params, std::string& out) const {
  const Type& type = types_[id];
  if (!type.format_params) return;
  abi::TextSink sink{&out, [](void* self, const char* text, std::size_t n) {
                       static_cast<std::string*>(self)->append(text, n);
                     }};
  type.format_params(params, &sink);
}

}  // namespace sylva
