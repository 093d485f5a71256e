// The L+C front end: recognises the L-system constructs in preprocessed C++
// (module declarations, axiom, productions, decomposition and interpretation
// rules, control statements, ignore/consider ...) and builds the Model IR.
// All other C++ passes through untouched.
#pragma once

#include "lang/model_ir.h"
#include "lang/token.h"

namespace sylva::lang {

// Throws ModelError with the position of the first problem found.
Model parse_lc(const TokenStream& tokens, const std::string& main_file);

}  // namespace sylva::lang
