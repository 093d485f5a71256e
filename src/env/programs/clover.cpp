// PLACEHOLDER until the in-process clover is written.
#include <stdexcept>

#include "env/programs/programs.h"

namespace sylva::env {

std::unique_ptr<Field> make_clover(const ProgramInvocation&) { throw std::logic_error("clover: not written yet"); }

}  // namespace sylva::env
