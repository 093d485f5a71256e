#include "env/programs/collision_program_support.h"

#include "support/diagnostic.h"

namespace sylva::env::collision {

std::filesystem::path parameter_file_path(const ProgramInvocation& invocation, const std::string& program) {
  std::vector<std::string> files = invocation.positional_arguments();
  SourceLocation at{invocation.e_file, invocation.e_file_line, 0};
  if (files.empty())
    throw ModelError(at, program + " needs a parameter file: 'executable: " + program + " [-e commfile.e] eparamsfile'");
  if (files.size() > 1)
    throw ModelError(at, program + " takes one parameter file, found '" + files[0] + "' and '" + files[1] + "'");
  return invocation.resolve(files[0]);
}

void require_turtle_values(const ProgramInvocation& invocation, const std::string& program, const std::string& field,
                           int sent, int count) {
  if (sent >= count) return;
  std::string format;
  for (int i = 0; i < count; ++i) format += i == 0 ? "%g" : " %g";
  throw ModelError(SourceLocation{invocation.e_file, invocation.e_file_line, 0},
                   program + " needs the " + field + " of every communication module: add '" + field + ": " + format +
                       "' to the .e file" + (sent > 0 ? " (it sends " + std::to_string(sent) + " values)" : ""));
}

}  // namespace sylva::env::collision
