// The C++ compiler models are built with and input files are preprocessed
// with, when none is named.
#pragma once

#include <string>

namespace sylva {

// $SYLVA_CXX, then $CXX, then g++ (an empty variable counts as unset).
std::string default_compiler();
// `named`, or the default where none is named ("").
std::string compiler_or_default(const std::string& named);

}  // namespace sylva
