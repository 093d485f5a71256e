// What the built-in programs need from their invocation and their queries:
// the parameter file named on the .e file's "executable:" line, and the
// turtle state the .e file must send with each query.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "env/field.h"
#include "env/program.h"
#include "env/programs/parameter_file.h"

namespace sylva::env {

// The parameter file `program` takes ("honda81 [-e commfile.e] eparamsfile"),
// resolved against the .e file's folder. A missing one is an error pointing
// at the executable: line. The collision programs take exactly one; the
// light programs read the first and ignore the rest.
std::filesystem::path parameter_file_path(const ProgramInvocation& invocation, const std::string& program,
                                          ParameterDialect dialect);

// The specification file of a program built on the Virtual Laboratory's
// communication library (honda81, clover), as that library leaves it: the
// switches -e, -ext, -k and -h each take the next word; the first word after
// them is the file, resolved against the .e file's folder; later words are
// ignored, as the real programs ignore them. No word at all is an error at
// the executable: line (the real program prints its usage and exits).
std::filesystem::path vlab_spec_file_path(const ProgramInvocation& invocation, const std::string& program);

// The collision programs' check, made once per pass on the first query:
// throws an error pointing at the executable: line unless the .e file sends
// at least `count` values of `field` ("turtle position", ...).
void require_turtle_values(const ProgramInvocation& invocation, const std::string& program, const std::string& field,
                           int sent, int count);
// The turtle position in 2D (x y) or in 3D (x y z).
inline void require_turtle_position(const ProgramInvocation& invocation, const std::string& program,
                                    const Query& query, bool three_d) {
  require_turtle_values(invocation, program, "turtle position", query.turtle.position_count, three_d ? 3 : 2);
}

// A query's position in 2D (z set to 0) or 3D.
inline std::array<float, 3> position_in(const Query& query, bool three_d) {
  return {query.turtle.position[0], query.turtle.position[1], three_d ? query.turtle.position[2] : 0.0f};
}

// The light programs' check, made on every query: its turtle position, or
// an error when the .e file does not send it.
const std::array<float, 3>& turtle_position(const Query& query, const std::string& program);

// Parameter i of a query's module, or `otherwise` when it has fewer.
inline double query_parameter(const Query& query, std::size_t i, double otherwise = 0) {
  return i < query.module.parameters.size() ? query.module.parameters[i] : otherwise;
}

// The light programs' error for a query whose parameters they cannot use:
// "program: module ?E number 12 " followed by `problem`.
[[noreturn]] void fail_module(const std::string& program, const Query& query, const std::string& problem);

}  // namespace sylva::env
