// The registry of module types: names, parameters (their types and offsets,
// their saved-string printer and reader), indexed by module id. It comes from
// a compiled model, or is built by hand in tests.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "sylva/abi.h"

namespace sylva {

using abi::ModuleId;

class ModuleTypes {
 public:
  struct Type {
    std::string name;
    std::uint32_t param_size = 0;
    void (*format_params)(const unsigned char*, abi::TextSink*) = nullptr;
    // Reading the parameters back (null: from their table where they are
    // written from it, see read_params; cpfg's modules cannot be).
    std::uint32_t param_count = 0;
    bool (*parse_params)(abi::TextSource*, unsigned char*) = nullptr;
    // The parameters' types and offsets, param_count of them (null: not
    // known, as in types built by hand).
    const abi::ParamField* params = nullptr;
  };

  ModuleTypes() = default;
  explicit ModuleTypes(std::vector<Type> types);
  static ModuleTypes from_model(const abi::ModelDescriptor& model);

  std::size_t size() const { return types_.size(); }
  const Type& operator[](ModuleId id) const { return types_[id]; }
  const std::string& name(ModuleId id) const { return types_[id].name; }
  // Bytes a module of this type takes in a string: parameters plus two ids,
  // or one id without parameters.
  std::uint32_t encoded_size(ModuleId id) const { return encoded_sizes_[id]; }
  const std::uint32_t* encoded_sizes() const { return encoded_sizes_.data(); }
  std::optional<ModuleId> find(std::string_view name) const;
  // The model is cpfg's: its strings are written in cpfg's format.
  bool cpfg() const { return cpfg_; }
  void set_cpfg(bool cpfg);

  // The parameters' types and offsets; empty when they are not known.
  std::span<const abi::ParamField> params(ModuleId id) const;
  // The numbers a module's parameter block holds, in declaration order:
  // every number, bool (0 or 1) and enum; a vector's, an array's and a
  // struct's known fields' numbers in turn. Text and values of unknown
  // layout hold none.
  std::vector<double> numbers(ModuleId id, const unsigned char* params) const;

  // "p1,p2" for a module's parameter block, appended to `out`: written from
  // the parameters' table (lstring/param_text.h) where it describes them,
  // by the model's own printer otherwise.
  void format_params(ModuleId id, const unsigned char* params, std::string& out) const;
  // Whether a module's parameters can be read back from that text (not
  // cpfg's, not text), and reading them (see abi::ModuleType::parse_params).
  bool can_read_params(ModuleId id) const;
  bool read_params(ModuleId id, abi::TextSource* in, unsigned char* params) const;

 private:
  std::vector<Type> types_;
  // Which types' parameters are written from their table.
  void classify_params_text();

  std::vector<std::uint32_t> encoded_sizes_;
  std::vector<bool> params_text_from_table_;
  std::unordered_map<std::string, ModuleId> by_name_;
  bool cpfg_ = false;
};

// The engine's own entries for the predefined modules, in id order.
const abi::ModuleType* predefined_module_types(std::size_t* count);

}  // namespace sylva
