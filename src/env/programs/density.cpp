// PLACEHOLDER until the in-process density is written.
#include <stdexcept>

#include "env/programs/programs.h"

namespace sylva::env {

std::unique_ptr<Field> make_density(const ProgramInvocation&) { throw std::logic_error("density: not written yet"); }

}  // namespace sylva::env
