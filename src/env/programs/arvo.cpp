// PLACEHOLDER until the in-process arvo is written.
#include <stdexcept>

#include "env/programs/programs.h"

namespace sylva::env {

std::unique_ptr<Field> make_arvo(const ProgramInvocation&) { throw std::logic_error("arvo: not written yet"); }

}  // namespace sylva::env
