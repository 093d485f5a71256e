// The part of a ModelError's text that names the module at fault.
#pragma once

#include <string>

#include "geometry/scene.h"

namespace sylva::turtle {

// " (module N of the string)".
inline std::string where(geometry::Provenance from) {
  return " (module " + std::to_string(from.module_index) + " of the string)";
}

}  // namespace sylva::turtle
