// PLACEHOLDER until the in-process honda81 is written.
#include <stdexcept>

#include "env/programs/programs.h"

namespace sylva::env {

std::unique_ptr<Field> make_honda81(const ProgramInvocation&) { throw std::logic_error("honda81: not written yet"); }

}  // namespace sylva::env
