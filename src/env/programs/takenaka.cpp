// PLACEHOLDER until the in-process takenaka is written.
#include <stdexcept>

#include "env/programs/programs.h"

namespace sylva::env {

std::unique_ptr<Field> make_takenaka(const ProgramInvocation&) { throw std::logic_error("takenaka: not written yet"); }

}  // namespace sylva::env
