// Reading values out of a module's parameter block by their table type
// (abi::ParamType): what ModuleTypes::numbers and the text writer
// (param_text.h) share.
#pragma once

#include <cstdint>
#include <cstring>

#include "sylva/abi.h"

namespace sylva {

template <class T>
T load_param(const unsigned char* at) {
  T value;
  std::memcpy(&value, at, sizeof value);
  return value;
}

// Calls `use` with the integer at `at` (a kSigned or kUnsigned type) as its
// own C++ type, and returns what it returns.
template <class Use>
decltype(auto) with_integer(const abi::ParamType& type, const unsigned char* at, Use&& use) {
  const bool is_signed = type.kind == abi::ParamKind::kSigned;
  switch (type.size) {
    case 1: return is_signed ? use(load_param<std::int8_t>(at)) : use(load_param<std::uint8_t>(at));
    case 2: return is_signed ? use(load_param<std::int16_t>(at)) : use(load_param<std::uint16_t>(at));
    case 4: return is_signed ? use(load_param<std::int32_t>(at)) : use(load_param<std::uint32_t>(at));
    default: return is_signed ? use(load_param<std::int64_t>(at)) : use(load_param<std::uint64_t>(at));
  }
}

}  // namespace sylva
