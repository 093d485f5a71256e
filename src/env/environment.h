// Choosing the environment a .e file names (make_field).
//
// The first word of the "executable:" line decides:
//  - its file name (folders dropped) is a built-in program: honda81,
//    ecosystem, arvo, density, clover, chiba or takenaka run in process;
//  - it ends in ".so": a plugin, a shared library with a Field of the user's
//    own, loaded in process (see kPluginFactoryName below);
//  - anything else is a program started as a separate process and spoken to
//    over pipes (external_program.h, docs/environment.md), found as written
//    when it holds a '/' (relative to the .e file's folder), else on PATH,
//    else in the .e file's folder.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "env/comm_library_transport.h"
#include "env/comm_spec.h"
#include "env/field.h"
#include "env/program.h"
#include "support/diagnostic.h"

namespace sylva::env {

// A plugin exports, with C linkage, a function of this name and type:
//
//   extern "C" sylva::env::Field* sylva_environment_field(int argc, const char* const* argv,
//                                                          const char* directory);
//
// argv[0] is the plugin as named on the executable: line, argv[1..argc) the
// rest of that line, `directory` the .e file's folder (parameter files are
// relative to it). It returns a Field allocated with new (Sylva deletes it
// before unloading the library), or null after printing why to stderr. The
// plugin is compiled against src/env/field.h with the compiler Sylva was.
inline constexpr const char* kPluginFactoryName = "sylva_environment_field";
using PluginFactory = Field* (*)(int argc, const char* const* argv, const char* directory);

struct FieldOptions {
  // How long an external program may take to answer one pass before it is
  // stopped and the run fails.
  double timeout_seconds = 60;
  // The modeling program whose side of the Virtual Laboratory's
  // communication library the built-in programs are served as
  // (comm_library_transport.h): lpfg for L+C models, cpfg for cpfg models.
  ModelingProgram master = ModelingProgram::lpfg;
  // Warnings of the built-in programs and of that transport; standard error
  // when empty.
  std::function<void(const std::string&)> warn;
};

// An environmental program that cannot be started: not found, not
// executable, or ended before it said it was ready. lpfg ("Environmental
// program ... did not start.") and cpfg ("Field process ... is not started.
// Environment ignored.") then derive without the environment; make_field
// does the same with a warning.
class ProgramNotStarted : public ModelError {
 public:
  using ModelError::ModelError;
};

// The environment of a .e file whose program is not run: the passes still
// interpret the string, as lpfg and cpfg do, and nothing answers.
class IgnoredEnvironment : public Field {
 public:
  void answer(std::span<const Query>, std::span<Answer>, int) override {}
};

// The executable: line of `spec` split into words as a shell would.
ProgramInvocation invocation_of(const CommSpec& spec);

// The Field for `spec`. A program that cannot be started (ProgramNotStarted),
// or a .e file without an executable, gives an IgnoredEnvironment, after a
// warning at the executable: line through options.warn; a plugin that cannot
// be loaded is a ModelError there.
std::unique_ptr<Field> make_field(const CommSpec& spec, const FieldOptions& options = {});

}  // namespace sylva::env
