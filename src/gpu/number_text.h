// Numbers of strings derived on the GPU, written as the engine writes them:
// the shortest text that reads back exactly, of the float the GPU computed
// (`as_float`) or of the double.
#pragma once

#include <charconv>
#include <string>

namespace sylva::gpu {

inline void append_number(std::string& out, double value, bool as_float) {
  char buffer[64];
  auto result = as_float ? std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(value))
                         : std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace sylva::gpu
