// The cpfg front end: the classic cpfg L-system file (CPFG manual, sections
// 2-5) into the same Model IR as L+C. Every cpfg symbol with a given number of
// parameters is a module type of its own (internal name cpfg_<symbol>_<n>,
// shown as the symbol); `[`, `]` and `%` are the engine's SB, EB and Cut.
#pragma once

#include <string>

#include "lang/model_ir.h"

namespace sylva::lang {

// `preprocessed` is the output of the C preprocessor (with line markers).
// Throws ModelError at file:line:column for the first problem found, and for
// cpfg features that are not supported yet.
Model parse_cpfg(const std::string& preprocessed, const std::string& main_file);

}  // namespace sylva::lang
