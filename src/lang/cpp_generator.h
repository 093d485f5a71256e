// Turns the Model IR into the C++ of a compiled model: rule bodies become
// functions, produce statements become module writes, and tables describe
// modules and rules to the engine (see sylva/abi.h).
#pragma once

#include <string>

#include "lang/model_ir.h"

namespace sylva::lang {

std::string generate_cpp(const Model& model);

}  // namespace sylva::lang
