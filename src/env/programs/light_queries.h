// Reading queries for the light programs.
#pragma once

#include <stdexcept>
#include <string>

#include "env/field.h"
#include "env/programs/light_geometry.h"

namespace sylva::env::light {

// The turtle position of a query; the .e file must ask for it.
inline Vec3 query_position(const Query& query, const std::string& program) {
  if (query.turtle.position_count == 0) {
    throw std::runtime_error(program + ": the turtle position is needed; add 'turtle position: %g %g %g' to the .e file");
  }
  const auto& p = query.turtle.position;
  return {p[0], p[1], p[2]};
}

// Parameter i of a query's module, or `otherwise` when it has fewer.
inline double query_parameter(const Query& query, std::size_t i, double otherwise = 0) {
  return i < query.module.parameters.size() ? query.module.parameters[i] : otherwise;
}

}  // namespace sylva::env::light
