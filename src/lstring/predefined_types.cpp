// Printers for the predefined modules, compiled once into the engine rather
// than into every model.
#include "lstring/module_types.h"
#include "sylva/runtime/modules.h"

namespace sylva {

const abi::ModuleType* predefined_module_types(std::size_t* count) {
  static const abi::ModuleType table[] = {
#define SYLVA_MODULE(name, ...) ::sylva::rt::module_type<__VA_ARGS__>(#name),
#include "sylva/predefined_modules.def"
  };
  *count = sizeof table / sizeof table[0];
  return table;
}

}  // namespace sylva
