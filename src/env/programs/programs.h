// The Virtual Laboratory's environmental programs, computed in process. Each
// reads the same parameter file as the original (named on the .e file's
// "executable:" line) and answers the same queries; see EnviroManual section 3.
#pragma once

#include <memory>

#include "env/field.h"
#include "env/program.h"

namespace sylva::env {

// Collisions (EnviroManual 3.1).
std::unique_ptr<Field> make_honda81(const ProgramInvocation& invocation);
std::unique_ptr<Field> make_ecosystem(const ProgramInvocation& invocation);
std::unique_ptr<Field> make_arvo(const ProgramInvocation& invocation);
std::unique_ptr<Field> make_density(const ProgramInvocation& invocation);

// Light (EnviroManual 3.2).
std::unique_ptr<Field> make_clover(const ProgramInvocation& invocation);
std::unique_ptr<Field> make_chiba(const ProgramInvocation& invocation);
std::unique_ptr<Field> make_takenaka(const ProgramInvocation& invocation);

}  // namespace sylva::env
