#include "support/default_compiler.h"

#include <cstdlib>

namespace sylva {

std::string default_compiler() {
  for (const char* name : {"SYLVA_CXX", "CXX"})
    if (const char* value = std::getenv(name); value && *value) return value;
  return "g++";
}

std::string compiler_or_default(const std::string& named) { return named.empty() ? default_compiler() : named; }

}  // namespace sylva
