// Numeric ids of the predefined modules, in the order of predefined_modules.def.
#pragma once

#include <sylva/abi.h>

namespace sylva::rt::mid {
enum : abi::ModuleId {
#define SYLVA_MODULE(name, ...) name,
#include <sylva/predefined_modules.def>
  PredefinedCount
};
}  // namespace sylva::rt::mid
