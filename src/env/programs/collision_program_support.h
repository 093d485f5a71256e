// What the collision programs (honda81, ecosystem, density, arvo) share: the
// parameter file named on the .e file's "executable:" line, and the turtle
// state each query must carry.
#pragma once

#include <filesystem>
#include <string>

#include "env/field.h"
#include "env/program.h"

namespace sylva::env::collision {

// The one parameter file `program` takes ("honda81 [-e commfile.e]
// eparamsfile"), resolved against the .e file's folder. A missing one is an
// error pointing at the executable: line.
std::filesystem::path parameter_file_path(const ProgramInvocation& invocation, const std::string& program);

// Throws an error pointing at the executable: line unless the .e file sends
// at least `count` values of `field` ("turtle position", ...) with each query.
void require_turtle_values(const ProgramInvocation& invocation, const std::string& program, const std::string& field,
                           int sent, int count);

// A query's position in 2D (z set to 0) or 3D.
inline std::array<float, 3> position_in(const Query& query, bool three_d) {
  return {query.turtle.position[0], query.turtle.position[1], three_d ? query.turtle.position[2] : 0.0f};
}

}  // namespace sylva::env::collision
