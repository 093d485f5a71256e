// PLACEHOLDER until the in-process chiba is written.
#include <stdexcept>

#include "env/programs/programs.h"

namespace sylva::env {

std::unique_ptr<Field> make_chiba(const ProgramInvocation&) { throw std::logic_error("chiba: not written yet"); }

}  // namespace sylva::env
