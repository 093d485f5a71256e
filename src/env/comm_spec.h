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

  std::string executable;  // the command line, as written
  int executable_line = 0;
  int executable_column = 0;  // 1-based, where the command line starts
  // files, memory, pipes or sockets. Whatever it says, Sylva uses pipes (or
  // no transport at all for a built-in program); the value is checked only.
  std::string communication_type;

  TurtleFormat position, heading, left, up, line_width, scale_factor;
  bool following_module = false;
  // Modules whose graphics cpfg sends after a communication module (QuasiMC).
  std::vector<std::string> interpreted_modules;
  bool verbose = false;

  // A spec for an environment given in code rather than by a .e file: every
  // turtle field with all its values ("%.9g" each), and the following module.
  static CommSpec everything();
};

// Reads a .e file; a ModelError at file:line:column for anything malformed
// (unknown command, a missing executable or communication type, a bad format).
CommSpec read_comm_spec(const std::string& path);
// The same from text already read; `path` names it in errors.
CommSpec parse_comm_spec(const std::string& text, const std::string& path);

}  // namespace sylva::env
