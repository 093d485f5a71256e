// Modules whose arguments are all literals, encoded by the translator: a long
// axiom or successor becomes a table of bytes copied in one call instead of
// one C++ statement per module, which the C++ compiler takes far longer to
// compile than the table.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lang/model_ir.h"

namespace sylva::lang {

// The bytes `put_module<param_types...>(at, id, args...)` would write
// ([id][parameters][id], or [id] without parameters: see sylva/abi.h), or
// nullopt unless every argument is a literal the translator converts exactly
// as the C++ compiler does (decimal numbers, signed, parenthesized, cast to
// float) to a built-in arithmetic type, and the count matches.
std::optional<std::string> constant_module_bytes(abi::ModuleId id, const std::vector<std::string>& param_types,
                                                 const std::vector<Code>& args);

// `bytes` as a C++ string literal (its terminating NUL is not part of them).
std::string bytes_literal(const std::string& bytes);

}  // namespace sylva::lang
