#include "support/default_compiler.h"

#include <cstdlib>

namespace sylva {

std::string default_compiler() {
  for (const char* name : {"SYLVA_CXX", "CXX"})
    if (const char* value = std::getenv(name); value && *value) return value;
  return "g++";
}

}  // namespace sylva
