// The communication specification file (.e, EnviroManual section 2): which
// environmental program runs, what the model sends it at each communication
// module, and how.
//
//   executable: honda81 -e honda.e honda.par
//   communication type: pipes
//   turtle position: %g %g %g
//   following module: yes
//   verbose: on
#pragma once

#include <string>
#include <vector>

#include "env/turtle_format.h"

namespace sylva::env {

struct CommSpec {
  std::string path;  // the .e file as named

  // The command line, as written; empty when the file names none (lpfg and
  // cpfg then run without the environment, and so does Sylva).
  std::string executable;
  int executable_line = 0;
  int executable_column = 0;  // 1-based, where the command line starts
  // files, memory, pipes or sockets (lower case, as written). Whatever it
  // says, Sylva uses pipes (or no transport at all for a built-in program).
  std::string communication_type;

  TurtleFormat position, heading, left, up, line_width, scale_factor;
  bool following_module = false;
  // Modules whose graphics cpfg sends after a communication module (QuasiMC).
  std::vector<std::string> interpreted_modules;
  bool verbose = false;
  // "file:line:column: warning: ..." for what lpfg and cpfg pass over: unknown
  // commands, lines that are not commands, commands given again, switches
  // that are neither on nor off, an unknown communication type.
  std::vector<std::string> warnings;

  // A spec for an environment given in code rather than by a .e file: every
  // turtle field with all its values ("%.9g" each), and the following module.
  static CommSpec everything();
};

// Reads a .e file. What lpfg and cpfg pass over is a warning (`warnings`);
// so is a missing executable (the environment is then ignored, as they
// ignore it). A ModelError at file:line:column stops the run where they
// would fail or garble the exchange: a turtle format that printf cannot
// apply to the turtle's numbers or that sends no number.
CommSpec read_comm_spec(const std::string& path);
// The same from text already read; `path` names it in errors.
CommSpec parse_comm_spec(const std::string& text, const std::string& path);

}  // namespace sylva::env
