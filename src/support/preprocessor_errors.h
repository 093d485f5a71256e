// The C preprocessor's complaint about a directive (`#include "missing.h"`,
// `#if` without an expression, `#error`), as an error at its file, line and
// column.
#pragma once

#include <optional>
#include <string>

#include "support/diagnostic.h"

namespace sylva {

// The first error in the preprocessor's standard error `err`: at column 1
// where it gives a line without a column ("unterminated #if"), and saying
// which line included the file it is in. nullopt when no error is located.
// `argument` is the file as the preprocessor was given it, `path` as it is
// to be named.
std::optional<ModelError> first_preprocessor_error(const std::string& err, const std::string& argument,
                                                   const std::string& path);

}  // namespace sylva
