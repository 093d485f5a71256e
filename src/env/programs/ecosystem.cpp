// PLACEHOLDER until the in-process ecosystem is written.
#include <stdexcept>

#include "env/programs/programs.h"

namespace sylva::env {

std::unique_ptr<Field> make_ecosystem(const ProgramInvocation&) { throw std::logic_error("ecosystem: not written yet"); }

}  // namespace sylva::env
