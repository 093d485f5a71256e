#include "env/programs/program_inputs.h"

#include <stdexcept>

#include "support/diagnostic.h"

namespace sylva::env {

std::filesystem::path parameter_file_path(const ProgramInvocation& invocation, const std::string& program,
                                          ParameterDialect dialect) {
  std::vector<std::string> files = invocation.positional_arguments();
  SourceLocation at{invocation.e_file, invocation.e_file_line, 0};
  if (dialect == ParameterDialect::light) {
    if (files.empty())
      throw ModelError(at, program + ": expected a parameter file after the program name, e.g. 'executable: " +
                               program + " -e field.e " + program + ".par'");
    return invocation.resolve(files.front());
  }
  if (files.empty())
    throw ModelError(at, program + " needs a parameter file: 'executable: " + program + " [-e commfile.e] eparamsfile'");
  if (files.size() > 1)
    throw ModelError(at, program + " takes one parameter file, found '" + files[0] + "' and '" + files[1] + "'");
  return invocation.resolve(files[0]);
}

std::filesystem::path vlab_spec_file_path(const ProgramInvocation& invocation, const std::string& program) {
  const std::vector<std::string>& words = invocation.arguments;
  std::size_t at = 0;
  while (at + 1 < words.size() && words[at].size() > 1 && words[at][0] == '-' &&
         (words[at][1] == 'e' || words[at][1] == 'k' || words[at][1] == 'h'))
    at += 2;
  if (at >= words.size())
    throw ModelError(SourceLocation{invocation.e_file, invocation.e_file_line, 0},
                     program + " needs its specification file: 'executable: " + program +
                         " [-e commfile.e] specfile'");
  return invocation.resolve(words[at]);
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

const std::array<float, 3>& turtle_position(const Query& query, const std::string& program) {
  if (query.turtle.position_count == 0)
    throw std::runtime_error(program + ": the turtle position is needed; add 'turtle position: %g %g %g' to the .e file");
  return query.turtle.position;
}

void fail_module(const std::string& program, const Query& query, const std::string& problem) {
  throw std::runtime_error(program + ": module " + query.module.symbol + " number " + std::to_string(query.id) + " " +
                           problem);
}

}  // namespace sylva::env
